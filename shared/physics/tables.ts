// Table and ball specifications, with the physical constants in use. Lengths in metres, masses in
// kilograms. The playing area is measured between the cushion noses; the origin is its centre,
// x along the long side, y across, z up (right-handed); headings from +x, counter-clockwise.
import type { ClothParams } from './cloth-motion.ts';
import type { CushionParams } from './cushion/index.ts';
import { buildOutline, type Cushion, type Pocket, type PocketShape } from './table-geometry.ts';

export type TableName = 'pool-9ft' | 'snooker-12ft' | 'carom-match';

/** Ball-cloth constants (Alciatore, "Pool and billiards physics resources", typical values). */
export interface ClothSpec {
  readonly muSlide: number;
  readonly muRoll: number;
  /** Deceleration of spin about the vertical (rad/s^2). */
  readonly spinDecel: number;
}

/** Ball-ball constants: restitution and the friction law μ(v) = a + b e^(-c v) (Alciatore A-14). */
export interface BallBallSpec {
  readonly restitution: number;
  readonly frictionA: number;
  readonly frictionB: number;
  readonly frictionC: number;
}

/** Ball-cushion constants for the Mathavan 2010 impact. */
export interface CushionSpec {
  /** Height of the cushion nose above the cloth (m), in (R, 2R). */
  readonly height: number;
  /** Work restitution e_e. */
  readonly restitution: number;
  /** Ball-cushion friction μ_w. */
  readonly friction: number;
  /**
   * Optional: how fast the restitution falls with the impact's normal speed v_n (per m/s). With
   * it, an impact's e_e is restitution - restitutionSlope * v_n, kept within [0, 1]: a real
   * cushion returns less of a hard impact's energy (Mathavan, Jackson and Parkin 2010 find their
   * rigid-cushion model valid below about 2.5 m/s normal speed). Absent (the default): e_e is
   * the constant restitution.
   */
  readonly restitutionSlope?: number;
}

export interface TableSpec {
  readonly name: TableName;
  /** Playing area along x, between cushion noses (m). */
  readonly length: number;
  /** Playing area along y, between cushion noses (m). */
  readonly width: number;
  readonly ballRadius: number;
  readonly ballMass: number;
  /** Height of the cushion nose above the cloth (m); the same as cushion.height. */
  readonly cushionHeight: number;
  readonly g: number;
  readonly cloth: ClothSpec;
  readonly ballBall: BallBallSpec;
  readonly cushion: CushionSpec;
  /** Pocket drop circles, with ids as the referees use them (BL, BR, ML, MR, TL, TR). */
  readonly pockets: readonly Pocket[];
  /** The cushion outline: rails, jaw noses, jaw faces. */
  readonly cushions: readonly Cushion[];
}

const G = 9.81;

// Alciatore's fit to measured ball-ball friction (technical proof A-14): μ(v) = 9.951e-3 + 0.108 e^(-1.088 v).
const PHENOLIC: BallBallSpec = { restitution: 0.95, frictionA: 9.951e-3, frictionB: 0.108, frictionC: 1.088 };
// Typical cloth (Alciatore, "Pool and billiards physics resources", physical properties: μ_slide
// 0.15-0.4, μ_roll 0.005-0.015, spin deceleration 5-15 rad/s^2): μ_slide 0.2, μ_roll 0.01, 10 rad/s^2.
const CLOTH: ClothSpec = { muSlide: 0.2, muRoll: 0.01, spinDecel: 10 };

// cos and sin of the jaw angles, written out because shared/ uses no Math.cos.
const COS_142 = -0.788010753606722;
const SIN_142 = 0.6156614753256583;
const COS_104 = -0.24192189559966773;
const SIN_104 = 0.9702957262759965;
const COS_135 = -0.7071067811865476;
const SIN_135 = 0.7071067811865476;
const COS_100 = -0.17364817766693033;
const SIN_100 = 0.984807753012208;

function table(
  base: Omit<TableSpec, 'pockets' | 'cushions' | 'cushionHeight'>,
  corner?: PocketShape,
  middle?: PocketShape,
): TableSpec {
  const outline = buildOutline(base.length, base.width, base.ballRadius, corner, middle);
  return Object.freeze({ ...base, cushionHeight: base.cushion.height, pockets: outline.pockets, cushions: outline.cushions });
}

