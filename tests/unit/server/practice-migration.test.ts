// SQLite's migration 007 of practice records: a player's best of a kind and type stays, the runs
// stay. (The store's practice seeds and records, on both databases: tests/contract/store.contract.ts.)
import Database from 'better-sqlite3';
import { copyFileSync } from 'node:fs';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { listMigrations, migrate } from '../../../server/migrate.ts';
import { ROOT, tempDir } from '../../support/server-process.ts';

const MIGRATIONS = join(ROOT, 'migrations');
const closers: (() => void)[] = [];
afterEach(() => closers.splice(0).forEach((c) => c()));

describe('practice records in SQLite', () => {
  it('from before this change keep each player\'s best of a kind and type when migrated; the runs stay', () => {
    const dir = tempDir('baize-migrations-');
    for (const m of listMigrations(MIGRATIONS).filter((m) => m.version <= 4)) copyFileSync(m.path, join(dir, m.file));
    const path = join(tempDir(), 'old.db');
    const db = new Database(path);
    closers.push(() => db.close());
    migrate(db, dir);
    db.prepare("INSERT INTO players (id, name, token_hash, created_at) VALUES (1, 'Ann', ?, 0), (2, 'Bob', ?, 0)").run(Buffer.alloc(32, 1), Buffer.alloc(32, 2));
    const runInsert = db.prepare("INSERT INTO practice_runs (id, player_id, kind, seed, shots, score, created_at) VALUES (?, ?, ?, 7, '[]', 0, 0)");
    const recInsert = db.prepare('INSERT INTO records (id, kind, what, player_id, value, better, practice_id, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, 0)');
    const rows: [number, string, string, number, number][] = [
      // id, kind, what, player, better
      [1, 'snooker', 'break', 1, 30],
      [2, 'snooker', 'break', 1, 91],
      [3, 'snooker', 'break', 1, 91],
      [4, 'snooker', 'break', 2, 12],
      [5, 'nineball', 'break-and-run', 1, -9],
      [6, 'nineball', 'break-and-run', 1, -6],
      [7, 'threecushion', 'run', 1, 4],
    ];
    for (const [id, kind, what, player, better] of rows) {
      runInsert.run(id, player, kind);
      recInsert.run(id, kind, what, player, Math.abs(better), better, id);
    }
    migrate(db, MIGRATIONS);
    expect(db.prepare('SELECT id FROM records ORDER BY id').all()).toEqual([2, 4, 6, 7].map((id) => ({ id })));
    expect((db.prepare('SELECT count(*) AS n FROM practice_runs').get() as { n: number }).n).toBe(rows.length);
    expect(() => recInsert.run(8, 'snooker', 'break', 2, 13, 13, 4)).toThrow(/UNIQUE/);
  });
});
