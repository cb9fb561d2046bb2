// Opens the SQLite database: folder created, WAL journal, a busy timeout, migrations applied.
import Database from 'better-sqlite3';
import { mkdirSync } from 'node:fs';
import { dirname } from 'node:path';
import { migrate } from './migrate.ts';

export type { Database } from 'better-sqlite3';

/** How long a writer waits for a lock held by another connection before SQLITE_BUSY (ms). */
export const BUSY_TIMEOUT_MS = 5000;

export interface OpenedDatabase {
  readonly db: Database.Database;
  /** The migration files applied by this opening (none when the schema was already current). */
  readonly applied: readonly string[];
}

export function openDatabase(path: string, migrationsDir: string): OpenedDatabase {
  if (path !== ':memory:') mkdirSync(dirname(path), { recursive: true });
  const db = new Database(path);
  try {
    db.pragma('journal_mode = WAL');
    db.pragma(`busy_timeout = ${BUSY_TIMEOUT_MS}`);
    db.pragma('foreign_keys = ON');
    const applied = migrate(db, migrationsDir);
    return { db, applied };
  } catch (err) {
    db.close();
    throw err;
  }
}
