// The game service: players, rooms, seats, turns, shot clocks and held seats. It knows no sockets:
// it takes parsed commands from numbered connections and returns what to send to whom. Every
// change is computed on copies, written to the store, and only then made current, so a command
// that fails (bad input, the rules, the physics, the database) changes nothing for anyone.
//
// The store is asynchronous, so operations overlap. Each operation collects its deliveries in its
// own outbox (an array passed down its calls), never a shared buffer, so no operation sends
// another's messages or loses its own when another fails. A room's commands, timers and computer
// moves run one at a time in arrival order (a promise chain per room), so each sees the state the
// previous one committed; different rooms proceed concurrently.
//
// With several processes (options.peers, docs/scale.md) each room has one owner process: a
// command for a room owned elsewhere is forwarded there and its answer awaited; only the owner
// commits a room and runs its clocks, and announces the room's summary when it changes so that
// every process's lobby mirrors it; deliveries for another process's sockets go to that process.
import { randomBytes } from 'node:crypto';
import type { ClientMessage, PlayerRef, ServerMessage } from '../../shared/protocol/index.ts';
import { LOBBY_MAX_ROOMS, LOBBY_UPDATE_MS, MAX_OPEN_ROOMS_PER_PLAYER, MAX_TABS_PER_PLAYER } from '../../shared/protocol/index.ts';
import { claimGame, concede, decide, EMPTY_TALLY, placeCueBall, playShot, shotClockExpired, tallied, type Game, type MatchAction } from '../../shared/rules/index.ts';
import { RATED_MIN_PLAY_MS, RATED_MIN_SHOTS, unratedSentence, type UnratedReason } from '../ratings/policy.ts';
import { StaleRoomError, TooManyRoomsError, type AsyncStore, type MatchResult, type RoomChange, type StoredResult } from '../store/index.ts';
import { guestName, nameProblem, normalizeName } from '../players/names.ts';
import { hashToken, newToken } from '../tokens.ts';
import { ChatLimits } from './chat-limits.ts';
import { describeError, ServiceError } from './errors.ts';
import { GuestLimit } from './guest-limit.ts';
import { Lobby, type ConnId } from './lobby.ts';
import { afterMove, deadlineAfter, gameFor, Room, roomView, type RoomState } from './room.ts';
import { isLevel, type Decision, type Level } from '../../shared/ai/index.ts';
import type { Thinker } from '../workers/pool.ts';
import { computerName, decisionSeed, fallbackDecision, looksLikeComputer } from '../computer/player.ts';
import { PointSchema, ShotSchema, type ShotInput } from '../../shared/protocol/index.ts';
import * as v from 'valibot';
import type { Point } from '../../shared/rules/index.ts';
import type { Peers } from '../cluster/index.ts';
import { PeerMessageSchema, type PeerMessage } from './peer-messages.ts';
import { splitDeliveries } from './split-deliveries.ts';

export type { ConnId } from './lobby.ts';

export interface Delivery {
  readonly to: readonly ConnId[];
  readonly message: ServerMessage;
}

/** One operation's deliveries, in the order they are to go out. */
type Outbox = Delivery[];

/** A room as the store holds it at start, and its finished match's result when it has one. */
interface Restored {
  readonly state: RoomState;
  readonly result: StoredResult | undefined;
}

/** A move refused because the room changed in the store meanwhile: the room has been reloaded. */
class StaleState extends ServiceError {
  constructor(readonly room: Room) {
    super('stale-state', `the room changed elsewhere and is now at stateId ${room.state.stateId}: look again and retry`);
  }
}

export interface ServiceOptions {
  /** How long a dropped player's seat is held before the opponent may claim the game (ms). */
  readonly seatHoldMs: number;
  /** Server time from a match's start to its result below which it is not rated (ms; default RATED_MIN_PLAY_MS). */
  readonly ratedMinPlayMs?: number;
  readonly now?: () => number;
  /** Where internal errors are reported. */
  readonly log?: (line: string) => void;
  /** New players one address may make an hour (absent: no limit). */
  readonly guestsPerAddress?: number;
  /** How long a player who never played is kept after last seen (ms; absent: for ever). */
  readonly guestKeepMs?: number;
  /** Sockets one player may have welcomed at once (tabs); default MAX_TABS_PER_PLAYER. */
  readonly maxTabsPerPlayer?: number;
  /** The computer opponent: where it thinks, and the least time between the balls stopping and its move (ms). */
  readonly computer?: { readonly thinker: Thinker; readonly pauseMs: number };
  /** The other processes, when there are several (docs/scale.md); absent: this process is the platform. */
  readonly peers?: Peers;
}

type Msg<T extends ClientMessage['type']> = Extract<ClientMessage, { type: T }>;
type Re = string | number | undefined;

const DEFAULT_RACE = { nineball: 1, eightball: 1, snooker: 1, threecushion: 15 } as const;

/** Made-up names tried before giving up; with 31^8 of them a second try is already rare. */
const GUEST_NAME_TRIES = 10;
/** last_seen is written at hello only when older than this, so reconnects cost no write. */
const SEEN_EVERY_MS = 3_600_000;
/** Players the pruner looks at per tick, so a tick stays short however many there are. */
const PRUNE_BATCH = 500;
/** A pass of the pruner starts at start-up and then hourly. */
const PRUNE_EVERY_MS = 3_600_000;
/** Forgotten guest limits are swept once a minute. */
const SWEEP_EVERY_MS = 60_000;
/** How long a command forwarded to a room's owner waits for its answer. */
const FORWARD_TIMEOUT_MS = 5_000;
/** Rooms without a live owner that one tick tries to take over. */
const ADOPT_PER_TICK = 200;

function randomSeed(): number {
  return randomBytes(4).readUInt32LE(0);
}

export class GameService {
  private readonly lobby: Lobby;
  private readonly now: () => number;
  private readonly log: (line: string) => void;
  /** Rooms where each player holds a seat. */
  private readonly seatsOf = new Map<string, Set<string>>();
  /** Rooms each socket watches. */
  private readonly watching = new Map<ConnId, Set<string>>();
  /** The network address each open socket came from (for limits per address). */
  private readonly addresses = new Map<ConnId, string>();
  private lobbyChanged = false;
  private readonly guestLimit: GuestLimit | undefined;
  private sweepAt = 0;
  /** When the pruner's next pass starts, and the id after which its next batch starts. */
  private pruneAt = 0;
  private pruneFrom = 0;
  /** When the lobby last went to its subscribers: updates are coalesced, one per LOBBY_UPDATE_MS. */
  private lobbySentAt = -Infinity;
  /** Rooms whose spectators changed: one `room` each to their members at the next tick. */
  private readonly roomsChanged = new Set<Room>();
  private readonly chatLimits: ChatLimits;
  private chatPrunedAt = 0;
  /** Where deliveries made outside a command go (the computer's moves); set by the binding. */
  private outlet: ((deliveries: Delivery[]) => void) | undefined;
  /** The computer's stored players, by level. */
  private readonly computers = new Map<Level, PlayerRef>();
  private readonly computerIds = new Set<string>();
  /** Each room's queue: the last operation of the room, which the next one waits for. */
  private readonly queues = new Map<string, Promise<void>>();
  /** Sockets whose hello is under way: true, or false once the socket closed meanwhile. */
  private readonly greeting = new Map<ConnId, boolean>();
  /** The pruner's pass in progress, if any. */
  private pruning: Promise<void> | undefined;
  private readonly peers: Peers | undefined;
  /** Commands forwarded to another process, by ref, awaiting their answer. */
  private readonly forwarded = new Map<number, (deliveries: Delivery[]) => void>();
  private nextRef = 1;
  /** Rooms changed here since the last announcement to the other processes. */
  private readonly dirty = new Set<Room>();

  /** The service with every room not closed brought back from the store. */
  static async start(store: AsyncStore, options: ServiceOptions): Promise<GameService> {
    const restored: Restored[] = [];
    for (const row of await store.openRooms()) {
      const state = JSON.parse(row.state) as RoomState;
      const result = state.status === 'over' && state.matchId !== null ? await store.matchResult(state.matchId) : undefined;
      restored.push({ state, result });
    }
    const service = new GameService(store, options, restored);
    // The other processes' sockets; their rooms' owners are learnt from their announcements.
    if (options.peers) for (const e of await options.peers.presence()) service.lobby.attach(e.conn, e.player, e.proc);
    return service;
  }

