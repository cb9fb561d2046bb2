// The cushion impact: the public entry. The model is Mathavan, Jackson and Parkin (2010),
// "A theoretical analysis of billiard ball dynamics under cushion impacts", Proc. IMechE C
// 224(9):1863-1873 (doi 10.1243/09544062JMES1964); the method is in docs/cushion.md.
import { CushionSolver } from './solver.ts';
import type { CushionTracePoint } from './solver.ts';
import type { CushionOptions, CushionOutcome, CushionParams, CushionState } from './types.ts';
import { MIN_TOLERANCE, resolveTolerance, validateParams, validateState } from './validate.ts';

export type { CushionTracePoint } from './solver.ts';
export { CUSHION_TOLERANCES } from './types.ts';
export type { CushionOptions, CushionOutcome, CushionParams, CushionState, CushionToleranceName } from './types.ts';

/** A plain, mutable copy of a state. */
export type CushionStateOut = { -readonly [K in keyof CushionState]: number };

/** The rebound with how it ended and what it cost. */
export interface CushionImpact {
  readonly state: CushionStateOut;
  /** The solver's result before the energy guard (`leaving`): what the energy tests check. */
  readonly unguarded: CushionStateOut;
  readonly outcome: CushionOutcome;
  /** Integration steps taken, accepted and rejected. */
  readonly steps: number;
  readonly rejectedSteps: number;
}

/** A rebound slower than this fraction of e_e vy0 is solved again at a finer tolerance. */
const SLOW_LEAVE = 0.1;
/** The finer tolerance is at least this fraction of the one asked for. */
const SLOW_FLOOR = 1e-3;

/** Twice the kinetic and rotational energy per unit mass (I = 2/5 M R²). */
function energyOf(o: CushionState, R: number): number {
  return o.vx * o.vx + o.vy * o.vy + 0.4 * R * R * (o.wx * o.wx + o.wy * o.wy + o.wz * o.wz);
}

/**
 * The result as the ball leaves: not moving into the cushion, and with no more energy than it
 * brought with state s. vy > 0 is set to 0 (with e_e near 0, restitution can end a hair before
 * vy's zero). Where the model dissipates next to nothing (friction near 0, e_e near 1) the
 * integration's error, inside the tolerance, can show as a gain: such a result is brought back
 * to the energy it came with, by factors common to every component, so zeros and mirror
 * symmetry stay.
 */
function leaving(o: CushionStateOut, s: CushionState, R: number): CushionStateOut {
  if (o.vy > 0) o.vy = 0;
  const e0 = energyOf(s, R);
  if (!(energyOf(o, R) > e0)) return o;
  // First the change s -> o is scaled by k, the nonzero root of energy(s + k Δ) = e0, a hair
  // inside: what the impact did not change stays exactly as it was (frictionless: vx, spins).
  const d = { vx: o.vx - s.vx, vy: o.vy - s.vy, wx: o.wx - s.wx, wy: o.wy - s.wy, wz: o.wz - s.wz };
  const a = energyOf(d, R);
  const b = d.vx * s.vx + d.vy * s.vy + 0.4 * R * R * (d.wx * s.wx + d.wy * s.wy + d.wz * s.wz);
  const kd = (-2 * b / a) * (1 - 4 * Number.EPSILON);
  const t = { vx: s.vx + kd * d.vx, vy: s.vy + kd * d.vy, wx: s.wx + kd * d.wx, wy: s.wy + kd * d.wy, wz: s.wz + kd * d.wz };
  if (kd > 0 && kd < 1 && !(energyOf(t, R) > e0)) o = t;
  const e = energyOf(o, R);
  if (!(e > e0)) return o;
  // (1 - 4 ε): the scaled energy then lies below e0 whatever the rounding of its sum.
  const k = Math.sqrt(e0 / e) * (1 - 4 * Number.EPSILON);
  return { vx: o.vx * k + 0, vy: o.vy * k + 0, wx: o.wx * k + 0, wy: o.wy * k + 0, wz: o.wz * k + 0 };
}

/** Checks the input, solves the impact with `solver` and reports how it ended. */
function run(
  solver: CushionSolver, state: CushionState, params: CushionParams, options: CushionOptions | undefined,
  trace: CushionTracePoint[] | null,
): CushionImpact {
  validateState(state);
  validateParams(params);
  const tol = resolveTolerance(options);
  const { vx, vy, wx, wy, wz } = state;
  if (!(vy > 0)) {
    return { state: { vx, vy, wx, wy, wz }, unguarded: { vx, vy, wx, wy, wz }, outcome: 'no-impact', steps: 0, rejectedSteps: 0 };
  }
  const { M, R, h, ee, muS, muW } = params;
  solver.trace = trace;
  solver.solve(vx, vy, wx, wy, wz, M, R, h, ee, muS, muW, tol);
  // A ball that leaves much slower than e_e vy0 after a long restitution: the end, where the work
  // meets its target, moves by dW / (c |vy|) for an error dW in the work, and |vy| there is far
  // below the vy0 the work's error weight assumes. Solved again with the tolerance scaled by the
  // shortfall (docs/cushion.md, Limits). (e_e = 0: 0 / 0 or an infinity, not below.)
  const shortfall = -solver.y[1]! / (ee * vy);
  if (shortfall < SLOW_LEAVE && solver.outcome === 'restitution') {
    const fine = Math.max(tol * Math.max(shortfall, SLOW_FLOOR), MIN_TOLERANCE);
    if (fine < tol) {
      if (trace !== null) trace.length = 0;
      solver.solve(vx, vy, wx, wy, wz, M, R, h, ee, muS, muW, fine);
    }
  }
  return {
    state: leaving(solver.result(), state, R),
    unguarded: solver.result(),
    outcome: solver.outcome,
    steps: solver.steps,
    rejectedSteps: solver.rejected,
  };
}

/**
 * The ball's velocity and spin after it strikes a cushion, in the cushion frame (x along the
 * cushion, y into it, z up). `vy <= 0` is no impact: a copy of the state is returned.
 * Throws a RangeError naming the field for non-finite input, M or R <= 0, h outside (R, 2R),
 * e_e outside [0, 1], negative friction or a bad tolerance.
 */
export function cushionRebound(state: CushionState, params: CushionParams, options?: CushionOptions): CushionStateOut {
  return run(new CushionSolver(), state, params, options, null).state;
}

/** cushionRebound with a solver kept for many impacts (the simulation keeps one per shot). */
export class CushionKernel {
  private readonly solver = new CushionSolver();

  rebound(state: CushionState, params: CushionParams, options?: CushionOptions): CushionStateOut {
    return run(this.solver, state, params, options, null).state;
  }
}

/** cushionRebound with its outcome and step counts (diagnostics). */
export function cushionImpact(state: CushionState, params: CushionParams, options?: CushionOptions): CushionImpact {
  return run(new CushionSolver(), state, params, options, null);
}

/**
 * cushionImpact with the impact's history along the impulse, 8 points per step on the
 * integrator's continuous extension: the same solve, recorded (Fig. 12, the lab).
 */
export function cushionTrace(
  state: CushionState, params: CushionParams, options?: CushionOptions,
): CushionImpact & { readonly trace: readonly CushionTracePoint[] } {
  const trace: CushionTracePoint[] = [];
  return { ...run(new CushionSolver(), state, params, options, trace), trace };
}
