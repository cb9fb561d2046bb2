// The store's entry point: the AsyncStore contract, its SQLite and PostgreSQL implementations,
// openStore to pick one, the synchronous SQLite Store (still the game service's), and the rows.
export type { AsyncStore } from './contract.ts';
export { Store } from './sqlite-sync.ts';
export { SqliteStore } from './sqlite.ts';
export * from './types.ts';
export { PostgresStore, type PostgresOptions } from './postgres.ts';
export { openStore, type OpenedStore, type StoreConfig } from './open.ts';