  /** Use `start`, which reads the rooms to bring back; this one starts with `restored`. */
  constructor(
    private readonly store: AsyncStore,
    private readonly options: ServiceOptions,
    restored: readonly Restored[] = [],
  ) {
    this.now = options.now ?? Date.now;
    this.log = options.log ?? ((line) => console.error(line));
    this.lobby = new Lobby(this.now());
    this.guestLimit = options.guestsPerAddress === undefined ? undefined : new GuestLimit(options.guestsPerAddress);
    this.chatLimits = new ChatLimits(options.peers?.chat);
    for (const { state, result } of restored) {
      const room = this.addRoom(new Room(state));
      room.outcome = outcomeOf(result);
      if (room.state.computer) this.computerIds.add(room.state.computer.id);
    }
    const peers = (this.peers = options.peers);
    if (peers) {
      peers.onMessage((from, body) => this.fromPeer(from, body));
      peers.onDead((proc) => this.peerDead(proc));
      peers.onLost((id) => this.lost(id));
      peers.onRevived(() => this.revived());
    }
  }

  /**
   * Runs `fn` after every operation queued before it in the room (a command, a timer, a computer
   * move) has finished, so that a room's operations apply in arrival order. Not re-entrant: an
   * operation already in the room's queue must not queue another there.
   */
  private inRoom<T>(id: string, fn: () => Promise<T>): Promise<T> {
    const before = this.queues.get(id);
    const run = before === undefined ? fn() : before.then(fn);
    const tail = run.then(
      () => undefined,
      () => undefined,
    );
    this.queues.set(id, tail);
    void tail.then(() => {
      if (this.queues.get(id) === tail) this.queues.delete(id);
    });
    return run;
  }

  /** Rooms brought back from the store or made since, not closed. */
  get roomCount(): number {
    return this.lobby.rooms.size;
  }

  /** Where the service sends what it does by itself (the computer's moves), as the binding delivers. */
  attach(outlet: (deliveries: Delivery[]) => void): void {
    this.outlet = outlet;
  }

  /** A socket opened from `address` (its remote IP); the service is told before any of its frames. */
  open(conn: ConnId, address: string): void {
    this.addresses.set(conn, address);
  }

  /** The address a socket came from ('' when never told). */
  private addressOf(conn: ConnId): string {
    return this.addresses.get(conn) ?? '';
  }

  async handle(conn: ConnId, msg: ClientMessage): Promise<Delivery[]> {
    const out: Outbox = [];
    try {
      if (msg.type === 'hello') await this.hello(out, conn, msg);
      else {
        const player = this.welcomed(conn);
        if ('room' in msg) {
          const owner = await this.ownerFor(msg.room);
          if (owner !== undefined) return await this.forward(owner, conn, player, msg);
          // A command about a room waits its turn in the room's queue.
          await this.inRoom(msg.room, () => this.command(out, conn, player, msg));
        } else await this.command(out, conn, player, msg);
      }
    } catch (err) {
      this.fail(out, conn, msg.id, err);
    }
    return this.route(out);
  }

  /** An error for a frame that never became a command (bad JSON, a schema failure). */
  reject(conn: ConnId, code: 'bad-json' | 'bad-message', message: string, re?: string | number): Delivery[] {
    return [{ to: [conn], message: { type: 'error', ...(re === undefined ? {} : { re }), code, message } }];
  }

  /** A socket closed: it stops watching; a player's last socket starts the seat hold. */
  async close(conn: ConnId): Promise<Delivery[]> {
    const out: Outbox = [];
    if (this.greeting.has(conn)) this.greeting.set(conn, false);
    if (this.peers && this.lobby.playerOf(conn)) {
      this.peers.left(conn);
      this.peers.publish({ t: 'detach', conn });
    }
    this.departed(out, conn);
    this.addresses.delete(conn);
    return this.route(out);
  }

  /** A socket gone, here or on another process: out of the rooms this process owns and of presence. */
  private departed(out: Outbox, conn: ConnId): void {
    for (const id of this.watching.get(conn) ?? []) {
      const room = this.lobby.rooms.get(id);
      if (room && this.owns(room) && room.spectators.delete(conn)) {
        this.roomsChanged.add(room);
        this.touched(room);
        this.lobbyChanged = true;
      }
    }
    this.watching.delete(conn);
    const gone = this.lobby.detach(conn, this.now());
    if (gone) {
      for (const room of this.roomsOf(gone.id)) if (this.owns(room)) this.broadcastRoom(out, room);
      this.lobbyChanged = true;
    }
  }

  /**
   * Timers: shot clocks that ran out, and seat holds that ended (the opponent may now claim). A
   * room with a timer due runs it in its queue, and its deliveries go out through the outlet as
   * soon as it is done (not held back for slower rooms); the tick resolves once all have run.
   */
  async tick(): Promise<Delivery[]> {
    const out: Outbox = [];
    const now = this.now();
    const pass = this.housekeeping(now);
    const due: Promise<void>[] = [];
    const orphans: Room[] = [];
    for (const room of this.lobby.rooms.values()) {
      if (!this.owns(room)) {
        if (this.orphan(room) && orphans.length < ADOPT_PER_TICK) orphans.push(room);
        continue;
      }
      if (room.state.status === 'playing') this.computerTurn(room);
      if (room.timersQueued || !this.timersDue(room, now)) continue;
      room.timersQueued = true;
      due.push(
        this.inRoom(room.state.id, async () => {
          const mine: Outbox = [];
          try {
            await this.timers(mine, room, this.now());
          } catch (err) {
            // A room whose timer fails (say, the database) stays as it was and is tried again next tick.
            if (!(err instanceof StaleState)) this.log(`timers of room ${room.state.id}: ${(err as Error).stack ?? String(err)}`);
            else this.broadcastRoom(mine, room);
          } finally {
            room.timersQueued = false;
          }
          if (mine.length > 0) this.emit(mine);
        }),
      );
    }
    await Promise.all([pass, this.adoptOrphans(orphans), ...due]);
    for (const room of [...this.roomsChanged]) if (room.state.status !== 'closed') this.broadcastRoom(out, room);
    this.roomsChanged.clear();
    const at = this.now();
    if (this.lobbyChanged && at - this.lobbySentAt >= LOBBY_UPDATE_MS) {
      this.lobbyChanged = false;
      this.lobbySentAt = at;
      if (this.lobby.subscribers.size > 0) this.send(out, [...this.lobby.subscribers], this.lobbyMessage());
    }
    if (at - this.chatPrunedAt >= 10_000) {
      this.chatLimits.prune(at);
      this.chatPrunedAt = at;
    }
    return this.route(out);
  }

  /** Deliveries made outside a command (timers, the computer's moves), out through the binding's outlet. */
  private emit(deliveries: Outbox): void {
    try {
      const here = this.route(deliveries);
      if (here.length > 0) this.outlet?.(here);
    } catch (err) {
      this.log(`delivering: ${(err as Error).stack ?? String(err)}`);
    }
  }

  /** Forgets idle guest limits, and starts (or joins) a batch of the pruner's pass. */
  private housekeeping(now: number): Promise<void> {
    if (this.guestLimit && now >= this.sweepAt) {
      this.guestLimit.sweep(now);
      this.sweepAt = now + SWEEP_EVERY_MS;
    }
    const keep = this.options.guestKeepMs;
    if (this.pruning) return this.pruning;
    if (keep === undefined || now < this.pruneAt) return Promise.resolve();
    this.pruning = this.prune(now, keep).finally(() => (this.pruning = undefined));
    return this.pruning;
  }

  /** Deletes a batch of players who never played and are long gone. */
  private async prune(now: number, keep: number): Promise<void> {
    try {
      const page = await this.store.idlePlayers(this.pruneFrom, now - keep, PRUNE_BATCH);
      // Someone connected is kept even if they never played (a spectator for weeks).
      await this.store.deletePlayers(page.idle.filter((id) => !this.lobby.connected(String(id))));
      this.pruneFrom = page.next ?? 0;
      if (page.next === undefined) this.pruneAt = now + PRUNE_EVERY_MS;
    } catch (err) {
      this.pruneAt = now + PRUNE_EVERY_MS;
      this.log(`pruning players: ${(err as Error).stack ?? String(err)}`);
    }
  }

