// Sampling an outcome at any time, for animation: each ball's path is a list of closed-form
// segments, and the state at t comes from the last segment that starts at or before t.
import type { BallSample, Motion } from './ball-state.ts';
import { emptySample, sampleAt, specificEnergy, type ClothParams } from './cloth-motion.ts';
import type { Outcome, PathSegment } from './sim-types.ts';
import { clothParamsOf, tableSpec, type TableSpec } from './tables.ts';

export interface BallAtTime extends BallSample {
  readonly id: string;
  readonly motion: Motion;
}

export function clothParams(tableName: string): ClothParams {
  return clothParamsOf(tableSpec(tableName));
}

/** The last segment with t0 <= t (binary search); the first one if t is before it. */
function segmentAt(segments: readonly PathSegment[], t: number): PathSegment {
  let lo = 0;
  let hi = segments.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (segments[mid]!.t0 <= t) lo = mid;
    else hi = mid - 1;
  }
  return segments[lo]!;
}

/**
 * Every ball's position, velocity and spin at time t (s) of the outcome; `table` when it was
 * simulated on constants of the caller's (simulateOn).
 */
export function sampleOutcome(outcome: Outcome, t: number, table?: TableSpec): BallAtTime[] {
  const p = table === undefined ? clothParams(outcome.table) : clothParamsOf(table);
  return outcome.paths.map((path) => {
    const s = segmentAt(path.segments, t);
    return { id: path.id, motion: s.t0 <= t ? s.motion : 'rest', ...sampleAt(s, Math.max(0, t - s.t0), p, emptySample()) };
  });
}

/** Total kinetic and rotational energy (J) of the balls still on the table at time t. */
export function energyAt(outcome: Outcome, t: number): number {
  const table = tableSpec(outcome.table);
  let e = 0;
  for (const b of sampleOutcome(outcome, t)) {
    if (b.motion !== 'pocketed') e += table.ballMass * specificEnergy(b, table.ballRadius);
  }
  return e;
}
