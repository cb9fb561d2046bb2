// Checks a scene and a shot before anything is simulated: every problem is a clear error that
// names it, and nothing has been computed when it is thrown.
import type { Scene, Shot, SimOptions } from './sim-types.ts';
import { CUSHION_TOLERANCES, type CushionParams } from './cushion/index.ts';
import { MISCUE_LIMIT, MiscueError } from './strike.ts';
import { inConvexPolygon, penetratedCushion } from './table-geometry.ts';
import { cushionParamsOf, tableSpec, type TableSpec } from './tables.ts';

/** Overlap between balls, or between a ball and a cushion, tolerated as touching (m). */
export const CONTACT_TOLERANCE = 1e-9;
/** The fastest shot accepted (m/s): a hard break is about 11 m/s. */
export const MAX_SPEED = 20;
export const MAX_BALLS = 64;

export class SimulationInputError extends RangeError {
  override readonly name = 'SimulationInputError';
}

function fail(message: string): never {
  throw new SimulationInputError(message);
}

function finite(value: unknown, what: string): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) fail(`${what} must be a finite number, got ${String(value)}`);
  return value;
}

export function validateScene(scene: Scene): TableSpec {
  if (typeof scene !== 'object' || scene === null) fail('scene must be an object { table, balls }');
  if (typeof scene.table !== 'string') fail('scene.table must be a table name');
  let table: TableSpec;
  try {
    table = tableSpec(scene.table);
  } catch (err) {
    fail(`scene.table: ${(err as Error).message}`);
  }
  const balls = scene.balls;
  if (!Array.isArray(balls) || balls.length === 0) fail('scene.balls must be a non-empty array');
  if (balls.length > MAX_BALLS) fail(`scene.balls has ${balls.length} balls, at most ${MAX_BALLS} are allowed`);
  const R = table.ballRadius;
  const hx = table.length / 2 - R + CONTACT_TOLERANCE;
  const hy = table.width / 2 - R + CONTACT_TOLERANCE;
  const seen = new Set<string>();
  balls.forEach((b, i) => {
    if (typeof b !== 'object' || b === null) fail(`scene.balls[${i}] must be an object { id, x, y }`);
    if (typeof b.id !== 'string' || b.id.length === 0 || b.id.length > 32) fail(`scene.balls[${i}].id must be a string of 1 to 32 characters`);
    if (seen.has(b.id)) fail(`duplicate ball id "${b.id}"`);
    seen.add(b.id);
    const x = finite(b.x, `ball "${b.id}" x`);
    const y = finite(b.y, `ball "${b.id}" y`);
    // Beyond the rectangle the rails leave, a centre may lie within a ball radius of it wherever it
    // touches no cushion (checked below: against a rounded jaw nose, where the simulation can
    // leave a ball), or further out in a pocket's mouth.
    const beyond = Math.max(Math.abs(x) - hx, Math.abs(y) - hy);
    if (beyond > R && !table.pockets.some((p) => inConvexPolygon(p.mouth, x, y))) {
      fail(`ball "${b.id}" at (${x}, ${y}) is off the table: its centre must lie within ${table.length / 2 - R} of the centre along x and ${table.width / 2 - R} along y, or in a pocket's mouth`);
    }
    const over = table.pockets.find((p) => (x - p.x) * (x - p.x) + (y - p.y) * (y - p.y) < p.r * p.r);
    if (over) fail(`ball "${b.id}" at (${x}, ${y}) is over pocket ${over.id}: it would drop`);
    const into = penetratedCushion(table.cushions, x, y, R, CONTACT_TOLERANCE);
    if (into) fail(`ball "${b.id}" at (${x}, ${y}) is off the table: it sinks into the cushion ${into.name}`);
  });
  const limit = 2 * R - CONTACT_TOLERANCE;
  for (let i = 0; i < balls.length; i++) {
    for (let j = i + 1; j < balls.length; j++) {
      const dx = balls[j]!.x - balls[i]!.x;
      const dy = balls[j]!.y - balls[i]!.y;
      const d = Math.sqrt(dx * dx + dy * dy);
      if (d < limit) fail(`balls "${balls[i]!.id}" and "${balls[j]!.id}" overlap by ${(2 * R - d).toExponential(3)} m (centres ${d} m apart, diameter ${2 * R} m)`);
    }
  }
  return table;
}

