// The game service in-process over a real SQLite file in a temporary folder, with a clock the test
// moves: connections are numbers, deliveries are collected per connection.
import { join } from 'node:path';
import { openDatabase } from '../../server/database.ts';
import { GameService, type ConnId, type Delivery, type ServiceOptions } from '../../server/game/service.ts';
import { Store } from '../../server/store/index.ts';
import { parseClientMessage, type ClientMessage, type ServerMessage } from '../../shared/protocol/index.ts';
import { ROOT, tempDir } from './server-process.ts';

export interface Harness {
  readonly service: GameService;
  readonly store: Store;
  readonly dbPath: string;
  /** Milliseconds since the epoch as the service sees them. */
  clock: number;
  /** A connection opens from an address (connections never opened count as address ''). */
  open(conn: ConnId, address: string): void;
  /** Sends a parsed message from a connection; returns what each connection got. */
  send(conn: ConnId, msg: ClientMessage): Map<ConnId, ServerMessage[]>;
  /** Sends a raw frame through the parser first, as the WebSocket binding does. */
  sendText(conn: ConnId, text: string): Map<ConnId, ServerMessage[]>;
  /** The service's timers, as the binding runs them. */
  tick(): Map<ConnId, ServerMessage[]>;
  /** A socket closes. */
  drop(conn: ConnId): Map<ConnId, ServerMessage[]>;
  /** Every message a connection has received so far. */
  inbox(conn: ConnId): ServerMessage[];
  close(): void;
}

export function byConn(deliveries: readonly Delivery[]): Map<ConnId, ServerMessage[]> {
  const out = new Map<ConnId, ServerMessage[]>();
  for (const d of deliveries) for (const c of d.to) out.set(c, [...(out.get(c) ?? []), d.message]);
  return out;
}

export function openHarness(options: { seatHoldMs?: number; dbPath?: string; service?: Partial<ServiceOptions> } = {}): Harness {
  const dbPath = options.dbPath ?? join(tempDir('baize-service-'), 'baize.db');
  const { db } = openDatabase(dbPath, join(ROOT, 'migrations'));
  const store = new Store(db, () => h.clock);
  const inboxes = new Map<ConnId, ServerMessage[]>();
  const record = (d: readonly Delivery[]) => {
    const m = byConn(d);
    for (const [c, msgs] of m) inboxes.set(c, [...(inboxes.get(c) ?? []), ...msgs]);
    return m;
  };
  const h: Harness = {
    clock: 1_800_000_000_000,
    service: undefined as unknown as GameService,
    store,
    dbPath,
    open: (conn, address) => h.service.open(conn, address),
    send: (conn, msg) => record(h.service.handle(conn, msg)),
    sendText: (conn, text) => {
      const p = parseClientMessage(text);
      return record(p.ok ? h.service.handle(conn, p.message) : h.service.reject(conn, p.code, p.message, p.re));
    },
    tick: () => record(h.service.tick()),
    drop: (conn) => record(h.service.close(conn)),
    inbox: (conn) => inboxes.get(conn) ?? [],
    close: () => db.close(),
  };
  (h as { service: GameService }).service = new GameService(store, { seatHoldMs: options.seatHoldMs ?? 60_000, now: () => h.clock, log: () => {}, ...options.service });
  return h;
}

/** The last message of a type a connection received. */
export function last<T extends ServerMessage['type']>(h: Harness, conn: ConnId, type: T): Extract<ServerMessage, { type: T }> {
  const m = h.inbox(conn).filter((x) => x.type === type).at(-1);
  if (!m) throw new Error(`connection ${conn} has no ${type} message`);
  return m as Extract<ServerMessage, { type: T }>;
}
