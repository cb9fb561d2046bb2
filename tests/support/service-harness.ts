// The game service in-process over a real database (a SQLite file in a temporary folder, or the
// PostgreSQL at `databaseUrl`), with a clock the test moves: connections are numbers, deliveries
// are collected per connection. Every step returns once the service has finished it.
import { join } from 'node:path';
import { GameService, type ConnId, type Delivery, type ServiceOptions } from '../../server/game/service.ts';
import { openStore, type AsyncStore } from '../../server/store/index.ts';
import { parseClientMessage, type ClientMessage, type ServerMessage } from '../../shared/protocol/index.ts';
import { ROOT, tempDir } from './server-process.ts';

export interface Harness {
  readonly service: GameService;
  readonly store: AsyncStore;
  /** The SQLite file ('' on PostgreSQL). */
  readonly dbPath: string;
  /** The PostgreSQL database's URL, when the harness runs on one. */
  readonly databaseUrl: string | undefined;
  /** Milliseconds since the epoch as the service sees them. */
  clock: number;
  /** A connection opens from an address (connections never opened count as address ''). */
  open(conn: ConnId, address: string): void;
  /** Sends a parsed message from a connection; resolves to what each connection got. */
  send(conn: ConnId, msg: ClientMessage): Promise<Map<ConnId, ServerMessage[]>>;
  /** Sends a raw frame through the parser first, as the WebSocket binding does. */
  sendText(conn: ConnId, text: string): Promise<Map<ConnId, ServerMessage[]>>;
  /** The service's timers, as the binding runs them (with what the rooms' timers sent through the outlet). */
  tick(): Promise<Map<ConnId, ServerMessage[]>>;
  /** A socket closes. */
  drop(conn: ConnId): Promise<Map<ConnId, ServerMessage[]>>;
  /** Every message a connection has received so far. */
  inbox(conn: ConnId): ServerMessage[];
  close(): Promise<void>;
}

export interface HarnessOptions {
  readonly seatHoldMs?: number;
  /** A SQLite file to open (another harness's, for a restart); a new one when absent. */
  readonly dbPath?: string;
  /** A PostgreSQL database instead of a SQLite file. */
  readonly databaseUrl?: string;
  readonly service?: Partial<ServiceOptions>;
}

export function byConn(deliveries: readonly Delivery[]): Map<ConnId, ServerMessage[]> {
  const out = new Map<ConnId, ServerMessage[]>();
  for (const d of deliveries) for (const c of d.to) out.set(c, [...(out.get(c) ?? []), d.message]);
  return out;
}

export async function openHarness(options: HarnessOptions = {}): Promise<Harness> {
  const dbPath = options.databaseUrl !== undefined ? '' : (options.dbPath ?? join(tempDir('baize-service-'), 'baize.db'));
  let clock = 1_800_000_000_000;
  const now = () => clock;
  const { store } = await openStore({ dbPath, migrationsDir: join(ROOT, 'migrations'), databaseUrl: options.databaseUrl }, now);
  const inboxes = new Map<ConnId, ServerMessage[]>();
  const put = (d: readonly Delivery[]) => {
    for (const [c, msgs] of byConn(d)) inboxes.set(c, [...(inboxes.get(c) ?? []), ...msgs]);
  };
  const record = (d: readonly Delivery[]) => {
    put(d);
    return byConn(d);
  };
  // What the service sends by itself (timers, the computer): in the inboxes at once, and in the
  // answer of the tick it happened in.
  let emitted: Delivery[] = [];
  const service = await GameService.start(store, { seatHoldMs: options.seatHoldMs ?? 60_000, now, log: () => {}, ...options.service });
  service.attach((d) => {
    put(d);
    emitted.push(...d);
  });
  const h: Harness = {
    get clock() {
      return clock;
    },
    set clock(t: number) {
      clock = t;
    },
    service,
    store,
    dbPath,
    databaseUrl: options.databaseUrl,
    open: (conn, address) => service.open(conn, address),
    send: async (conn, msg) => record(await service.handle(conn, msg)),
    sendText: async (conn, text) => {
      const p = parseClientMessage(text);
      return record(p.ok ? await service.handle(conn, p.message) : service.reject(conn, p.code, p.message, p.re));
    },
    tick: async () => {
      emitted = [];
      const own = await service.tick();
      put(own);
      return byConn([...emitted, ...own]);
    },
    drop: async (conn) => record(await service.close(conn)),
    inbox: (conn) => inboxes.get(conn) ?? [],
    close: () => store.close(),
  };
  return h;
}

/** The last message of a type a connection received. */
export function last<T extends ServerMessage['type']>(h: Harness, conn: ConnId, type: T): Extract<ServerMessage, { type: T }> {
  const m = h.inbox(conn).filter((x) => x.type === type).at(-1);
  if (!m) throw new Error(`connection ${conn} has no ${type} message`);
  return m as Extract<ServerMessage, { type: T }>;
}
