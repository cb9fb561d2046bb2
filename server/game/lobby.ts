// The lobby and presence: which rooms exist, who is connected on which sockets, who watches the
// lobby. With several processes it is a mirror: the sockets of other processes are here too,
// each with its process, kept current by their events (docs/scale.md).
import type { LobbyRoom, PlayerRef } from '../../shared/protocol/index.ts';
import type { Room } from './room.ts';

export type ConnId = number;

export class Lobby {
  readonly rooms = new Map<string, Room>();
  /** The player of each welcomed socket. */
  private readonly players = new Map<ConnId, PlayerRef>();
  /** Each connected player's sockets. */
  private readonly sockets = new Map<string, Set<ConnId>>();
  /** When each player's last socket dropped (ms since the epoch); absent while connected. */
  private readonly droppedAt = new Map<string, number>();
  /** The process of each socket held by another process. */
  private readonly procs = new Map<ConnId, string>();
  /** Sockets that asked for the lobby list. */
  readonly subscribers = new Set<ConnId>();

  constructor(private readonly startedAt: number) {}

  playerOf(conn: ConnId): PlayerRef | undefined {
    return this.players.get(conn);
  }

  /** Binds a socket (another process's when `proc` is given) to a player; true when the player was not connected before. */
  attach(conn: ConnId, player: PlayerRef, proc?: string): boolean {
    this.players.set(conn, player);
    if (proc !== undefined) this.procs.set(conn, proc);
    let set = this.sockets.get(player.id);
    const first = set === undefined;
    if (!set) this.sockets.set(player.id, (set = new Set()));
    set.add(conn);
    this.droppedAt.delete(player.id);
    return first;
  }

  /** Forgets a socket; returns its player when that was the player's last socket. */
  detach(conn: ConnId, now: number): PlayerRef | undefined {
    this.subscribers.delete(conn);
    this.procs.delete(conn);
    const player = this.players.get(conn);
    if (!player) return undefined;
    this.players.delete(conn);
    const set = this.sockets.get(player.id);
    set?.delete(conn);
    if (set && set.size > 0) return undefined;
    this.sockets.delete(player.id);
    this.droppedAt.set(player.id, now);
    return player;
  }

  /** The process holding another process's socket; undefined for this process's own or unknown ones. */
  procOf(conn: ConnId): string | undefined {
    return this.procs.get(conn);
  }

  /** The sockets held by one other process. */
  connsOf(proc: string): ConnId[] {
    const out: ConnId[] = [];
    for (const [conn, p] of this.procs) if (p === proc) out.push(conn);
    return out;
  }

  connected(playerId: string): boolean {
    return this.sockets.has(playerId);
  }

  socketsOf(playerId: string): readonly ConnId[] {
    const set = this.sockets.get(playerId);
    return set ? [...set] : [];
  }

  /** When a disconnected player dropped: a player never seen since the start dropped at the start. */
  droppedSince(playerId: string): number | undefined {
    if (this.sockets.has(playerId)) return undefined;
    return this.droppedAt.get(playerId) ?? this.startedAt;
  }

  /** Who is connected, by name (the first hundred). */
  online(): PlayerRef[] {
    const out: PlayerRef[] = [];
    for (const conn of this.sockets.values()) {
      const p = this.players.get(conn.values().next().value as ConnId);
      if (p) out.push(p);
      if (out.length >= 100) break;
    }
    return out;
  }

  /** Renames a connected player on all their sockets. */
  rename(player: PlayerRef): void {
    for (const conn of this.sockets.get(player.id) ?? []) this.players.set(conn, player);
  }

  /**
   * The public rooms not yet over, at most `max` of them: the waiting ones first (a seat to take),
   * then the games in play, each oldest first; `more` counts the rest. A game both players have
   * left (paused) is not shown. Bounded so that thousands of rooms never make one huge message.
   */
  listing(max: number): { rooms: LobbyRoom[]; more: number } {
    const waiting: LobbyRoom[] = [];
    const playing: LobbyRoom[] = [];
    let total = 0;
    for (const room of this.rooms.values()) {
      const s = room.state;
      if (s.private || (s.status !== 'waiting' && s.status !== 'playing')) continue;
      if (s.status === 'playing' && s.seats.every((p) => !this.connected(p.id))) continue;
      total++;
      const list = s.status === 'waiting' ? waiting : playing;
      if (waiting.length + playing.length >= max) {
        if (list === playing || playing.length === 0) continue;
        playing.pop(); // a waiting room takes the place of the newest game in play
      }
      list.push({ id: s.id, kind: s.kind, raceTo: s.raceTo, players: s.seats.map((p) => ({ id: p.id, name: p.name })), spectators: room.spectators.size, status: s.status });
    }
    const rooms = [...waiting, ...playing];
    return { rooms, more: total - rooms.length };
  }
}
