import Database from 'better-sqlite3';
import { copyFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { fill } from '../../bench/store-fill.ts';
import { openDatabase } from '../../server/database.ts';
import { listMigrations, migrate, MigrationError, schemaVersion } from '../../server/migrate.ts';
import { ROOT, tempDir } from '../support/server-process.ts';

const MIGRATIONS = join(ROOT, 'migrations');
const LATEST = listMigrations(MIGRATIONS).length;

function tableNames(db: Database.Database): string[] {
  return (db.prepare("SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY name").all() as { name: string }[]).map((r) => r.name);
}

/** A migrations folder with the project's real files followed by the given extra ones. */
function migrationsWith(extra: Record<string, string>): string {
  const dir = tempDir('baize-migrations-');
  for (const m of listMigrations(MIGRATIONS)) copyFileSync(m.path, join(dir, m.file));
  for (const [name, sql] of Object.entries(extra)) writeFileSync(join(dir, name), sql);
  return dir;
}

describe('migrations', () => {
  it('apply in order on a fresh file, in WAL mode with a busy timeout', () => {
    const path = join(tempDir(), 'nested', 'fresh.db');
    const { db, applied } = openDatabase(path, MIGRATIONS);
    expect(applied).toEqual(listMigrations(MIGRATIONS).map((m) => m.file));
    expect(schemaVersion(db)).toBe(LATEST);
    expect(db.pragma('journal_mode', { simple: true })).toBe('wal');
    expect(db.pragma('busy_timeout', { simple: true })).toBeGreaterThan(0);
    expect(tableNames(db)).toContain('players');
    db.close();
  });

  it('create a players table that keeps names, hashed tokens and creation times', () => {
    const { db } = openDatabase(':memory:', MIGRATIONS);
    const insert = db.prepare('INSERT INTO players (name, token_hash, created_at) VALUES (?, ?, ?)');
    insert.run('ada', Buffer.alloc(32, 1), 1_700_000_000_000);
    expect(db.prepare('SELECT name, length(token_hash) AS n, created_at FROM players').get()).toEqual({ name: 'ada', n: 32, created_at: 1_700_000_000_000 });
    expect(() => insert.run('ADA', Buffer.alloc(32, 2), 1)).toThrow(/UNIQUE/); // names are unique regardless of case
    expect(() => insert.run('', Buffer.alloc(32, 3), 1)).toThrow(/CHECK/);
    expect(() => insert.run('bob', Buffer.alloc(16, 4), 1)).toThrow(/CHECK/); // not a SHA-256
    db.close();
  });

  it('apply nothing on a second opening', () => {
    const path = join(tempDir(), 'again.db');
    openDatabase(path, MIGRATIONS).db.close();
    const { db, applied } = openDatabase(path, MIGRATIONS);
    expect(applied).toEqual([]);
    expect(schemaVersion(db)).toBe(LATEST);
    db.close();
  });

  it('roll back a failing migration whole and name the file and the reason', () => {
    const dir = migrationsWith({
      [`${String(LATEST + 1).padStart(3, '0')}_broken.sql`]: 'CREATE TABLE half_done (id INTEGER);\nCREATE TABLE oops (;\n',
    });
    const path = join(tempDir(), 'broken.db');
    let error: unknown;
    try {
      openDatabase(path, dir);
    } catch (err) {
      error = err;
    }
    expect(error).toBeInstanceOf(MigrationError);
    expect((error as Error).message).toMatch(new RegExp(`${String(LATEST + 1).padStart(3, '0')}_broken\\.sql failed: .*syntax error`));
    // The good migrations before it stay; nothing of the broken one does.
    const db = new Database(path, { readonly: true });
    expect(schemaVersion(db)).toBe(LATEST);
    expect(tableNames(db)).not.toContain('half_done');
    db.close();
  });

  it('reject gaps, repeats and badly named files before applying anything', () => {
    const far = `${String(LATEST + 2).padStart(3, '0')}_far.sql`;
    const gap = migrationsWith({ [far]: 'SELECT 1;' });
    expect(() => listMigrations(gap)).toThrow(new RegExp(`${far.replace('.', '\\.')}.*expected number`));
    const badName = migrationsWith({ 'Add Things.sql': 'SELECT 1;' });
    expect(() => listMigrations(badName)).toThrow(/Add Things\.sql.*NNN_name\.sql/);
    const db = new Database(':memory:');
    expect(() => migrate(db, gap)).toThrow(MigrationError);
    expect(schemaVersion(db)).toBe(0);
    db.close();
  });

  it('refuse a database newer than the migrations it knows', () => {
    const db = new Database(':memory:');
    db.pragma(`user_version = ${LATEST + 5}`);
    expect(() => migrate(db, MIGRATIONS)).toThrow(/schema \d+ but only \d+ migrations exist/);
    db.close();
  });

  it('009 rebuilds players for names of 32 emoji, keeping every row and every reference to it', () => {
    // A database at 008 with players, rooms, matches and ratings, then 009 on it.
    const before8 = tempDir('baize-migrations-');
    for (const m of listMigrations(MIGRATIONS).filter((m) => m.version <= 8)) copyFileSync(m.path, join(before8, m.file));
    const path = join(tempDir(), 'at8.db');
    const at8 = openDatabase(path, before8).db;
    fill(at8, { players: 12, matches: 40, seed: 5 });
    const rows = (db: Database.Database) => db.prepare('SELECT * FROM players ORDER BY id').all();
    const count = (db: Database.Database, t: string) => (db.prepare(`SELECT count(*) AS n FROM ${t}`).get() as { n: number }).n;
    const players = rows(at8);
    const refs = ['rooms', 'results', 'ratings'].map((t) => count(at8, t));
    at8.close();
    const { db, applied } = openDatabase(path, MIGRATIONS);
    expect(applied).toContain('009_name_graphemes.sql');
    expect(rows(db)).toEqual(players);
    expect(['rooms', 'results', 'ratings'].map((t) => count(db, t))).toEqual(refs);
    expect(db.pragma('foreign_key_check')).toEqual([]);
    const insert = db.prepare('INSERT INTO players (name, token_hash, created_at) VALUES (?, ?, 1)');
    const family = '\u{1F468}\u200D\u{1F469}\u200D\u{1F467}\u200D\u{1F466}';
    insert.run(family.repeat(32), Buffer.alloc(32, 7)); // 224 code points
    expect(() => insert.run('', Buffer.alloc(32, 8))).toThrow(/CHECK/);
    expect(() => db.prepare('DELETE FROM players WHERE id = ?').run((players[0] as { id: number }).id)).toThrow(/FOREIGN KEY/);
    db.close();
  });
});
