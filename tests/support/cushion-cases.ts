// Impacts defined once, shared by the cushion tests, the benchmark and the figures.
import { cushionParamsOf, tableSpec } from '../../shared/physics/index.ts';
import { generator, PAPER, paperState } from '../../shared/scenes/index.ts';
import type { CushionParams, CushionState, TableName } from '../../shared/physics/index.ts';

export { PAPER, paperState } from '../../shared/scenes/index.ts';

/** Each table's own cushion-impact constants, as the simulation uses them (cushionParamsOf). */
export function tableParams(name: TableName): CushionParams {
  return cushionParamsOf(tableSpec(name));
}

/**
 * The constants the regression cases below the accuracy tests were found with, before the
 * tables carried cushion constants of their own: each table's ball and cushion nose with
 * ball-table friction 0.2, ball-cushion friction 0.14 and cushion restitution 0.85 (pool),
 * 0.98 (snooker), 0.9 (carom). A regression case only reproduces what it guards with these.
 */
export function legacyTableParams(name: TableName): CushionParams {
  const t = tableSpec(name);
  const ee = name === 'pool-9ft' ? 0.85 : name === 'snooker-12ft' ? 0.98 : 0.9;
  return { M: t.ballMass, R: t.ballRadius, h: t.cushionHeight, ee, muS: 0.2, muW: 0.14 };
}

export const TABLE_PARAMS: readonly (readonly [string, CushionParams])[] = [
  ['paper', PAPER],
  ['pool-9ft', tableParams('pool-9ft')],
  ['snooker-12ft', tableParams('snooker-12ft')],
  ['carom-match', tableParams('carom-match')],
];

export interface GridCase {
  readonly V0: number;
  readonly alpha: number;
  readonly kT: number;
  readonly kS: number;
  readonly state: CushionState;
}

export const BENCH_ANGLES = [0.5, 5, 15, 25, 35, 45, 55, 65, 75, 85, 89.5] as const;
export const BENCH_SPEEDS = [0.05, 0.5, 2, 5] as const;
export const BENCH_TOPSPINS = [-1, 0, 1, 2] as const;
export const BENCH_SIDESPINS = [-2, 0, 2] as const;

/**
 * The benchmark grid: 11 incidences × 4 speeds × 4 topspins × 3 sidespins = 528 impacts over
 * the range (V0 0.05-5 m/s, α 0.5-89.5°, k_T -1..2, k_S -2..2).
 */
export function benchGrid(R: number): GridCase[] {
  const out: GridCase[] = [];
  for (const alpha of BENCH_ANGLES) {
    for (const V0 of BENCH_SPEEDS) {
      for (const kT of BENCH_TOPSPINS) {
        for (const kS of BENCH_SIDESPINS) out.push({ V0, alpha, kT, kS, state: paperState(V0, alpha, kT, kS, R) });
      }
    }
  }
  return out;
}

/**
 * `count` impacts drawn uniformly over the range (V0 0.05-5 m/s, α 0.5-89.5°, k_T
 * -1..2, k_S -2..2) from `seed` (mulberry32, the same draws everywhere). The grid's spins are
 * a few round values; here they are anything in the range, so a slip can start anywhere near
 * zero (a ball with a little less than natural roll, whose table slip then passes zero during
 * the impact): the benchmark's second set, for what a typical impact costs.
 */
export function benchRandom(R: number, count = 528, seed = 2026): GridCase[] {
  return uniformDraws(R, count, seed, [-1, 2], 2);
}

/**
 * `count` balls rolling on the cloth into the cushion (natural roll, k_T = 1, the commonest
 * cushion hit in play: a ball struck on the cloth rolls within a metre or so), drawn from
 * `seed` with V0 0.05-5 m/s, α 0.5-89.5° and a little sidespin, k_S -0.5..0.5: the
 * benchmark's third set. From about 55° on, with little sidespin, the cushion slip passes
 * through or near zero in restitution.
 */
export function benchRolling(R: number, count = 528, seed = 2027): GridCase[] {
  return uniformDraws(R, count, seed, 1, 0.5);
}

/** Draws V0, α, then k_T (unless fixed) and k_S uniformly, in that order. */
function uniformDraws(
  R: number, count: number, seed: number, kT: number | readonly [number, number], kSMax: number,
): GridCase[] {
  const next = generator(seed);
  const out: GridCase[] = [];
  for (let i = 0; i < count; i++) {
    const V0 = 0.05 + 4.95 * next();
    const alpha = 0.5 + 89 * next();
    const t = typeof kT === 'number' ? kT : kT[0] + (kT[1] - kT[0]) * next();
    const kS = -kSMax + 2 * kSMax * next();
    out.push({ V0, alpha, kT: t, kS, state: paperState(V0, alpha, t, kS, R) });
  }
  return out;
}

/** Largest component difference (spins times R) as a fraction of V0. */
export function relError(
  a: { vx: number; vy: number; wx: number; wy: number; wz: number },
  b: { vx: number; vy: number; wx: number; wy: number; wz: number },
  R: number,
  V0: number,
): number {
  return Math.max(
    Math.abs(a.vx - b.vx),
    Math.abs(a.vy - b.vy),
    R * Math.abs(a.wx - b.wx),
    R * Math.abs(a.wy - b.wy),
    R * Math.abs(a.wz - b.wz),
  ) / V0;
}

/** Kinetic plus rotational energy (I = 2/5 M R²). */
export function energy(s: { vx: number; vy: number; wx: number; wy: number; wz: number }, M: number, R: number): number {
  return 0.5 * M * (s.vx * s.vx + s.vy * s.vy) + 0.2 * M * R * R * (s.wx * s.wx + s.wy * s.wy + s.wz * s.wz);
}