// WPA equipment specifications, 9-ft table: playing surface 100 x 50 in (2.54 x 1.27 m); balls
// 2.25 in (57.15 mm), 5.5-6 oz (0.17 kg); cushion nose at 62.5-64.5% of the ball diameter; corner
// pocket mouth 4.5-4.625 in (116 mm used), side 5-5.125 in (128.5 mm used); mouth angles 142°
// (corner) and 104° (side). Nose radius and face length are not specified: 8 mm and 50/35 mm.
const POOL = table(
  {
    name: 'pool-9ft',
    length: 2.54,
    width: 1.27,
    ballRadius: 0.028575,
    ballMass: 0.17,
    g: G,
    cloth: CLOTH,
    ballBall: PHENOLIC,
    cushion: { height: 0.635 * 0.05715, restitution: 0.9, friction: 0.14 },
  },
  { mouth: 0.116, cosJaw: COS_142, sinJaw: SIN_142, noseRadius: 0.008, faceLength: 0.05 },
  { mouth: 0.1285, cosJaw: COS_104, sinJaw: SIN_104, noseRadius: 0.008, faceLength: 0.035 },
);

// WPBSA official table specification: playing area 3569 x 1778 mm; balls 52.5 mm (Mathavan et al.
// use 0.1406 kg); cushion nose at h = 7R/5 and e_e 0.98, μ_w 0.14 as in Mathavan et al. 2010.
// Pocket openings follow the WPBSA templates, about 88 mm at the corners and 106 mm in the
// middle, with rounded (curved) jaws; the radii and angles here approximate the templates.
const SNOOKER = table(
  {
    name: 'snooker-12ft',
    length: 3.569,
    width: 1.778,
    ballRadius: 0.02625,
    ballMass: 0.1406,
    g: G,
    cloth: { muSlide: 0.212, muRoll: 0.01, spinDecel: 10 },
    ballBall: PHENOLIC,
    cushion: { height: 0.02625 * 1.4, restitution: 0.98, friction: 0.14 },
  },
  { mouth: 0.088, cosJaw: COS_135, sinJaw: SIN_135, noseRadius: 0.03, faceLength: 0.06 },
  { mouth: 0.106, cosJaw: COS_100, sinJaw: SIN_100, noseRadius: 0.025, faceLength: 0.045 },
);

// UMB carom match table: playing area 2.84 x 1.42 m; balls 61-61.5 mm, 205-220 g; cushion nose
// 37 mm +/- 1 mm above the cloth; no pockets.
// The cloth, the cushion's friction and the ball-ball friction law fitted to 91 tracked
// three-cushion shots and tested on 91 others (npm run fidelity, docs/fidelity.md): a heated
// match cloth rolls and slides differently from pool cloth.
const CAROM = table({
  name: 'carom-match',
  length: 2.84,
  width: 1.42,
  ballRadius: 0.03075,
  ballMass: 0.21,
  g: G,
  cloth: { muSlide: 0.221, muRoll: 0.004958311163877231, spinDecel: 5.0575 },
  // Alciatore's friction law, 1.3 times.
  ballBall: { ...PHENOLIC, frictionA: 0.0129363, frictionB: 0.1404 },
  cushion: { height: 0.037, restitution: 0.93, friction: 0.240695 },
});

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

/**
 * The constants of a table's cushion impacts (cushionRebound's params): its ball, its cushion
 * nose, restitution and friction, and its cloth's sliding friction at the table contact. The
 * simulation uses these; the kernel's accuracy tests use them for "each table's constants".
 */
/** The parameters of motion on a table's cloth (cloth-motion.ts), built here once for every caller. */
export function clothParamsOf(table: TableSpec): ClothParams {
  return { R: table.ballRadius, g: table.g, muSlide: table.cloth.muSlide, muRoll: table.cloth.muRoll, spinDecel: table.cloth.spinDecel };
}

export function cushionParamsOf(table: TableSpec): CushionParams {
  return {
    M: table.ballMass,
    R: table.ballRadius,
    h: table.cushion.height,
    ee: table.cushion.restitution,
    muS: table.cloth.muSlide,
    muW: table.cushion.friction,
  };
}
