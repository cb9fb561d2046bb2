// A bot player over one socket: says hello, creates or joins a room, and plays its shots whenever
// the room is in play and the game's turn is its own. It measures each shot's round trip (sent to
// the `shot` broadcast with the new stateId) and counts every error the server sends it.
import { simulate } from '../shared/physics/index.ts';
import type { Game, Shot } from '../shared/rules/index.ts';
import type { GameKindName, PlayerRef, RoomStatus, RoomView, ServerMessage } from '../shared/protocol/index.ts';
import type { ProtocolClient } from './client.ts';
import { chooseShot, quickShot, type BotMode, type Simulate } from './strategy.ts';

/** Counters that many bots may share. */
export interface BotStats {
  /** Shots the server played (their broadcast came back). */
  shots: number;
  /** `{type:"error"}` messages received, and by code. */
  errors: number;
  errorCodes: Record<string, number>;
  /** Shot round trips, ms. */
  rttMs: number[];
  /** Games seen ending in play (counted by the bots with countGames, one a room). */
  gamesFinished: number;
  /** Sockets the server closed while the bot was still playing. */
  disconnects: number;
}

export function newStats(): BotStats {
  return { shots: 0, errors: 0, errorCodes: {}, rttMs: [], gamesFinished: 0, disconnects: 0 };
}

export interface BotOptions {
  /** The name to ask for; the server makes up a guest name without one. */
  readonly name?: string;
  /** "sound" (default) simulates candidates; "quick" aims once. */
  readonly mode?: BotMode;
  /** Wait about this long before each shot (ms): drawn from 0.5 to 1.5 times it, so that rooms started together do not shoot in step. */
  readonly thinkMs?: number;
  /** Ask for a rematch whenever a game is over (else the bot stops playing then). */
  readonly rematch?: boolean;
  readonly stats?: BotStats;
  /** Count finished games: set on one bot of each room so that a game counts once. */
  readonly countGames?: boolean;
}

/** Retries of a refused shot (each with the next quick candidate) before the bot concedes instead. */
const MAX_ATTEMPTS = 5;

const play: Simulate = (scene, shot) => simulate(scene, shot);

export class Bot {
  readonly stats: BotStats;
  private me: PlayerRef | undefined;
  private roomId: string | undefined;
  private status: RoomStatus | undefined;
  private stateId = -1;
  private game: Game | null = null;
  private rematchAsked = false;
  private stopped = false;
  /** The stateId a shot is scheduled for, and its timer. */
  private scheduled: { stateId: number; timer: NodeJS.Timeout } | undefined;
  /** The shot in flight: its request id, the stateId it was made on, when it was sent. */
  private pending: { id: string; stateId: number; sentAt: number } | undefined;
  private attempt = 0;

  constructor(
    readonly client: ProtocolClient,
    private readonly options: BotOptions = {},
  ) {
    this.stats = options.stats ?? newStats();
    client.onMessage((m) => this.receive(m));
    client.onClose(() => {
      if (!this.stopped) this.stats.disconnects++;
      this.stop();
    });
  }

  get player(): PlayerRef | undefined {
    return this.me;
  }

  get room(): string | undefined {
    return this.roomId;
  }

  /** Says hello (with the name, if any) and resolves with the player the server made. */
  async hello(): Promise<PlayerRef> {
    const msg = await this.client.request({ type: 'hello', ...(this.options.name === undefined ? {} : { name: this.options.name }) });
    if (msg.type !== 'welcome') throw new Error(`expected welcome, got ${msg.type}`);
    this.me = msg.player;
    return msg.player;
  }

  /** Creates a room, seated in it, and resolves with its id. */
  async create(kind: GameKindName, raceTo?: number): Promise<string> {
    const msg = await this.client.request({ type: 'create', kind, ...(raceTo === undefined ? {} : { raceTo }) });
    if (msg.type !== 'room') throw new Error(`expected room, got ${msg.type}`);
    this.roomId = msg.room.id;
    this.update(msg.room);
    return msg.room.id;
  }

  /** Takes the second seat of a room, which starts its game. */
  async join(room: string): Promise<void> {
    this.roomId = room; // before the request: the room message that answers it is this bot's first state
    const msg = await this.client.request({ type: 'join', room });
    if (msg.type === 'room') this.update(msg.room);
  }

