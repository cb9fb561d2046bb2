// Table and ball specifications. Lengths in metres, masses in kilograms.
// The playing area is measured between the cushion noses; the origin is its centre,
// x along the long side (see ../shared/physics.md, "Units and frames").

export type TableName = 'pool-9ft' | 'snooker-12ft' | 'carom-match';

export interface TableSpec {
  readonly name: TableName;
  /** Playing area along x, between cushion noses (m). */
  readonly length: number;
  /** Playing area along y, between cushion noses (m). */
  readonly width: number;
  readonly ballRadius: number;
  readonly ballMass: number;
  /** Height of the cushion nose above the cloth (m); must lie in (R, 2R). */
  readonly cushionHeight: number;
}

// WPA equipment specifications, 9-ft table: playing surface 100 x 50 in (2.54 x 1.27 m),
// balls 2.25 in (57.15 mm), 5.5-6 oz (about 0.17 kg); cushion nose at 63.5% of the ball diameter.
const POOL: TableSpec = {
  name: 'pool-9ft',
  length: 2.54,
  width: 1.27,
  ballRadius: 0.028575,
  ballMass: 0.17,
  cushionHeight: 0.635 * 0.05715,
};

// WPBSA official table specification: playing area 3569 x 1778 mm, balls 52.5 mm, about 142 g.
// Cushion nose height: Mathavan et al. 2010 use h = 7R/5 for snooker cushions.
const SNOOKER: TableSpec = {
  name: 'snooker-12ft',
  length: 3.569,
  width: 1.778,
  ballRadius: 0.02625,
  ballMass: 0.1406,
  cushionHeight: 0.02625 * 1.4,
};

// UMB carom match table: playing area 2.84 x 1.42 m, balls 61.0-61.5 mm, 205-220 g.
// Cushion nose height 37 mm (UMB: 37 mm +/- 1 mm).
const CAROM: TableSpec = {
  name: 'carom-match',
  length: 2.84,
  width: 1.42,
  ballRadius: 0.03075,
  ballMass: 0.21,
  cushionHeight: 0.037,
};

const TABLES: Readonly<Record<TableName, TableSpec>> = {
  'pool-9ft': POOL,
  'snooker-12ft': SNOOKER,
  'carom-match': CAROM,
};

export const TABLE_NAMES: readonly TableName[] = ['pool-9ft', 'snooker-12ft', 'carom-match'];

export function isTableName(name: unknown): name is TableName {
  return typeof name === 'string' && Object.prototype.hasOwnProperty.call(TABLES, name);
}

/** The specification of a named table; throws a RangeError for an unknown name. */
export function tableSpec(name: string): TableSpec {
  if (!isTableName(name)) {
    throw new RangeError(`unknown table "${name}": expected one of ${TABLE_NAMES.join(', ')}`);
  }
  return TABLES[name];
}
