// The store's contract (tests/contract/store.contract.ts) on SQLite: a real file in a temporary
// folder, opened by openStore as the server opens it when BAIZE_DATABASE_URL is not set.
import Database from 'better-sqlite3';
import { rmSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { openStore, SqliteStore } from '../../../server/store/index.ts';
import { storeContract, T0 } from '../../contract/store.contract.ts';
import { ROOT, tempDir } from '../../support/server-process.ts';

const MIGRATIONS = join(ROOT, 'migrations');

describe('the SQLite store', () => {
  storeContract(async () => {
    const dir = tempDir('baize-store-');
    const clock = { now: T0 };
    const { store } = await openStore({ dbPath: join(dir, 'baize.db'), migrationsDir: MIGRATIONS }, () => clock.now);
    if (!(store instanceof SqliteStore)) throw new Error('openStore without a URL must open SQLite');
    const db = store.db;
    return {
      store,
      clock,
      count: async (table) => (db.prepare(`SELECT count(*) AS n FROM ${table}`).get() as { n: number }).n,
      setRating: async (player, kind, rating, rd) => {
        db.prepare('INSERT OR REPLACE INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES (?, ?, ?, ?, 0.06, 30, 15, 0)').run(kind, player, rating, rd);
      },
      insertKeyless: async (name, tokenHash) =>
        Number(db.prepare('INSERT INTO players (name, token_hash, created_at, last_seen) VALUES (?, ?, ?, ?)').run(name, tokenHash, clock.now, clock.now).lastInsertRowid),
      holdHealthLock: async () => {
        const other = new Database(join(dir, 'baize.db'));
        other.exec('BEGIN IMMEDIATE');
        return async () => {
          other.exec('ROLLBACK');
          other.close();
        };
      },
      close: async () => {
        await store.close();
        rmSync(dir, { recursive: true, force: true });
      },
    };
  });

  it('is what openStore opens without a database URL, migrated, the file made', async () => {
    const dir = tempDir('baize-store-');
    try {
      const { store, applied } = await openStore({ dbPath: join(dir, 'sub', 'baize.db'), migrationsDir: MIGRATIONS });
      expect(store.engine).toBe('sqlite');
      expect(applied).toHaveLength(await store.schemaVersion());
      await store.close();
      const again = await openStore({ dbPath: join(dir, 'sub', 'baize.db'), migrationsDir: MIGRATIONS, databaseUrl: undefined });
      expect(again.applied).toEqual([]);
      await again.store.close();
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});
