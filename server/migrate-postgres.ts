// PostgreSQL's schema migrations: migrations/postgres/NNN_name.sql, numbered as SQLite's
// (migrate.ts lists both alike), each applied in one transaction together with its row in
// schema_version. An advisory lock makes processes that start together migrate one at a time.
import { readFileSync } from 'node:fs';
import type { ClientBase } from 'pg';
import { listMigrations, MigrationError, pendingMigrations } from './migrate.ts';

/** The advisory lock's key: any constant of the application's own ("baize" in ASCII). */
const LOCK_KEY = 0x6261697a65;

/** The database's schema version: 0 before the first migration. */
export async function schemaVersionPostgres(client: ClientBase): Promise<number> {
  const present = await client.query<{ t: string | null }>("SELECT to_regclass('schema_version') AS t");
  if (present.rows[0]?.t === null) return 0;
  const r = await client.query<{ v: number | null }>('SELECT max(version) AS v FROM schema_version');
  return r.rows[0]?.v ?? 0;
}

/**
 * Applies every migration newer than the database's version. A failing migration rolls back
 * (its statements and its version row alike) and throws a MigrationError naming the file.
 * Returns the files applied.
 */
export async function migratePostgres(client: ClientBase, dir: string): Promise<string[]> {
  const migrations = listMigrations(dir);
  await client.query('SELECT pg_advisory_lock($1)', [LOCK_KEY]);
  try {
    await client.query('CREATE TABLE IF NOT EXISTS schema_version (version INTEGER PRIMARY KEY, applied_at BIGINT NOT NULL)');
    const applied: string[] = [];
    for (const m of pendingMigrations(migrations, await schemaVersionPostgres(client))) {
      const sql = readFileSync(m.path, 'utf8');
      try {
        await client.query('BEGIN');
        await client.query(sql);
        await client.query('INSERT INTO schema_version (version, applied_at) VALUES ($1, $2)', [m.version, Date.now()]);
        await client.query('COMMIT');
      } catch (err) {
        await client.query('ROLLBACK');
        throw new MigrationError(m.file, err instanceof Error ? err.message : String(err));
      }
      applied.push(m.file);
    }
    return applied;
  } finally {
    await client.query('SELECT pg_advisory_unlock($1)', [LOCK_KEY]);
  }
}