  /** Whether `timers` has anything to do in the room now (checked without queueing). */
  private timersDue(room: Room, now: number): boolean {
    const s = room.state;
    if (s.status === 'over') return s.closesAt !== null && s.closesAt <= now;
    if (s.status === 'waiting') return s.seats.every((p) => this.awayPastHold(p.id, now));
    if (s.status !== 'playing' || s.game === null) return false;
    if (s.deadline !== null && s.deadline <= now && !this.computersTurn(s)) return true;
    return s.seats.some((p) => this.awayPastHold(p.id, now) && !room.holdsOver.has(p.id));
  }

  /** The computer is on turn and plays it (its turn is bounded by its think budget and pause, not the shot clock). */
  private computersTurn(s: RoomState): boolean {
    return s.computer !== undefined && s.computer !== null && s.game !== null && s.game.turn === s.computer.id && this.options.computer !== undefined;
  }

  private async timers(out: Outbox, room: Room, now: number): Promise<void> {
    const s = room.state;
    if (this.lobby.rooms.get(s.id) !== room) return;
    if (s.status === 'over' && s.closesAt !== null && s.closesAt <= now) return this.settle(room, { ...s, status: 'closed' });
    // A table nobody waits at any more (its player gone past the seat hold) closes.
    if (s.status === 'waiting' && s.seats.every((p) => this.awayPastHold(p.id, now))) return this.settle(room, { ...s, status: 'closed' });
    if (s.status !== 'playing' || s.game === null) return;
    if (s.deadline !== null && s.deadline <= now && !this.computersTurn(s)) {
      if (s.seats.every((p) => !this.lobby.connected(p.id))) {
        // Nobody is there to play: the clock stops until a player comes back, so that no game
        // is decided by timeouts alone.
        await this.settle(room, { ...s, deadline: null });
        this.broadcastRoom(out, room);
      } else {
        await this.move(out, room, afterMove(s, shotClockExpired(s.game), 'played', now), { type: 'clock', player: s.game.turn });
      }
    }
    for (const p of room.state.seats) {
      if (this.awayPastHold(p.id, now) && !room.holdsOver.has(p.id)) {
        room.holdsOver.add(p.id);
        this.broadcastRoom(out, room);
      }
    }
  }

  /** A player disconnected for longer than the seat hold. */
  private awayPastHold(playerId: string, now: number): boolean {
    if (this.isComputer(playerId)) return false;
    const dropped = this.lobby.droppedSince(playerId);
    return dropped !== undefined && dropped + this.options.seatHoldMs <= now;
  }

  private welcomed(conn: ConnId): PlayerRef {
    const player = this.lobby.playerOf(conn);
    if (!player) throw new ServiceError('not-welcomed', 'say hello first: {"type":"hello"}');
    return player;
  }

  private async command(out: Outbox, conn: ConnId, player: PlayerRef, msg: Exclude<ClientMessage, { type: 'hello' }>): Promise<void> {
    switch (msg.type) {
      case 'lobby':
        if (msg.watch === false) this.lobby.subscribers.delete(conn);
        else this.lobby.subscribers.add(conn);
        this.send(out, [conn], this.lobbyMessage(msg.id));
        return;
      case 'create':
        return this.create(out, conn, player, msg);
      case 'rename':
        return this.rename(out, conn, player, msg);
      case 'join':
        return this.join(out, conn, player, msg);
      case 'watch':
        return this.watch(out, conn, msg);
      case 'leave':
        return this.leave(out, conn, player, msg);
      case 'shot':
        return this.shot(out, conn, player, msg);
      case 'place': {
        const { room, game } = this.onTurn(player, msg.room, msg.stateId);
        const next = { ...room.state, game: placeCueBall(game, player.id, msg.cueBall), stateId: room.state.stateId + 1 };
        return this.move(out, room, next, { type: 'place', player: player.id, cueBall: msg.cueBall }, conn, msg.id);
      }
      case 'decide': {
        const { room, game } = this.onTurn(player, msg.room, msg.stateId);
        return this.move(out, room, afterMove(room.state, decide(game, player.id, msg.choice), 'played', this.now()), { type: 'decide', player: player.id, choice: msg.choice }, conn, msg.id);
      }
      case 'concede': {
        const { room, game } = this.inPlay(player, msg.room);
        return this.move(out, room, afterMove(room.state, concede(game, player.id), 'concession', this.now()), { type: 'concede', player: player.id }, conn, msg.id);
      }
      case 'claim':
        return this.claim(out, conn, player, msg);
      case 'rematch':
        return this.rematch(out, conn, player, msg);
      case 'chat': {
        const room = this.room(msg.room);
        if (!this.seated(room, player.id) && !room.spectators.has(conn)) throw new ServiceError('not-seated', 'only the players and spectators of a room may chat there');
        await this.chatLimits.take(player.id, room.state.id, this.now());
        this.send(out, this.members(room), { type: 'chat', room: room.state.id, from: player, text: msg.text, at: this.now() });
        return;
      }
    }
  }

  private async hello(out: Outbox, conn: ConnId, msg: Msg<'hello'>): Promise<void> {
    if (this.lobby.playerOf(conn) || this.greeting.has(conn)) throw new ServiceError('bad-message', 'this socket has said hello already');
    this.greeting.set(conn, true);
    let player: PlayerRef;
    let token: string;
    try {
      if (msg.token !== undefined) {
        const row = await this.store.playerByTokenHash(hashToken(msg.token));
        if (!row) throw new ServiceError('bad-token', 'unknown token: say hello without one to start as a new guest');
        player = { id: String(row.id), name: row.name };
        token = msg.token;
        const tabs = this.options.maxTabsPerPlayer ?? MAX_TABS_PER_PLAYER;
        if (this.lobby.socketsOf(player.id).length >= tabs) throw new ServiceError('too-many-tabs', `at most ${tabs} tabs (sockets) per player are open at once: close one, then say hello again`);
        if (row.lastSeen === null || row.lastSeen + SEEN_EVERY_MS <= this.now()) await this.touch(row.id);
      } else {
        const asked = msg.name === undefined ? undefined : await this.freeName(msg.name);
        this.takeGuest(conn);
        const name = asked ?? (await this.madeUpName());
        token = newToken();
        const row = await this.store.createPlayer(name, hashToken(token));
        player = { id: String(row.id), name: row.name };
      }
      // A socket that closed while its player was looked up is not attached: it would stay connected for ever.
      if (this.greeting.get(conn) !== true) return;
    } finally {
      this.greeting.delete(conn);
    }
    const back = this.lobby.attach(conn, player);
    if (back) this.lobbyChanged = true;
    if (this.peers) {
      this.peers.joined(conn, player);
      this.peers.publish({ t: 'attach', conn, player });
    }
    this.send(out, [conn], { type: 'welcome', ...re(msg.id), player, token });
    await this.arrived(out, conn, player, back);
  }

  /**
   * A player's socket welcomed (here, or on another process): in each of their rooms this process
   * owns, a stopped clock starts again, and the room goes to them (to everyone, when they are back).
   */
  private async arrived(out: Outbox, conn: ConnId, player: PlayerRef, back: boolean): Promise<void> {
    for (const room of this.roomsOf(player.id)) {
      if (!this.owns(room)) continue;
      room.holdsOver.delete(player.id);
      await this.inRoom(room.state.id, async () => {
        const s = room.state;
        if (this.lobby.rooms.get(s.id) !== room) return;
        // A clock stopped while nobody was there starts again for the player on turn.
        const restart = s.status === 'playing' && s.game !== null && s.shotClock > 0 && s.deadline === null;
        if (restart) {
          try {
            await this.settle(room, { ...s, deadline: deadlineAfter(s, this.now()) });
          } catch (err) {
            if (!(err instanceof StaleState)) this.log(`restarting the clock of room ${s.id}: ${(err as Error).stack ?? String(err)}`);
          }
        }
        if (back || restart) this.broadcastRoom(out, room);
        else this.send(out, [conn], { type: 'room', room: this.view(room) });
      });
    }
  }

