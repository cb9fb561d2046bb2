// The store's contract (tests/contract/store.contract.ts) on PostgreSQL: a real server started by
// the test (tests/support/postgres.ts), a fresh database for each test copied from one migrated
// template. Skips without PostgreSQL's binaries, unless BAIZE_REQUIRE_POSTGRES=1.
import { resolve } from 'node:path';
import pg from 'pg';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openStore, PostgresStore } from '../../server/store/index.ts';
import { storeContract, T0 } from '../contract/store.contract.ts';
import { postgresAvailable, startPostgres, type PostgresServer } from '../support/postgres.ts';

const MIGRATIONS = resolve(import.meta.dirname, '../../migrations');
const TEMPLATE = 'store_template';

describe.skipIf(!postgresAvailable())('the PostgreSQL store', () => {
  let server: PostgresServer;
  /** postgres://... without a database. */
  let base: string;
  let made = 0;

  async function admin<T>(fn: (c: pg.Client) => Promise<T>): Promise<T> {
    const c = new pg.Client({ connectionString: `${base}/postgres` });
    await c.connect();
    try {
      return await fn(c);
    } finally {
      await c.end();
    }
  }

  beforeAll(async () => {
    server = await startPostgres();
    base = server.url.slice(0, server.url.lastIndexOf('/'));
    const { store, applied } = await openStore({ dbPath: 'unused', migrationsDir: MIGRATIONS, databaseUrl: await server.database(TEMPLATE) });
    expect(store.engine).toBe('postgres');
    expect(applied).toHaveLength(10);
    await store.close();
  }, 60_000);
  afterAll(async () => {
    await server?.stop();
  });

  /** A new database copied from the migrated template; a copy waits for the template's last connection to go. */
  async function freshDatabase(): Promise<string> {
    const name = `store_${++made}`;
    await admin(async (c) => {
      for (let tries = 0; ; tries++) {
        try {
          await c.query(`CREATE DATABASE ${name} TEMPLATE ${TEMPLATE}`);
          return;
        } catch (err) {
          if ((err as { code?: string }).code !== '55006' || tries > 50) throw err; // object_in_use
          await new Promise((r) => setTimeout(r, 50));
        }
      }
    });
    return `${base}/${name}`;
  }

  storeContract(async () => {
    const url = await freshDatabase();
    const clock = { now: T0 };
    const { store, applied } = await openStore({ dbPath: 'unused', migrationsDir: MIGRATIONS, databaseUrl: url }, () => clock.now);
    if (!(store instanceof PostgresStore) || applied.length > 0) throw new Error('openStore with a URL must open the migrated PostgreSQL');
    const side = new pg.Client({ connectionString: url });
    await side.connect();
    return {
      store,
      clock,
      count: async (table) => Number((await side.query<{ n: string }>(`SELECT count(*) AS n FROM ${pg.escapeIdentifier(table)}`)).rows[0]!.n),
      setRating: async (player, kind, rating, rd) => {
        await side.query(
          `INSERT INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES ($1, $2, $3, $4, 0.06, 30, 15, 0)
           ON CONFLICT (kind, player_id) DO UPDATE SET rating = excluded.rating, rd = excluded.rd`,
          [kind, player, rating, rd],
        );
      },
      insertKeyless: async (name, tokenHash) =>
        Number((await side.query<{ id: string }>('INSERT INTO players (name, token_hash, created_at, last_seen) VALUES ($1, $2, $3, $3) RETURNING id', [name, tokenHash, clock.now])).rows[0]!.id),
      holdHealthLock: async () => {
        const other = new pg.Client({ connectionString: url });
        await other.connect();
        await other.query('BEGIN');
        await other.query('INSERT INTO health (id, checked_at) VALUES (1, 0) ON CONFLICT (id) DO UPDATE SET checked_at = 0');
        return async () => {
          await other.query('ROLLBACK');
          await other.end();
        };
      },
      close: async () => {
        await side.end();
        await store.close();
      },
    };
  });

  it('survives its connections killed, idle or mid-transaction: that write fails whole, the next goes through', async () => {
    const url = await freshDatabase();
    const name = url.slice(url.lastIndexOf('/') + 1);
    const { store } = await openStore({ dbPath: 'unused', migrationsDir: MIGRATIONS, databaseUrl: url });
    const other = new pg.Client({ connectionString: url });
    await other.connect();
    const errors: string[] = [];
    const log = console.error;
    console.error = (...args: unknown[]) => void errors.push(args.join(' '));
    try {
      const a = await store.createPlayer('Ann', Buffer.alloc(32, 1));
      // The store's transaction waits for a row lock that another connection holds; then it is killed.
      await other.query('BEGIN');
      await other.query('INSERT INTO health (id, checked_at) VALUES (1, 0)');
      // Its outcome caught at once: it fails while the test is still busy killing the connection.
      const probe = store.probeWrite(30_000).then(() => 'written', (err: unknown) => err);
      let pid: number | undefined;
      for (let i = 0; i < 200 && pid === undefined; i++) {
        const waiting = await admin((c) => c.query<{ pid: number }>("SELECT pid FROM pg_stat_activity WHERE datname = $1 AND wait_event_type = 'Lock'", [name]));
        pid = waiting.rows[0]?.pid;
        if (pid === undefined) await new Promise((r) => setTimeout(r, 25));
      }
      expect(pid).toBeDefined();
      await admin((c) => c.query('SELECT pg_terminate_backend($1)', [pid]));
      expect(await probe).toBeInstanceOf(Error);
      await other.query('ROLLBACK');
      await expect(store.probeWrite(1000)).resolves.toBeUndefined();
      // Every idle connection of the store killed: the pool opens new ones.
      await admin((c) => c.query('SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE datname = $1 AND pid <> $2', [name, (other as unknown as { processID: number }).processID]));
      await new Promise((r) => setTimeout(r, 100));
      expect(await store.playerById(a.id)).toEqual(a);
      await store.saveChanges();
    } finally {
      console.error = log;
      await other.end();
      await store.close();
    }
  });

  it('refuses to open a database newer than the build, and leaves no connection open', async () => {
    const url = await freshDatabase();
    const c = new pg.Client({ connectionString: url });
    await c.connect();
    await c.query('INSERT INTO schema_version (version, applied_at) VALUES (99, 0)');
    await c.end();
    await expect(openStore({ dbPath: 'unused', migrationsDir: MIGRATIONS, databaseUrl: url })).rejects.toThrow(/schema 99/);
    const left = await admin(async (a) => (await a.query<{ n: string }>('SELECT count(*) AS n FROM pg_stat_activity WHERE datname = $1', [url.slice(url.lastIndexOf('/') + 1)])).rows[0]!.n);
    expect(Number(left)).toBe(0);
  });
});
