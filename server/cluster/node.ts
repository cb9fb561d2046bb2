// One process's place in the cluster: its id, its heartbeat in the registry, the other processes
// it sees alive, the room leases it holds (renewed together), its sockets' presence, and the bus.
// The game service talks to the cluster only through `Peers`; `ClusterNode` is Peers over Redis.
import { randomBytes } from 'node:crypto';
import { RedisBus } from './bus.ts';
import { RedisChatLimit, type ChatLimit } from './chat-limit.ts';
import { RedisConnIds } from './conn-ids.ts';
import { requireId } from './keys.ts';
import { RedisRoomLeases } from './leases.ts';
import { connectRedis, type RedisClient } from './redis.ts';
import { RedisRegistry, type PresenceEntry } from './registry.ts';

export type { PresenceEntry } from './registry.ts';

/** What the game service needs of the other processes. */
export interface Peers {
  readonly self: string;
  /** A message for one process; false when no process heard it (it is gone). */
  send(to: string, body: unknown): Promise<boolean>;
  /** A message for every other process. */
  publish(body: unknown): void;
  onMessage(handler: (from: string, body: unknown) => void): void;
  /** Whether a process's heartbeat is recent (this process always is). */
  alive(proc: string): boolean;
  /** A process found dead: its sockets are gone and its rooms are free once their leases expire. */
  onDead(handler: (proc: string) => void): void;
  /** This process had been taken for dead (a stall) and is listed again: its presence must be told again. */
  onRevived(handler: () => void): void;
  /** Takes the room's lease (true when held, now renewed with the others). */
  acquire(roomId: string): Promise<boolean>;
  /** Gives a room up (closed, or the process stopping). */
  release(roomId: string): void;
  /** A lease that could not be renewed: another process may own the room now. */
  onLost(handler: (roomId: string) => void): void;
  ownerOf(roomId: string): Promise<string | null>;
  /** A socket here was welcomed as a player / closed. */
  joined(conn: number, player: { id: string; name: string }): void;
  left(conn: number): void;
  /** The welcomed sockets of the other live processes. */
  presence(): Promise<PresenceEntry[]>;
  /** The per-player chat allowance shared by every process. */
  readonly chat: ChatLimit;
  /** A connection id unique across processes, at once (undefined: none to hand, refuse the socket). */
  nextConnId(): number | undefined;
  close(): Promise<void>;
}

export interface ClusterTiming {
  /** Between heartbeats (ms). */
  readonly beatMs: number;
  /** A process silent this long is dead (ms). */
  readonly deadMs: number;
  /** A room lease's expiry (ms); renewed every third of it. */
  readonly leaseMs: number;
}

export const CLUSTER_TIMING: ClusterTiming = { beatMs: 1000, deadMs: 3000, leaseMs: 6000 };

function log(line: string): void {
  console.warn(`cluster: ${line}`);
}

export class ClusterNode implements Peers {
  private readonly handlers: ((from: string, body: unknown) => void)[] = [];
  private readonly deadHandlers: ((proc: string) => void)[] = [];
  private readonly revivedHandlers: (() => void)[] = [];
  private readonly lostHandlers: ((roomId: string) => void)[] = [];
  /** Processes seen alive at the last heartbeat. */
  private live = new Set<string>();
  /** Processes already reported dead (each is reported once). */
  private readonly buried = new Set<string>();
  private readonly owned = new Set<string>();
  private readonly timers: NodeJS.Timeout[] = [];
  private readonly registry: RedisRegistry;
  private readonly leases: RedisRoomLeases;
  readonly chat: ChatLimit;
  private beats = 0;
  private closed = false;

  private constructor(
    readonly self: string,
    private readonly client: RedisClient,
    private readonly bus: RedisBus,
    private readonly ids: RedisConnIds,
    private readonly timing: ClusterTiming,
  ) {
    this.registry = new RedisRegistry(client);
    this.leases = new RedisRoomLeases(client);
    this.chat = new RedisChatLimit(client);
    const dispatch = (m: { from: string; body: unknown }) => {
      if (m.from === this.self) return;
      // A process heard from is alive, even before the next heartbeat lists it.
      this.live.add(m.from);
      this.buried.delete(m.from);
      for (const h of this.handlers) h(m.from, m.body);
    };
    bus.onCommand(dispatch);
    bus.onDelivery(dispatch);
  }