  /** Notes that a player was here; a failed write (the database) does not refuse their hello. */
  private async touch(id: number): Promise<void> {
    try {
      await this.store.touchPlayer(id);
    } catch (err) {
      this.log(`last seen of player ${id}: ${(err as Error).stack ?? String(err)}`);
    }
  }

  /** A new player from this socket's address, unless the address has made its share this hour. */
  private takeGuest(conn: ConnId): void {
    const wait = this.guestLimit?.take(this.addressOf(conn), this.now()) ?? 0;
    if (wait > 0) {
      const minutes = Math.ceil(wait / 60_000);
      throw new ServiceError(
        'too-many-guests',
        `too many new players from your address (at most ${this.options.guestsPerAddress} an hour): try again in ${minutes} minute${minutes === 1 ? '' : 's'}, or say hello with the token of a player you already have`,
      );
    }
  }

  /**
   * A name asked for, normalised: refused when blank-looking or too long once normalised, or when
   * it looks like another player's name (the same in another case, or with lookalike letters).
   */
  private async freeName(raw: string, self = 0): Promise<string> {
    const name = normalizeName(raw);
    const problem = nameProblem(name);
    if (problem !== undefined) throw new ServiceError('bad-name', problem);
    if (looksLikeComputer(name)) throw new ServiceError('name-taken', `the name "${name}" is the computer's`);
    if ((await this.store.nameOwner(name, self)) !== undefined) throw new ServiceError('name-taken', `the name "${name}" is taken, or one that looks like it`);
    return name;
  }

  /** A new name for the player: unique by its lookalike keys, shown in every room they sit in. */
  private async rename(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'rename'>): Promise<void> {
    // Their own name in another case or with lookalikes is theirs to take.
    const name = await this.freeName(msg.name, Number(player.id));
    await this.store.renamePlayer(Number(player.id), name);
    const renamed = { id: player.id, name };
    this.lobby.rename(renamed);
    this.peers?.publish({ t: 'rename', player: renamed });
    await this.renamedInRooms(out, renamed);
    const others = this.lobby.socketsOf(player.id).filter((c) => c !== conn);
    this.send(out, others, { type: 'player', player: renamed });
    this.send(out, [conn], { type: 'player', ...re(msg.id), player: renamed });
    this.lobbyChanged = true;
  }

  /** A player's new name in the seats of the rooms this process owns. */
  private async renamedInRooms(out: Outbox, renamed: PlayerRef): Promise<void> {
    const player = renamed;
    for (const room of this.roomsOf(player.id)) {
      if (!this.owns(room)) continue;
      await this.inRoom(room.state.id, async () => {
        if (this.lobby.rooms.get(room.state.id) !== room || !this.seated(room, player.id)) return;
        try {
          await this.settle(room, { ...room.state, seats: room.state.seats.map((p) => (p.id === player.id ? renamed : p)) });
        } catch (err) {
          // The name is theirs already; a room that could not be rewritten shows it after its next change.
          this.log(`renaming in room ${room.state.id}: ${(err as Error).message}`);
        }
        this.broadcastRoom(out, room);
      });
    }
  }

  /** A free made-up name; a few tries, as a collision in 31^8 names is all but impossible. */
  private async madeUpName(): Promise<string> {
    for (let i = 0; i < GUEST_NAME_TRIES; i++) {
      const name = guestName();
      if ((await this.store.nameOwner(name)) === undefined) return name;
    }
    throw new Error(`no free guest name in ${GUEST_NAME_TRIES} tries`);
  }

  private async create(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'create'>): Promise<void> {
    const level = msg.computer;
    if (level !== undefined && !isLevel(level)) throw new ServiceError('bad-message', 'computer: must be a level from 1 to 5 (a whole number)');
    if (level !== undefined && !this.options.computer) throw new ServiceError('bad-message', 'computer: this server does not run the computer opponent');
    let open = 0;
    for (const room of this.lobby.rooms.values()) {
      if (room.state.createdBy === player.id && (room.state.status === 'waiting' || room.state.status === 'playing')) open++;
    }
    // Counted here first (no round trip for the common refusal); the store's count is the one that holds across processes.
    if (open >= MAX_OPEN_ROOMS_PER_PLAYER) throw tooManyRooms();
    const state: RoomState = {
      id: randomBytes(6).toString('base64url'),
      kind: msg.kind,
      raceTo: msg.raceTo ?? DEFAULT_RACE[msg.kind],
      private: msg.private ?? false,
      shotClock: msg.shotClock ?? 0,
      guidance: msg.guidance ?? 'contact',
      createdBy: player.id,
      seats: [player],
      status: 'waiting',
      stateId: 0,
      game: null,
      matchId: null,
      order: [],
      seed: 0,
      frame: 0,
      frames: msg.kind === 'snooker' ? {} : null,
      deadline: null,
      rematch: [],
      winner: null,
      how: null,
      left: [],
      closesAt: null,
      tally: EMPTY_TALLY,
    };
    const computer = level === undefined ? undefined : await this.computerPlayer(level);
    const seated: RoomState = computer ? { ...state, seats: [player, computer], computer: { id: computer.id, level: level! } } : state;
    // With several processes the maker's process owns the new room: its lease first.
    if (this.peers && !(await this.peers.acquire(seated.id))) throw new Error(`the lease of new room ${seated.id} is held elsewhere`);
    try {
      await this.store.createRoom({ ...seated, createdBy: Number(player.id), state: JSON.stringify(seated) });
    } catch (err) {
      this.peers?.release(seated.id);
      throw err instanceof TooManyRoomsError ? tooManyRooms() : err;
    }
    const room = this.addRoom(new Room(seated));
    room.owner = this.peers?.self;
    this.touched(room);
    if (!state.private) this.lobbyChanged = true;
    // Against the computer the game starts at once, the person breaking.
    if (computer) await this.inRoom(seated.id, () => this.startMatch(out, room, { ...seated, order: [player.id, computer.id] }, conn, msg.id));
    else this.broadcastRoom(out, room, conn, msg.id);
  }

  /** The computer's stored player at a level (made on first use). */
  private async computerPlayer(level: Level): Promise<PlayerRef> {
    let p = this.computers.get(level);
    if (!p) {
      const row = await this.store.computerPlayer(level, computerName(level), hashToken(newToken()));
      p = { id: String(row.id), name: row.name };
      this.computers.set(level, p);
      this.computerIds.add(p.id);
    }
    return p;
  }

  private isComputer(playerId: string): boolean {
    return this.computerIds.has(playerId);
  }

  /**
   * Asks the computer for its move when it is on turn and not already thinking about this state.
   * The decision comes back from a worker; it is played once the balls of the last shot have
   * stopped and the pause has passed, through the same steps as a person's move.
   */
  private computerTurn(room: Room): void {
    const s = room.state;
    const c = s.computer;
    const options = this.options.computer;
    if (!c || !options || !this.owns(room) || s.status !== 'playing' || s.game === null || s.game.winner !== null || s.game.turn !== c.id) return;
    if (room.thinking?.stateId === s.stateId) return;
    clearTimeout(room.thinking?.timer);
    const stateId = s.stateId;
    const game = s.game;
    const thinking: { stateId: number; timer?: NodeJS.Timeout } = { stateId };
    room.thinking = thinking;
    const playAt = Math.max(this.now(), room.stillAt) + options.pauseMs;
    options.thinker
      .think({ game, level: c.level, seed: decisionSeed(s.id, s.matchId, stateId) })
      .catch((err: unknown) => {
        this.log(`computer in room ${s.id}: ${(err as Error).message}; it plays a simple stroke`);
        return fallbackDecision(game);
      })
      .then((decision) => {
        if (room.thinking !== thinking) return;
        // Played in the room's queue, after whatever came before it there.
        const play = () => this.inRoom(s.id, () => this.computerPlays(room, thinking, decision)).catch((err: unknown) => this.log(`computer in room ${s.id}: ${(err as Error).stack ?? String(err)}`));
        thinking.timer = setTimeout(play, Math.max(0, playAt - this.now()));
        thinking.timer.unref?.();
      })
      .catch((err: unknown) => this.log(`computer in room ${s.id}: ${(err as Error).stack ?? String(err)}`));
  }

