// Opens the store the configuration names: PostgreSQL for a postgres:// URL, else the SQLite file
// (the default). Either is migrated to the build's schema before it is handed out.
import { join } from 'node:path';
import { openDatabase } from '../database.ts';
import type { AsyncStore } from './contract.ts';
import { PostgresStore, type PostgresOptions } from './postgres.ts';
import { SqliteStore } from './sqlite.ts';

export interface StoreConfig {
  /** The SQLite file (or ':memory:'), used when there is no databaseUrl. */
  readonly dbPath: string;
  /** SQLite's migrations; PostgreSQL's are in its folder `postgres`. */
  readonly migrationsDir: string;
  /** postgres://... (BAIZE_DATABASE_URL): PostgreSQL instead of the file. */
  readonly databaseUrl?: string | undefined;
}

export interface OpenedStore {
  readonly store: AsyncStore;
  /** The migration files applied by this opening (none when the schema was already current). */
  readonly applied: readonly string[];
}

export async function openStore(config: StoreConfig, now: () => number = Date.now, options: PostgresOptions = {}): Promise<OpenedStore> {
  if (config.databaseUrl === undefined) {
    const { db, applied } = openDatabase(config.dbPath, config.migrationsDir);
    return { store: new SqliteStore(db, now), applied };
  }
  const store = new PostgresStore(config.databaseUrl, now, options);
  try {
    const applied = await store.migrate(join(config.migrationsDir, 'postgres'));
    // Rows from before the name keys get theirs, as the SQLite store does when it opens.
    await store.fillNameKeys();
    return { store, applied };
  } catch (err) {
    await store.close();
    throw err;
  }
}