  /** Stops playing: no further shot or rematch is sent. */
  stop(): void {
    this.stopped = true;
    if (this.scheduled) clearTimeout(this.scheduled.timer);
    this.scheduled = undefined;
  }

  /** Stops, leaves the room (conceding a game in play) and closes the socket. */
  async leave(timeoutMs = 3000): Promise<void> {
    this.stop();
    if (this.roomId !== undefined && this.client.open) {
      await this.client.request({ type: 'leave', room: this.roomId }, timeoutMs).catch(() => {});
    }
    await this.client.close();
  }

  private receive(m: ServerMessage): void {
    if (m.type === 'error') {
      this.stats.errors++;
      this.stats.errorCodes[m.code] = (this.stats.errorCodes[m.code] ?? 0) + 1;
      if (this.pending && m.re === this.pending.id) this.refused(m.code);
      return;
    }
    if (m.type === 'room' && m.room.id === this.roomId) this.update(m.room);
    if (m.type === 'shot' && m.room === this.roomId) this.played(m);
  }

  private update(room: RoomView): void {
    if (room.stateId < this.stateId) return; // an older view crossed a newer one
    const wasOver = this.status === 'over';
    this.status = room.status;
    this.stateId = room.stateId;
    this.game = room.game;
    if (room.status !== 'over') this.rematchAsked = false;
    if (room.status === 'over' && !wasOver) this.gameOver();
    if (room.status === 'over' && this.options.rematch && !this.stopped && !this.rematchAsked) {
      this.rematchAsked = true;
      this.client.send({ type: 'rematch', id: this.client.newId(), room: room.id });
    }
    this.consider();
  }

  private played(m: Extract<ServerMessage, { type: 'shot' }>): void {
    if (m.stateId <= this.stateId) return;
    this.stateId = m.stateId;
    this.game = m.game;
    if (this.pending && m.stateId > this.pending.stateId) {
      if (m.shot.player === this.me?.id) {
        this.stats.shots++;
        this.stats.rttMs.push(performance.now() - this.pending.sentAt);
      }
      this.pending = undefined;
      this.attempt = 0;
    }
    this.consider();
  }

  private gameOver(): void {
    if (this.options.countGames && !this.stopped) this.stats.gamesFinished++;
  }

  /** The server refused the shot in flight: after a stale state wait for the new one, else try another shot. */
  private refused(code: string): void {
    this.pending = undefined;
    if (code === 'stale-state') return;
    this.attempt++;
    if (this.attempt > MAX_ATTEMPTS && this.roomId !== undefined) {
      // Nothing this bot aims is taken: give the game away rather than stall the room.
      this.client.send({ type: 'concede', id: this.client.newId(), room: this.roomId });
      return;
    }
    this.consider();
  }

  private myTurn(): boolean {
    const g = this.game;
    return !this.stopped && this.status === 'playing' && g !== null && g.winner === null && g.turn === this.me?.id;
  }

  /** Schedules a shot for the current state when it is this bot's turn and none is scheduled or in flight for it. */
  private consider(): void {
    if (!this.myTurn()) return;
    if (this.pending?.stateId === this.stateId || this.scheduled?.stateId === this.stateId) return;
    if (this.scheduled) clearTimeout(this.scheduled.timer);
    const stateId = this.stateId;
    const think = (this.options.thinkMs ?? 0) * (0.5 + Math.random());
    this.scheduled = { stateId, timer: setTimeout(() => this.shoot(stateId), think) };
  }

  private shoot(stateId: number): void {
    this.scheduled = undefined;
    if (stateId !== this.stateId || !this.myTurn() || this.roomId === undefined) return this.consider();
    let chosen: Shot;
    try {
      chosen = chooseShot(this.game!, this.options.mode ?? 'sound', play, this.attempt);
    } catch {
      chosen = quickShot(this.game!, this.attempt); // the sound mode found nothing the referee takes
    }
    const { player: _player, ...shot } = chosen;
    const id = this.client.newId();
    const pending = { id, stateId, sentAt: performance.now() };
    this.pending = pending;
    // The round trip starts when the frame goes out, not while it waits for this socket's budget.
    this.client.send({ type: 'shot', id, room: this.roomId, stateId, shot }, () => (pending.sentAt = performance.now()));
  }
}