  /** Plays the computer's decision if the room is still where it was; a refused one gives way to a fallback. */
  private async computerPlays(room: Room, thinking: NonNullable<Room['thinking']>, decision: Decision): Promise<void> {
    const s = room.state;
    if (room.thinking !== thinking || this.lobby.rooms.get(s.id) !== room || !this.owns(room)) return;
    if (s.status !== 'playing' || s.game === null || s.stateId !== thinking.stateId || s.game.turn !== s.computer?.id) return;
    const me = s.seats.find((p) => p.id === s.computer!.id)!;
    const game = s.game;
    const tries: ((out: Outbox) => Promise<void>)[] = [
      (out) => this.playDecision(out, room, game, me, decision),
      (out) => this.playDecision(out, room, game, me, fallbackDecision(game)),
      (out) => this.move(out, room, afterMove(s, shotClockExpired(game), 'played', this.now()), { type: 'clock', player: me.id }),
    ];
    for (const [i, attempt] of tries.entries()) {
      // Each try has its own outbox: a refused one sends nothing.
      const out: Outbox = [];
      try {
        await attempt(out);
        this.emit(out);
        return;
      } catch (err) {
        if (err instanceof StaleState) {
          // Another writer moved the room on: its new state is the room's, nothing of this decision is played.
          this.log(`computer in room ${s.id}: ${err.message}`);
          const fresh: Outbox = [];
          this.broadcastRoom(fresh, room);
          this.emit(fresh);
          return;
        }
        const last = i === tries.length - 1;
        this.log(`computer in room ${s.id}: move ${i + 1} refused: ${(err as Error).message}${last ? '; tried again at the next tick' : ''}`);
        if (last) room.thinking = null;
      }
    }
  }

  /** The computer's decision through the person's path: the stroke validated as a message is, or the choice. */
  private async playDecision(out: Outbox, room: Room, game: Game, me: PlayerRef, d: Decision): Promise<void> {
    if ('choice' in d) {
      return this.move(out, room, afterMove(room.state, decide(game, me.id, d.choice), 'played', this.now()), { type: 'decide', player: me.id, choice: d.choice });
    }
    const { player: _player, ...stroke } = d.shot;
    const input = v.parse(ShotSchema, stroke);
    const cueBall = d.cueBall === undefined ? undefined : v.parse(PointSchema, d.cueBall);
    return this.stroke(out, room, game, me, input, cueBall);
  }

  private async join(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'join'>): Promise<void> {
    const room = this.room(msg.room);
    if (this.seated(room, player.id)) {
      this.send(out, [conn], { type: 'room', ...re(msg.id), room: this.view(room) });
      return;
    }
    if (room.state.status !== 'waiting' || room.state.seats.length >= 2) throw new ServiceError('room-full', `room ${msg.room} has both its players`);
    const seats = [...room.state.seats, player];
    // A spectator who takes the seat watches no more: the seat brings every message anyway.
    for (const c of this.lobby.socketsOf(player.id)) {
      if (room.spectators.delete(c)) this.watching.get(c)?.delete(room.state.id);
    }
    await this.startMatch(out, room, { ...room.state, seats, order: seats.map((p) => p.id) }, conn, msg.id);
    this.index(room);
  }

  /** A new match in the room: the first of `order` breaks. */
  private async startMatch(out: Outbox, room: Room, base: RoomState, conn: ConnId, id: Re): Promise<void> {
    const now = this.now();
    const seeded: RoomState = { ...base, seed: randomSeed(), frame: 0, frames: base.kind === 'snooker' ? {} : null, rematch: [], winner: null, how: null, left: [], closesAt: null, tally: EMPTY_TALLY, status: 'playing' };
    const started: RoomState = { ...seeded, stateId: base.stateId + 1, game: gameFor(seeded, 0) };
    const [a, b] = started.order;
    let next: RoomState = { ...started, deadline: deadlineAfter(started, now) };
    const start = JSON.stringify(started.game);
    const expect = room.state.stateId;
    try {
      await this.store.startMatch({ roomId: started.id, kind: started.kind, raceTo: started.raceTo, player1: Number(a), player2: Number(b), seed: started.seed, start }, (matchId) => {
        next = { ...next, matchId };
        return { roomId: next.id, status: next.status, state: JSON.stringify(next), expectStateId: expect };
      });
    } catch (err) {
      if (err instanceof StaleRoomError) await this.stale(room);
      throw err;
    }
    room.state = next;
    room.thinking = null;
    room.outcome = null;
    this.touched(room);
    this.broadcastRoom(out, room, conn, id);
    this.lobbyChanged = true;
    this.computerTurn(room);
  }

  private async watch(out: Outbox, conn: ConnId, msg: Msg<'watch'>): Promise<void> {
    const room = this.room(msg.room);
    const player = this.lobby.playerOf(conn);
    if (player && this.seated(room, player.id)) {
      // A player's own room: its state, without counting them as a spectator.
      this.send(out, [conn], { type: 'room', ...re(msg.id), room: this.view(room) });
      return;
    }
    room.spectators.add(conn);
    let set = this.watching.get(conn);
    if (!set) this.watching.set(conn, (set = new Set()));
    set.add(room.state.id);
    // The new spectator gets the room at once; the others see the count at the next tick.
    this.send(out, [conn], { type: 'room', ...re(msg.id), room: this.view(room) });
    this.roomsChanged.add(room);
    this.touched(room);
    if (!room.state.private) this.lobbyChanged = true;
  }

  private async leave(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'leave'>): Promise<void> {
    const room = this.room(msg.room);
    if (room.spectators.delete(conn)) {
      this.watching.get(conn)?.delete(room.state.id);
      this.send(out, [conn], { type: 'left', ...re(msg.id), room: room.state.id });
      this.roomsChanged.add(room);
      this.touched(room);
      this.lobbyChanged = true;
      return;
    }
    if (!this.seated(room, player.id)) throw new ServiceError('not-seated', `you are not in room ${msg.room}`);
    const s = room.state;
    if (s.status === 'waiting') {
      const seats = s.seats.filter((p) => p.id !== player.id);
      await this.settle(room, { ...s, seats, status: seats.length === 0 ? 'closed' : 'waiting' });
    } else if (s.status === 'playing' && s.game) {
      // Leaving a game in play concedes it (and the concession tells the room).
      const conceded = afterMove(s, concede(s.game, player.id), 'concession', this.now());
      await this.move(out, room, { ...conceded, left: [player.id] }, { type: 'concede', player: player.id });
      this.seatsOf.get(player.id)?.delete(s.id);
      this.send(out, [conn], { type: 'left', ...re(msg.id), room: s.id });
      return;
    } else if (s.status === 'over' && !s.left.includes(player.id)) {
      // Once both players have left a finished room it closes.
      const left = [...s.left, player.id];
      const gone = left.length + (s.computer ? 1 : 0);
      await this.settle(room, { ...s, left, status: gone >= s.seats.length ? 'closed' : 'over' });
    }
    this.seatsOf.get(player.id)?.delete(s.id);
    this.send(out, [conn], { type: 'left', ...re(msg.id), room: s.id });
    if (room.state.status !== 'closed') this.broadcastRoom(out, room);
  }

  /** A change of the room with no move in it (seats, leaving, closing): stored, made current, and a closed room forgotten. */
  private async settle(room: Room, next: RoomState): Promise<void> {
    await this.commit(room, next, [await this.change(next, room.state.stateId)]);
    this.lobbyChanged = true;
  }

  /**
   * The one way a room's state changes: the changes stored, each guarded by the stateId the room
   * had, and only then `next` made current. A room another writer changed first is reloaded
   * from the store and the command refused (stale-state); a failed write changes nothing.
   */
  private async commit(room: Room, next: RoomState, changes: readonly RoomChange[]): Promise<void> {
    try {
      await this.store.saveChanges(...changes);
    } catch (err) {
      if (err instanceof StaleRoomError) await this.stale(room);
      throw err;
    }
    room.state = next;
    this.touched(room);
    if (next.status === 'closed') this.forget(room);
  }

