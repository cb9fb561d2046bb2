// The one entry point of the physics module: everything server, client, tests and benchmarks use.
export { tableSpec, isTableName, TABLE_NAMES } from './tables.ts';
export type { TableName, TableSpec } from './tables.ts';