  /** Joins the cluster at `url`: connected, subscribed, listed alive, with a block of connection ids. */
  static async start(url: string, options: { processId?: string; timing?: ClusterTiming } = {}): Promise<ClusterNode> {
    const self = requireId('processId', options.processId ?? `p${randomBytes(6).toString('base64url')}`);
    const client = await connectRedis(url, `redis ${self}`);
    try {
      const bus = await RedisBus.open(url, client, self);
      const ids = new RedisConnIds(client);
      await ids.ready();
      const node = new ClusterNode(self, client, bus, ids, options.timing ?? CLUSTER_TIMING);
      // A process restarted under its old name starts with no sockets listed.
      await node.registry.remove(self);
      await node.heartbeat();
      node.every(node.timing.beatMs, () => node.heartbeat());
      node.every(node.timing.leaseMs / 3, () => node.renew());
      return node;
    } catch (err) {
      client.destroy();
      throw err;
    }
  }

  private every(ms: number, run: () => Promise<void>): void {
    let busy = false;
    const t = setInterval(() => {
      if (busy || this.closed) return;
      busy = true;
      run()
        .catch((err: unknown) => log((err as Error).message))
        .finally(() => (busy = false));
    }, ms);
    t.unref();
    this.timers.push(t);
  }

  /** Lists this process alive, reads who else is, and buries the silent ones. */
  private async heartbeat(): Promise<void> {
    const now = Date.now();
    const known = await this.registry.beat(this.self, now);
    if (!known && this.beats++ > 0) for (const h of this.revivedHandlers) h();
    const procs = await this.registry.processes();
    const live = new Set<string>();
    for (const [proc, at] of procs) {
      if (proc === this.self || at >= now - this.timing.deadMs) {
        live.add(proc);
        this.buried.delete(proc);
        continue;
      }
      await this.registry.remove(proc);
      this.bury(proc);
    }
    // A process that left (or was removed by another survivor) is as gone as one found silent.
    for (const proc of this.live) if (!live.has(proc) && !procs.has(proc)) this.bury(proc);
    this.live = live;
  }

  private bury(proc: string): void {
    if (this.buried.has(proc)) return;
    this.buried.add(proc);
    for (const h of this.deadHandlers) h(proc);
  }

  private async renew(): Promise<void> {
    const rooms = [...this.owned];
    const held = await Promise.all(rooms.map((r) => this.leases.renew(r, this.self, this.timing.leaseMs).catch(() => true)));
    rooms.forEach((room, i) => {
      if (held[i] || !this.owned.delete(room)) return;
      for (const h of this.lostHandlers) h(room);
    });
  }

  async send(to: string, body: unknown): Promise<boolean> {
    return (await this.bus.command(to, body)) > 0;
  }

  publish(body: unknown): void {
    this.bus.deliver(body).catch((err: unknown) => log(`publish: ${(err as Error).message}`));
  }

  onMessage(handler: (from: string, body: unknown) => void): void {
    this.handlers.push(handler);
  }

  alive(proc: string): boolean {
    return proc === this.self || this.live.has(proc);
  }

  onDead(handler: (proc: string) => void): void {
    this.deadHandlers.push(handler);
  }

  onRevived(handler: () => void): void {
    this.revivedHandlers.push(handler);
  }

  async acquire(roomId: string): Promise<boolean> {
    const got = await this.leases.acquire(roomId, this.self, this.timing.leaseMs);
    if (got) this.owned.add(roomId);
    return got;
  }

  release(roomId: string): void {
    if (!this.owned.delete(roomId)) return;
    this.leases.release(roomId, this.self).catch((err: unknown) => log(`release ${roomId}: ${(err as Error).message}`));
  }

  onLost(handler: (roomId: string) => void): void {
    this.lostHandlers.push(handler);
  }

  ownerOf(roomId: string): Promise<string | null> {
    return this.leases.owner(roomId);
  }

  joined(conn: number, player: { id: string; name: string }): void {
    this.registry.joined(this.self, conn, player).catch((err: unknown) => log(`presence: ${(err as Error).message}`));
  }

  left(conn: number): void {
    this.registry.left(this.self, conn).catch((err: unknown) => log(`presence: ${(err as Error).message}`));
  }

  async presence(): Promise<PresenceEntry[]> {
    return this.registry.presence([...this.live].filter((p) => p !== this.self));
  }

  nextConnId(): number | undefined {
    return this.ids.take();
  }

  /** Leaves the cluster: leases given up (others take the rooms at once), sockets and entry removed. */
  async close(): Promise<void> {
    if (this.closed) return;
    this.closed = true;
    for (const t of this.timers) clearInterval(t);
    const rooms = [...this.owned];
    this.owned.clear();
    try {
      await Promise.all(rooms.map((r) => this.leases.release(r, this.self)));
      await this.registry.remove(this.self);
    } catch (err) {
      log(`leaving: ${(err as Error).message}`);
    }
    await this.bus.close();
    this.client.destroy();
  }
}