export function validateShot(scene: Scene, shot: Shot): void {
  if (typeof shot !== 'object' || shot === null) fail('shot must be an object { ball, heading, speed, side, top }');
  if (!scene.balls.some((b) => b.id === shot.ball)) fail(`shot.ball "${String(shot.ball)}" is not a ball of the scene`);
  const heading = finite(shot.heading, 'shot.heading');
  if (Math.abs(heading) > 1000) fail(`shot.heading must be an angle in radians within ±1000, got ${heading}`);
  const speed = finite(shot.speed, 'shot.speed');
  if (!(speed > 0) || speed > MAX_SPEED) fail(`shot.speed must be in (0, ${MAX_SPEED}] m/s, got ${speed}`);
  const side = finite(shot.side, 'shot.side');
  const top = finite(shot.top, 'shot.top');
  if (Math.sqrt(side * side + top * top) > MISCUE_LIMIT) {
    throw new MiscueError(`miscue: tip offset (side ${side}, top ${top}) is beyond ${MISCUE_LIMIT} R`);
  }
}

const CUSHION_KEYS = ['M', 'R', 'h', 'ee', 'muS', 'muW'] as const;

/** The table's cushion constants with the given overrides, checked as merged (h depends on R). */
function cushionParams(table: TableSpec, overrides: SimOptions['cushion']): CushionParams {
  const base = cushionParamsOf(table);
  if (overrides === undefined) return base;
  if (typeof overrides !== 'object' || overrides === null || Array.isArray(overrides)) {
    fail(`options.cushion must be an object of cushion constants { ${CUSHION_KEYS.join(', ')} }, got ${String(overrides)}`);
  }
  for (const key of Object.keys(overrides)) {
    if (!(CUSHION_KEYS as readonly string[]).includes(key)) fail(`options.cushion.${key} is not a cushion constant: use ${CUSHION_KEYS.join(', ')}`);
  }
  const merged = { ...base };
  // Field by field: a field set to undefined keeps the table's value, as a spread would not.
  for (const key of CUSHION_KEYS) {
    if (overrides[key] !== undefined) merged[key] = finite(overrides[key], `options.cushion.${key}`);
  }
  const { M, R, h, ee, muS, muW } = merged;
  if (!(M > 0)) fail(`options.cushion.M must be > 0 kg, got ${M}`);
  if (!(R > 0)) fail(`options.cushion.R must be > 0 m, got ${R}`);
  if (!(h > R && h < 2 * R)) {
    fail(`options.cushion.h must be in (R, 2R) = (${R}, ${2 * R}) m, got ${h}${overrides.h === undefined ? " (the table's)" : ''}`);
  }
  if (!(ee >= 0 && ee <= 1)) fail(`options.cushion.ee must be in [0, 1], got ${ee}`);
  if (!(muS >= 0)) fail(`options.cushion.muS must be >= 0, got ${muS}`);
  if (!(muW >= 0)) fail(`options.cushion.muW must be >= 0, got ${muW}`);
  return merged;
}

export function validateOptions(
  options: SimOptions | undefined, table: TableSpec,
): { rootTolerance: number; cushionTolerance: SimOptions['cushionTolerance']; cushionParams: CushionParams } {
  const rootTolerance = options?.rootTolerance ?? 1e-12;
  if (typeof rootTolerance !== 'number' || !(rootTolerance >= 1e-15 && rootTolerance <= 1e-3)) {
    fail(`options.rootTolerance must be in [1e-15, 1e-3] s, got ${String(rootTolerance)}`);
  }
  const cushionTolerance = options?.cushionTolerance ?? 'accurate';
  const named = typeof cushionTolerance === 'string' && Object.prototype.hasOwnProperty.call(CUSHION_TOLERANCES, cushionTolerance);
  const numeric = typeof cushionTolerance === 'number' && cushionTolerance >= 1e-12 && cushionTolerance <= 1e-2;
  if (!named && !numeric) {
    fail(`options.cushionTolerance must be one of ${Object.keys(CUSHION_TOLERANCES).join(', ')} or a number in [1e-12, 1e-2], got ${String(cushionTolerance)}`);
  }
  return { rootTolerance, cushionTolerance, cushionParams: cushionParams(table, options?.cushion) };
}
