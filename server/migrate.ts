// Schema migrations: migrations/NNN_name.sql applied in order, each in one transaction together
// with `PRAGMA user_version = NNN`, so the database file always carries the version it is at.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Database } from 'better-sqlite3';

const FILE_NAME = /^(\d{3})_[a-z0-9_]+\.sql$/;

export interface Migration {
  readonly version: number;
  readonly file: string;
  readonly path: string;
}

export class MigrationError extends Error {
  override readonly name = 'MigrationError';
  constructor(
    readonly file: string,
    readonly reason: string,
  ) {
    super(`migration ${file} failed: ${reason}`);
  }
}

/** The migration files of a folder, ordered by number; gaps, duplicates and stray names are errors. */
export function listMigrations(dir: string): Migration[] {
  const migrations: Migration[] = [];
  for (const file of readdirSync(dir).sort()) {
    if (!file.endsWith('.sql')) continue;
    const match = FILE_NAME.exec(file);
    if (!match) throw new MigrationError(file, 'name must look like NNN_name.sql (lower case, digits, _)');
    migrations.push({ version: Number(match[1]), file, path: join(dir, file) });
  }
  migrations.forEach((m, i) => {
    if (m.version !== i + 1) {
      throw new MigrationError(m.file, `expected number ${String(i + 1).padStart(3, '0')} (versions must run 001, 002, ... without gaps or repeats)`);
    }
  });
  return migrations;
}

/** The migrations newer than a database at version `current`; an error if it is newer than them all. */
export function pendingMigrations(migrations: readonly Migration[], current: number): Migration[] {
  if (current > migrations.length) {
    throw new MigrationError(
      `${String(current).padStart(3, '0')}_*.sql`,
      `the database is at schema ${current} but only ${migrations.length} migrations exist: is this build older than the database?`,
    );
  }
  return migrations.filter((m) => m.version > current);
}

export function schemaVersion(db: Database): number {
  return db.pragma('user_version', { simple: true }) as number;
}

/**
 * Applies every migration newer than the database's user_version. A failing migration rolls back
 * (its statements and its version bump alike) and throws a MigrationError naming the file.
 * Returns the files applied.
 */
export function migrate(db: Database, dir: string): string[] {
  const applied: string[] = [];
  for (const m of pendingMigrations(listMigrations(dir), schemaVersion(db))) {
    const sql = readFileSync(m.path, 'utf8');
    const apply = db.transaction(() => {
      db.exec(sql);
      // PRAGMA takes no bound parameters; the version is an integer we parsed ourselves.
      db.exec(`PRAGMA user_version = ${m.version}`);
    });
    try {
      apply();
    } catch (err) {
      throw new MigrationError(m.file, err instanceof Error ? err.message : String(err));
    }
    applied.push(m.file);
  }
  return applied;
}