  /** Takes the room as last committed in the store, after a write found it changed; throws StaleState. */
  private async stale(room: Room): Promise<never> {
    const row = await this.store.room(room.state.id);
    if (row) {
      const state = JSON.parse(row.state) as RoomState;
      room.outcome = state.status === 'over' && state.matchId !== null ? outcomeOf(await this.store.matchResult(state.matchId)) : null;
      room.state = state;
      room.thinking = null;
      this.index(room);
      this.touched(room);
      if (state.status === 'closed') this.forget(room);
    }
    this.lobbyChanged = true;
    throw new StaleState(room);
  }

  /** A closed room leaves the lobby, its seats and its spectators' lists. */
  private forget(room: Room): void {
    const s = room.state;
    if (this.lobby.rooms.get(s.id) === room) this.lobby.rooms.delete(s.id);
    for (const p of s.seats) this.seatsOf.get(p.id)?.delete(s.id);
    for (const c of room.spectators) this.watching.get(c)?.delete(s.id);
    this.peers?.release(s.id);
  }

  private async shot(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'shot'>): Promise<void> {
    const { room, game } = this.onTurn(player, msg.room, msg.stateId);
    return this.stroke(out, room, game, player, msg.shot, msg.cueBall, conn, msg.id);
  }

  /** A stroke of the player on turn (a person's or the computer's): simulated, judged, stored, sent. */
  private async stroke(out: Outbox, room: Room, game: Game, player: PlayerRef, input: ShotInput, cueBall: Point | undefined, conn?: ConnId, id?: Re): Promise<void> {
    const msg = { shot: input, cueBall };
    const shot = { ...msg.shot, player: player.id };
    const played = playShot(game, shot, msg.cueBall);
    const now = this.now();
    // The next player's clock starts once the balls have stopped.
    const moved = afterMove(room.state, played.game, 'played', now, now + Math.ceil(played.outcome.duration * 1000));
    const action: MatchAction = { type: 'shot', player: player.id, shot: msg.shot, ...(msg.cueBall ? { cueBall: msg.cueBall } : {}), hash: played.outcome.hash };
    // A snooker frame won but not the match: the frame's end and the next frame are two changes.
    const frameOver = moved.game !== played.game;
    const first: RoomState = frameOver ? { ...moved, game: played.game, frame: room.state.frame, deadline: null } : moved;
    const after: RoomState = frameOver ? { ...moved, stateId: moved.stateId + 1 } : moved;
    const changes = [await this.change(first, room.state.stateId, action)];
    if (frameOver) changes.push(await this.change(after, first.stateId, { type: 'frame', players: after.game!.players, seed: after.seed + after.frame }));
    await this.commit(room, after, changes);
    room.stillAt = now + Math.ceil(played.outcome.duration * 1000);
    if (changes.some((c) => c.result)) await this.learnOutcome(room);
    const o = played.outcome;
    const message: ServerMessage = {
      type: 'shot',
      room: room.state.id,
      match: first.matchId!,
      stateId: first.stateId,
      shot,
      ...(msg.cueBall ? { cueBall: msg.cueBall } : {}),
      outcome: { hash: o.hash, balls: o.balls, events: o.events, duration: o.duration },
      game: played.game,
      ...(first.deadline === null ? {} : { deadline: first.deadline }),
    };
    const members = this.members(room);
    this.send(
      out,
      members.filter((c) => c !== conn),
      message,
    );
    if (conn !== undefined) this.send(out, [conn], { ...message, ...re(id) });
    if (frameOver || after.status !== 'playing') this.broadcastRoom(out, room);
    if (after.status !== 'playing') this.lobbyChanged = true;
    this.computerTurn(room);
  }

  /** Whether the match just finished counted for the ratings, as the store decided; kept on the room for its views. */
  private async learnOutcome(room: Room): Promise<void> {
    const matchId = room.state.matchId;
    if (matchId === null) return;
    try {
      room.outcome = outcomeOf(await this.store.matchResult(matchId));
    } catch (err) {
      // The result is stored; its view only lacks the rated line until the room is read again.
      this.log(`result of match ${matchId}: ${(err as Error).stack ?? String(err)}`);
    }
  }

  private async claim(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'claim'>): Promise<void> {
    const { room, game } = this.inPlay(player, msg.room);
    const other = room.state.seats.find((p) => p.id !== player.id)!;
    if (this.isComputer(other.id)) throw new ServiceError('not-claimable', `${other.name} never leaves its seat`);
    const dropped = this.lobby.droppedSince(other.id);
    if (dropped === undefined) throw new ServiceError('not-claimable', `${other.name} is connected`);
    const until = dropped + this.options.seatHoldMs;
    if (this.now() < until) throw new ServiceError('not-claimable', `${other.name}'s seat is held for ${Math.ceil((until - this.now()) / 1000)} s more`);
    return this.move(out, room, afterMove(room.state, claimGame(game, player.id), 'claim', this.now()), { type: 'claim', player: player.id }, conn, msg.id);
  }

  private async rematch(out: Outbox, conn: ConnId, player: PlayerRef, msg: Msg<'rematch'>): Promise<void> {
    const room = this.room(msg.room);
    if (!this.seated(room, player.id)) throw new ServiceError('not-seated', `you are not a player of room ${msg.room}`);
    const s = room.state;
    if (s.status !== 'over' || s.seats.length < 2) throw new ServiceError('not-playing', 'a rematch is asked for once the game is over');
    if (s.left.length > 0) throw new ServiceError('not-playing', 'a player has left the room: no rematch');
    // The computer always wants another game.
    const willing = s.computer ? [s.computer.id] : [];
    const asked = [...new Set([...s.rematch, player.id, ...willing])];
    if (asked.length < 2) {
      const next = { ...s, rematch: asked };
      await this.commit(room, next, [await this.change(next, s.stateId)]);
      this.broadcastRoom(out, room, conn, msg.id);
      return;
    }
    // The other player breaks the new match.
    return this.startMatch(out, room, { ...s, order: [...s.order].reverse() }, conn, msg.id);
  }

  /** Makes a move's state current: stored with its action (and the result, when it ends the match), then sent. */
  private async move(out: Outbox, room: Room, next: RoomState, action: MatchAction, conn?: ConnId, id?: Re): Promise<void> {
    const change = await this.change(next, room.state.stateId, action);
    await this.commit(room, next, [change]);
    if (change.result) await this.learnOutcome(room);
    this.broadcastRoom(out, room, conn, id);
    if (next.status !== 'playing') this.lobbyChanged = true;
    this.computerTurn(room);
  }

  /**
   * The store's record of a room's new state, written only while the stored room is at `expect`
   * (the stateId its writer read): the action that made it in the match's log and, when that
   * action ends the match, its result.
   */
  private async change(next: RoomState, expect: number, action?: MatchAction): Promise<RoomChange> {
    const logged = action !== undefined && next.matchId !== null;
    const ends = logged && next.status === 'over' && next.winner !== null;
    return {
      roomId: next.id,
      status: next.status,
      state: JSON.stringify(next),
      expectStateId: expect,
      ...(logged ? { action: { matchId: next.matchId!, seq: next.stateId, json: JSON.stringify(action) } } : {}),
      ...(ends ? { result: await this.result(next, action!) } : {}),
    };
  }

  /**
   * A finished match's result, with the records its tally holds. Rated only after a real game:
   * each player took RATED_MIN_SHOTS shots, and the server's clock ran the minimum time of play
   * between the start and the result (the store adds the pair's daily limit).
   */
  private async result(s: RoomState, last: MatchAction): Promise<MatchResult> {
    const matchId = s.matchId!;
    const [shots, started] = await Promise.all([this.store.shotCounts(matchId), this.store.matchStartedAt(matchId)]);
    if (last.type === 'shot') shots.set(last.player, (shots.get(last.player) ?? 0) + 1);
    const loser = s.order.find((p) => p !== s.winner)!;
    const startedAt = started ?? this.now();
    let unrated: UnratedReason | undefined;
    if (s.computer) unrated = 'computer';
    else if (!s.order.every((p) => (shots.get(p) ?? 0) >= RATED_MIN_SHOTS)) unrated = 'few-shots';
    else if (this.now() - startedAt < this.minPlayMs) unrated = 'too-short';
    return {
      matchId,
      kind: s.kind,
      winner: Number(s.winner),
      loser: Number(loser),
      how: s.how ?? 'played',
      scores: JSON.stringify(scoresOf(s)),
      rated: unrated === undefined,
      ...(unrated === undefined ? {} : { unrated }),
      records: tallied(s.kind, s.tally).map((a) => ({ what: a.what, player: Number(a.player), value: a.value, better: a.what === 'break-and-run' ? -a.value : a.value })),
    };
  }

