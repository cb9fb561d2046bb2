// PostgreSQL's migrations (migrations/postgres) against a real server started by the test: they
// apply once, in order, from two processes at once; and they give the schema SQLite's give: the
// same tables, columns and indexes, and the same rules on what a row may hold.
import { copyFileSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import pg from 'pg';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openDatabase } from '../../server/database.ts';
import { migratePostgres, schemaVersionPostgres } from '../../server/migrate-postgres.ts';
import { postgresAvailable, startPostgres, type PostgresServer } from '../support/postgres.ts';

const SQLITE_MIGRATIONS = resolve(import.meta.dirname, '../../migrations');
const PG_MIGRATIONS = resolve(SQLITE_MIGRATIONS, 'postgres');
/** PostgreSQL's index for SQLite's `name ... UNIQUE COLLATE NOCASE` (an automatic index there). */
const PG_ONLY_INDEXES = ['players_name_nocase'];

describe.skipIf(!postgresAvailable())('PostgreSQL migrations', () => {
  let server: PostgresServer;
  beforeAll(async () => {
    server = await startPostgres();
  }, 60_000);
  afterAll(async () => {
    await server?.stop();
  });

  async function client(url: string): Promise<pg.Client> {
    const c = new pg.Client({ connectionString: url });
    await c.connect();
    return c;
  }

  it('apply once and in order, even from two connections at once', async () => {
    const url = await server.database('twice');
    const [a, b] = [await client(url), await client(url)];
    try {
      const [ra, rb] = await Promise.all([migratePostgres(a, PG_MIGRATIONS), migratePostgres(b, PG_MIGRATIONS)]);
      expect([...ra, ...rb]).toEqual(['001_players.sql', '002_rooms_matches.sql', '003_ratings_records.sql', '004_records_best.sql', '005_health.sql', '006_names.sql', '007_practice_seeds.sql', '008_ratings_board.sql', '009_name_graphemes.sql', '010_computer.sql']);
      expect(await migratePostgres(a, PG_MIGRATIONS)).toEqual([]);
      expect(await schemaVersionPostgres(b)).toBe(10);
    } finally {
      await a.end();
      await b.end();
    }
  });

  it('roll a failing migration back whole, and refuse a database newer than the build', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'baize-pg-migrations-'));
    copyFileSync(join(PG_MIGRATIONS, '001_players.sql'), join(dir, '001_players.sql'));
    writeFileSync(join(dir, '002_broken.sql'), 'CREATE TABLE half (id INTEGER);\nSELECT no_such_function();\n');
    const c = await client(await server.database('broken'));
    try {
      await expect(migratePostgres(c, dir)).rejects.toThrow(/002_broken.sql/);
      expect(await schemaVersionPostgres(c)).toBe(1);
      expect((await c.query("SELECT to_regclass('half') AS t")).rows[0].t).toBeNull();
      await migratePostgres(c, PG_MIGRATIONS);
      await expect(migratePostgres(c, dir)).rejects.toThrow(/schema 10 but only 2 migrations/);
    } finally {
      await c.end();
      rmSync(dir, { recursive: true, force: true });
    }
  });

  it('give the tables, columns and indexes of the SQLite schema', async () => {
    const c = await client(await server.database('schema'));
    const { db } = openDatabase(':memory:', SQLITE_MIGRATIONS);
    try {
      await migratePostgres(c, PG_MIGRATIONS);
      const sqliteTables = (db.prepare("SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%' ORDER BY name").all() as { name: string }[]).map((r) => r.name);
      const columns = new Map(sqliteTables.map((t) => [t, (db.prepare(`SELECT name FROM pragma_table_info(?) ORDER BY name`).all(t) as { name: string }[]).map((r) => r.name)]));
      const pgColumns = await c.query<{ table_name: string; column_name: string }>(
        "SELECT table_name, column_name FROM information_schema.columns WHERE table_schema = 'public' AND table_name <> 'schema_version' ORDER BY table_name, column_name",
      );
      const pgTables = [...new Set(pgColumns.rows.map((r) => r.table_name))];
      expect(pgTables).toEqual(sqliteTables);
      for (const t of sqliteTables) expect(pgColumns.rows.filter((r) => r.table_name === t).map((r) => r.column_name), t).toEqual(columns.get(t));
      // Indexes made by CREATE INDEX (SQLite's automatic ones for keys have no SQL).
      const sqliteIndexes = (db.prepare("SELECT name FROM sqlite_master WHERE type = 'index' AND sql IS NOT NULL ORDER BY name").all() as { name: string }[]).map((r) => r.name);
      const pgIndexes = await c.query<{ indexname: string }>(
        "SELECT indexname FROM pg_indexes WHERE schemaname = 'public' AND indexname NOT LIKE '%_pkey' AND indexname NOT LIKE '%_key' ORDER BY indexname",
      );
      expect(pgIndexes.rows.map((r) => r.indexname).filter((n) => !PG_ONLY_INDEXES.includes(n))).toEqual(sqliteIndexes);
    } finally {
      db.close();
      await c.end();
    }
  });

  it('refuse what SQLite refuses: a name taken in another case, a bad reason, a record of two sources', async () => {
    const c = await client(await server.database('rules'));
    const { db } = openDatabase(':memory:', SQLITE_MIGRATIONS);
    try {
      await migratePostgres(c, PG_MIGRATIONS);
      const hash = (n: number) => Buffer.alloc(32, n);
      const both = async (sqlite: () => unknown, postgres: () => Promise<unknown>): Promise<[boolean, boolean]> => {
        let s = true;
        try {
          sqlite();
        } catch {
          s = false;
        }
        let p = true;
        try {
          await postgres();
        } catch {
          p = false;
        }
        return [s, p];
      };
      const player = (id: number, name: string) =>
        both(
          () => db.prepare('INSERT INTO players (id, name, token_hash, created_at) VALUES (?, ?, ?, 0)').run(id, name, hash(id)),
          () => c.query('INSERT INTO players (id, name, token_hash, created_at) VALUES ($1, $2, $3, 0)', [id, name, hash(id)]),
        );
      expect(await player(1, 'Ann')).toEqual([true, true]);
      expect(await player(2, 'ANN')).toEqual([false, false]);
      expect(await player(3, 'x'.repeat(641))).toEqual([false, false]);
      expect(await player(4, 'Bo')).toEqual([true, true]);
      const room = both(
        () => db.prepare("INSERT INTO rooms VALUES ('r1', 'nineball', 1, 0, 0, 1, 0, 'playing', '{}', 0)").run(),
        () => c.query("INSERT INTO rooms VALUES ('r1', 'nineball', 1, 0, 0, 1, 0, 'playing', '{}', 0)"),
      );
      expect(await room).toEqual([true, true]);
      const match = both(
        () => db.prepare("INSERT INTO matches (id, room_id, kind, race_to, player1, player2, seed, started_at) VALUES (1, 'r1', 'nineball', 1, 1, 4, 7, 0)").run(),
        () => c.query("INSERT INTO matches (id, room_id, kind, race_to, player1, player2, seed, started_at) VALUES (1, 'r1', 'nineball', 1, 1, 4, 7, 0)"),
      );
      expect(await match).toEqual([true, true]);
      const result = (unrated: string) =>
        both(
          () => db.prepare("INSERT INTO results (match_id, winner, loser, how, scores, finished_at, rated, unrated) VALUES (1, 1, 4, 'won', '{}', 0, 0, ?)").run(unrated),
          () => c.query("INSERT INTO results (match_id, winner, loser, how, scores, finished_at, rated, unrated) VALUES (1, 1, 4, 'won', '{}', 0, 0, $1)", [unrated]),
        );
      expect(await result('bogus')).toEqual([false, false]);
      expect(await result('computer')).toEqual([true, true]);
      const record = both(
        () => db.prepare("INSERT INTO records (kind, what, player_id, value, better, match_id, practice_id, created_at) VALUES ('nineball', 'run', 1, 1, 1, NULL, NULL, 0)").run(),
        () => c.query("INSERT INTO records (kind, what, player_id, value, better, match_id, practice_id, created_at) VALUES ('nineball', 'run', 1, 1, 1, NULL, NULL, 0)"),
      );
      expect(await record).toEqual([false, false]);
    } finally {
      db.close();
      await c.end();
    }
  });
});