  // ---- Several processes (options.peers) ----

  /** Whether this process runs the room's commands and clocks: always, unless there are peers. */
  private owns(room: Room): boolean {
    return this.peers === undefined || room.owner === this.peers.self;
  }

  /** Announced to the other processes at the end of the operation (several processes only). */
  private touched(room: Room): void {
    if (this.peers) this.dirty.add(room);
  }

  /** Where a room's commands run: undefined for here, else the owning process. */
  private async ownerFor(id: string): Promise<string | undefined> {
    const peers = this.peers;
    if (!peers) return undefined;
    const room = this.lobby.rooms.get(id);
    if (room?.owner === peers.self) return undefined;
    if (room?.owner !== undefined && peers.alive(room.owner)) return room.owner;
    if (await this.adopt(id)) return undefined;
    const owner = await peers.ownerOf(id);
    if (owner !== null && owner !== peers.self && peers.alive(owner)) return owner;
    if (!room) throw new ServiceError('no-room', `there is no room ${id}`);
    throw unavailable('its server has gone and another takes it over within seconds');
  }

  /**
   * Takes a room no live process owns: its lease, then its state as last committed in the
   * store (the truth, whatever the mirror held). False when another process holds the lease or the
   * room is no more. Runs in the room's queue, so no operation of the room is under way.
   */
  private adopt(id: string): Promise<boolean> {
    const peers = this.peers!;
    return this.inRoom(id, async () => {
      if (this.lobby.rooms.get(id)?.owner === peers.self) return true;
      if (!(await peers.acquire(id))) return false;
      try {
        const row = await this.store.room(id);
        const state = row ? (JSON.parse(row.state) as RoomState) : undefined;
        let room = this.lobby.rooms.get(id);
        if (!state || state.status === 'closed') {
          if (room && state) room.state = state;
          if (room) this.forget(room);
          peers.release(id);
          return false;
        }
        if (room) room.state = state;
        else room = this.addRoom(new Room(state));
        this.index(room);
        room.outcome = state.status === 'over' && state.matchId !== null ? outcomeOf(await this.store.matchResult(state.matchId)) : null;
        room.owner = peers.self;
        room.thinking = null;
        room.announced = ''; // the new owner is announced, whatever the summary
        if (room.state.computer) this.computerIds.add(room.state.computer.id);
        this.touched(room);
        this.lobbyChanged = true;
        // Everyone there gets the room as stored: a player who came back meanwhile had no owner to send it.
        const out: Outbox = [];
        this.broadcastRoom(out, room);
        this.emit(out);
        return true;
      } catch (err) {
        peers.release(id);
        throw err;
      }
    });
  }

  /** A room no live process owns (several processes only): its clocks stand still until one adopts it. */
  private orphan(room: Room): boolean {
    return this.peers !== undefined && (room.owner === undefined || !this.peers.alive(room.owner));
  }

  /** Rooms whose owner is unknown or dead, taken over (a few a tick) so that their clocks run again. */
  private async adoptOrphans(orphans: readonly Room[]): Promise<void> {
    const peers = this.peers;
    if (!peers) return;
    await Promise.all(
      orphans.map(async (room) => {
        try {
          if (await this.adopt(room.state.id)) return;
          // Owned by a live process whose announcement this one has not seen: note the owner.
          const owner = await peers.ownerOf(room.state.id);
          if (owner !== null && room.owner === undefined) room.owner = owner;
        } catch (err) {
          this.log(`taking over room ${room.state.id}: ${(err as Error).message}`);
        }
      }),
    );
  }

  /** A room command sent to the process that owns the room; resolves with the deliveries for this process. */
  private forward(owner: string, conn: ConnId, player: PlayerRef, msg: Extract<ClientMessage, { room: string }>): Promise<Delivery[]> {
    const peers = this.peers!;
    const ref = this.nextRef++;
    return new Promise((resolve) => {
      const fail = (why: string) => {
        if (!this.forwarded.delete(ref)) return;
        clearTimeout(timer);
        resolve([{ to: [conn], message: { type: 'error', ...re(msg.id), code: 'unavailable', message: `room ${msg.room} cannot be reached: ${why}; try again` } }]);
      };
      const timer = setTimeout(() => fail(`its server did not answer within ${FORWARD_TIMEOUT_MS / 1000} s`), FORWARD_TIMEOUT_MS);
      this.forwarded.set(ref, (deliveries) => {
        clearTimeout(timer);
        this.forwarded.delete(ref);
        resolve(deliveries);
      });
      const body: PeerMessage = { t: 'cmd', ref, conn, player, msg };
      peers.send(owner, body).then(
        (heard) => {
          if (heard) return;
          const room = this.lobby.rooms.get(msg.room);
          if (room?.owner === owner) room.owner = undefined;
          fail('its server has gone and another takes it over within seconds');
        },
        (err: unknown) => fail(`the cluster's bus failed (${(err as Error).message})`),
      );
    });
  }

  /** A command forwarded by another process: run here as the owner, the answer sent back with its ref. */
  private async remoteCommand(from: string, ref: number, conn: ConnId, player: PlayerRef, msg: ClientMessage): Promise<void> {
    const out: Outbox = [];
    try {
      if (!('room' in msg)) throw new ServiceError('bad-message', 'only room commands are forwarded');
      const room = this.lobby.rooms.get(msg.room);
      if ((!room || !this.owns(room)) && !(await this.adopt(msg.room))) throw unavailable('it moved to another server');
      await this.inRoom(msg.room, () => this.command(out, conn, player, msg));
    } catch (err) {
      this.fail(out, conn, msg.id, err);
    }
    const here = this.route(out, { proc: from, ref });
    if (here.length > 0) this.outlet?.(here);
  }

  /**
   * Several processes: announces the rooms changed here, sends each other process the deliveries
   * for its sockets (with `ack`'s ref to the process awaiting a forwarded command's answer), and
   * returns this process's own.
   */
  private route(out: Outbox, ack?: { readonly proc: string; readonly ref: number }): Delivery[] {
    const peers = this.peers;
    if (!peers) return out;
    for (const room of this.dirty) {
      // Only what the other processes read of a room not theirs (the lobby, seats, spectators) is
      // announced: a shot that changes none of it costs no message to every process.
      const s = room.state;
      const summary = JSON.stringify([s.status, s.seats, s.left, s.private, [...room.spectators]]);
      if (summary === room.announced) continue;
      room.announced = summary;
      const body: PeerMessage = { t: 'room', state: { ...s }, spectators: [...room.spectators], outcome: room.outcome };
      peers.publish(body);
    }
    this.dirty.clear();
    const { here, there } = splitDeliveries(out, (c) => (this.addresses.has(c) ? undefined : this.lobby.procOf(c)));
    // The process awaiting a forwarded command's answer gets its ref even with nothing to deliver.
    if (ack && !there.has(ack.proc)) there.set(ack.proc, []);
    for (const [proc, deliveries] of there) {
      const body: PeerMessage = { t: 'out', ...(ack?.proc === proc ? { ref: ack.ref } : {}), deliveries };
      peers.send(proc, body).catch((err: unknown) => this.log(`to process ${proc}: ${(err as Error).message}`));
    }
    return here;
  }

  /** A message from another process, checked; a malformed one is logged and dropped. */
  private fromPeer(from: string, body: unknown): void {
    const parsed = v.safeParse(PeerMessageSchema, body);
    if (!parsed.success) {
      this.log(`dropped a malformed message from process ${from}: ${parsed.issues[0]?.message ?? 'invalid'}`);
      return;
    }
    const m = parsed.output;
    const failed = (err: unknown) => this.log(`message ${m.t} from process ${from}: ${(err as Error).stack ?? String(err)}`);
    switch (m.t) {
      case 'cmd':
        void this.remoteCommand(from, m.ref, m.conn, m.player, m.msg).catch(failed);
        return;
      case 'out': {
        const deliveries = m.deliveries as unknown as Delivery[];
        const waiting = m.ref === undefined ? undefined : this.forwarded.get(m.ref);
        if (waiting) waiting(deliveries);
        else this.emit(deliveries);
        return;
      }
      case 'room':
        this.mirror(from, m.state as unknown as RoomState, m.spectators, m.outcome as Room['outcome']);
        return;
      case 'attach': {
        const back = this.lobby.attach(m.conn, m.player, from);
        if (back) this.lobbyChanged = true;
        const out: Outbox = [];
        void this.arrived(out, m.conn, m.player, back).then(() => this.emit(out), failed);
        return;
      }
      case 'detach': {
        const out: Outbox = [];
        this.departed(out, m.conn);
        this.emit(out);
        return;
      }
      case 'rename': {
        this.lobby.rename(m.player);
        this.lobbyChanged = true;
        const out: Outbox = [];
        void this.renamedInRooms(out, m.player).then(() => this.emit(out), failed);
        return;
      }
    }
  }

  /** A room as its owner committed it: this process's mirror of it follows (never backwards). */
  private mirror(from: string, state: RoomState, spectators: readonly ConnId[], outcome: Room['outcome']): void {
    let room = this.lobby.rooms.get(state.id);
    if (!room) {
      if (state.status === 'closed') return;
      room = this.addRoom(new Room(state));
    } else {
      if (state.stateId < room.state.stateId) return;
      // Another process took the room over (this one's lease lapsed in a stall): it steps down.
      if (room.owner === this.peers!.self) this.stepDown(room);
      room.state = state;
      this.index(room);
    }
    room.owner = from;
    room.outcome = outcome;
    for (const c of room.spectators) this.watching.get(c)?.delete(state.id);
    room.spectators.clear();
    for (const c of spectators) {
      room.spectators.add(c);
      let set = this.watching.get(c);
      if (!set) this.watching.set(c, (set = new Set()));
      set.add(state.id);
    }
    if (state.computer) this.computerIds.add(state.computer.id);
    if (state.status === 'closed') this.forget(room);
    this.lobbyChanged = true;
  }

  private stepDown(room: Room): void {
    room.owner = undefined;
    clearTimeout(room.thinking?.timer);
    room.thinking = null;
    this.peers?.release(room.state.id);
  }

  /** A lease this process could not renew: the room is another's (or nobody's, till adopted). */
  private lost(id: string): void {
    const room = this.lobby.rooms.get(id);
    if (room && room.owner === this.peers?.self) this.stepDown(room);
  }

  /** A dead process's sockets leave presence (their players' seat holds start). */
  private peerDead(proc: string): void {
    this.log(`process ${proc} is gone: its sockets leave, its rooms are taken over`);
    const out: Outbox = [];
    for (const conn of this.lobby.connsOf(proc)) this.departed(out, conn);
    // Its rooms need nothing here: a dead owner makes them orphans, adopted at the next ticks.
    this.emit(out);
  }

  /** This process had been taken for dead: its sockets are told again. */
  private revived(): void {
    for (const conn of this.addresses.keys()) {
      const player = this.lobby.playerOf(conn);
      if (!player) continue;
      this.peers!.joined(conn, player);
      this.peers!.publish({ t: 'attach', conn, player });
    }
  }

  private room(id: string): Room {
    const room = this.lobby.rooms.get(id);
    if (!room || room.state.status === 'closed') throw new ServiceError('no-room', `there is no room ${id}`);
    return room;
  }

  private seated(room: Room, playerId: string): boolean {
    return room.state.seats.some((p) => p.id === playerId);
  }

  private inPlay(player: PlayerRef, id: string): { room: Room; game: Game } {
    const room = this.room(id);
    if (!this.seated(room, player.id)) throw new ServiceError('not-seated', `you are not a player of room ${id}`);
    if (room.state.status !== 'playing' || room.state.game === null) throw new ServiceError('not-playing', `room ${id} has no game in play`);
    return { room, game: room.state.game };
  }

  private onTurn(player: PlayerRef, id: string, stateId: number): { room: Room; game: Game } {
    const found = this.inPlay(player, id);
    if (stateId !== found.room.state.stateId) throw new ServiceError('stale-state', `the room is at stateId ${found.room.state.stateId}, not ${stateId}`);
    if (found.game.turn !== player.id) throw new ServiceError('not-your-turn', `it is not your turn`);
    return found;
  }

  private addRoom(room: Room): Room {
    this.lobby.rooms.set(room.state.id, room);
    this.index(room);
    return room;
  }

  private index(room: Room): void {
    for (const p of room.state.seats) {
      let set = this.seatsOf.get(p.id);
      if (!set) this.seatsOf.set(p.id, (set = new Set()));
      set.add(room.state.id);
    }
  }

  private roomsOf(playerId: string): Room[] {
    const out: Room[] = [];
    for (const id of this.seatsOf.get(playerId) ?? []) {
      const room = this.lobby.rooms.get(id);
      if (room && room.state.status !== 'closed' && this.seated(room, playerId) && !room.state.left.includes(playerId)) out.push(room);
    }
    return out;
  }

  /** Every socket in the room: the seated players' (all their tabs) and the spectators'. */
  private members(room: Room): ConnId[] {
    const out = new Set<ConnId>(room.spectators);
    for (const p of room.state.seats) for (const c of this.lobby.socketsOf(p.id)) out.add(c);
    return [...out];
  }

  private view(room: Room) {
    const view = roomView(room, (p) => {
      if (this.isComputer(p.id)) return { connected: true };
      const dropped = this.lobby.droppedSince(p.id);
      return dropped === undefined ? { connected: true } : { connected: false, heldUntil: dropped + this.options.seatHoldMs };
    });
    const result = room.state.status === 'over' ? room.outcome : null;
    if (result === null) return view;
    return result.unrated === null ? { ...view, rated: result.rated } : { ...view, rated: result.rated, unrated: unratedSentence(result.unrated, this.minPlayMs) };
  }

  private get minPlayMs(): number {
    return this.options.ratedMinPlayMs ?? RATED_MIN_PLAY_MS;
  }

  /** `room` to everyone there; the one who asked gets it with `re`. */
  private broadcastRoom(out: Outbox, room: Room, conn?: ConnId, id?: Re): void {
    this.roomsChanged.delete(room);
    const view = this.view(room);
    const members = this.members(room);
    this.send(
      out,
      members.filter((c) => c !== conn),
      { type: 'room', room: view },
    );
    if (conn !== undefined) this.send(out, [conn], { type: 'room', ...re(id), room: view });
  }

  private send(out: Outbox, to: readonly ConnId[], message: ServerMessage): void {
    if (to.length > 0) out.push({ to, message });
  }

  private fail(out: Outbox, conn: ConnId, id: Re, err: unknown): void {
    const e = describeError(err);
    if (e.internal) this.log(`internal error: ${(err as Error).stack ?? String(err)}`);
    this.send(out, [conn], { type: 'error', ...re(id), code: e.code, message: e.message });
    // A room found changed in the store was reloaded: everyone there (the sender too) gets it as it now is.
    if (err instanceof StaleState) {
      const room = err.room;
      if (room.state.status === 'closed') this.send(out, [conn], { type: 'left', room: room.state.id });
      else this.broadcastRoom(out, room);
    }
  }

  private lobbyMessage(id?: Re): ServerMessage {
    const { rooms, more } = this.lobby.listing(LOBBY_MAX_ROOMS);
    return { type: 'lobby', ...re(id), rooms, more, online: this.lobby.online() };
  }

}

function unavailable(why: string): ServiceError {
  return new ServiceError('unavailable', `the room cannot be reached: ${why}; try again`);
}

function tooManyRooms(): ServiceError {
  return new ServiceError('too-many-rooms', `at most ${MAX_OPEN_ROOMS_PER_PLAYER} open rooms per player`);
}

/** What a room's view says of its finished match's rating, from the stored result. */
function outcomeOf(result: StoredResult | undefined): Room['outcome'] {
  return result === undefined ? null : { rated: result.rated, unrated: result.unrated };
}

function re(id: Re): { re?: string | number } {
  return id === undefined ? {} : { re: id };
}

/** A finished match's score: frames in snooker, the rules' scores otherwise. */
function scoresOf(s: RoomState): Record<string, number> {
  return s.kind === 'snooker' ? { ...(s.frames ?? {}) } : { ...(s.game?.scores ?? {}) };
}
