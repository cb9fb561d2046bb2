// The cushion impact: public entry points. The model is Mathavan, Jackson and Parkin (2010),
// "A theoretical analysis of billiard ball dynamics under cushion impacts", Proc. IMechE C
// 224(9):1863-1873; the method (an adaptive Runge-Kutta integration in the impulse with the
// paper's rolling conditions at zero slip) is described in docs/cushion.md.
import { EXPRESS_FROM, EXPRESS_HANDOVER, EXPRESS_IN, EXPRESS_OUT, expressImpact } from './cushion-express.ts';
import { CushionSolver } from './cushion-solver.ts';
import type { CushionTracePoint } from './cushion-solver.ts';
import type { CushionOptions, CushionOutcome, CushionParams, CushionState } from './cushion-types.ts';
import { CUSHION_TOLERANCES } from './cushion-types.ts';
import { MIN_TOLERANCE, resolveTolerance, throwInvalid, validateParams, validateState } from './cushion-validate.ts';

/** A plain, mutable copy of a state. */
export interface CushionStateOut {
  vx: number;
  vy: number;
  wx: number;
  wy: number;
  wz: number;
}

/** The rebound with how it ended and what it cost. */
export interface CushionImpact {
  readonly state: CushionStateOut;
  readonly outcome: CushionOutcome;
  /** Integration steps taken, accepted and rejected. */
  readonly steps: number;
  readonly rejectedSteps: number;
}

// One solver reused by every call (JavaScript runs one call at a time; nothing is allocated
// per step).
const solver = new CushionSolver();
/** A rebound slower than this fraction of e_e vy0 is solved again, at a finer tolerance. */
const SLOW_LEAVE = 0.1;
/** The finer tolerance is at least this fraction of the one asked for (it costs more steps). */
const SLOW_FLOOR = 1e-3;
/** Whether the last impact had vy > 0 (an impact at all). */
let impacted = false;
/**
 * expressImpact's code for the last impact: its series steps when it ended the impact, else 0
 * or minus the steps it took before the solver continued (0 also when it was not tried).
 */
let expressCode = 0;

/** Twice the kinetic and rotational energy per unit mass of a state (I = 2/5 M R²). */
function energyOf(vx: number, vy: number, wx: number, wy: number, wz: number, R: number): number {
  return vx * vx + vy * vy + 0.4 * R * R * (wx * wx + wy * wy + wz * wz);
}

/**
 * The result o as the ball leaves: not moving into the cushion, and with no more kinetic and
 * rotational energy than it brought (e0, energyOf the input).
 * - vy > 0 is set to 0: with e_e near 0 but not 0, restitution ends where the work has fallen
 *   by e_e² W_c, at the rounding of W_c, which can fall a hair before vy's zero (vy 1e-39 to
 *   1e-238 m/s on random draws with e_e below 1e-8; docs/cushion.md, Limits).
 * - The model only dissipates, but where it dissipates next to nothing (friction near 0, e_e
 *   near 1) the integration's error, inside the tolerance, can show as a gain: 3.0e-8 of the
 *   energy on a random draw with μs 8.5e-7, μw 0, e_e 1 - 1.6e-15 and h = 1.02 R, from both the
 *   express path and the solver. Such a result is scaled down to e0 (every component by the
 *   same factor, so zeros and symmetries stay), which moves it by about half the gain's
 *   fraction, far inside the tolerance.
 */
function leaving(o: CushionStateOut, e0: number, R: number): CushionStateOut {
  const vy = o.vy > 0 ? 0 : o.vy;
  const e = energyOf(o.vx, vy, o.wx, o.wy, o.wz, R);
  if (!(e > e0)) return vy === o.vy ? o : { vx: o.vx, vy, wx: o.wx, wy: o.wy, wz: o.wz };
  // (1 - 4 ε): the scaled energy then lies below e0 whatever the rounding of its sum.
  const k = Math.sqrt(e0 / e) * (1 - 4 * Number.EPSILON);
  return { vx: o.vx * k + 0, vy: vy * k + 0, wx: o.wx * k + 0, wy: o.wy * k + 0, wz: o.wz * k + 0 };
}

/** The express result (EXPRESS_OUT) as a plain state, the spins in rad/s. */
function expressResult(R: number): CushionStateOut {
  const y = EXPRESS_OUT;
  // + 0 turns -0 into 0.
  return { vx: y[0]! + 0, vy: y[1]! + 0, wx: y[2]! / R + 0, wy: y[3]! / R + 0, wz: y[4]! / R + 0 };
}

/**
 * The solver's part of an impact the express path did not end (n: expressImpact's code, 0 or
 * minus its steps): from the start, or from where the express path left.
 */
function solverFrom(
  n: number, vx: number, vy: number, wx: number, wy: number, wz: number,
  M: number, R: number, h: number, ee: number, muS: number, muW: number, tol: number,
): void {
  if (n < 0) {
    const at = EXPRESS_HANDOVER;
    solver.resume(vx, vy, M, R, h, ee, muS, muW, tol, EXPRESS_FROM, at.restitution, at.wEnd, at.p);
  } else {
    solver.solve(vx, vy, wx, wy, wz, M, R, h, ee, muS, muW, tol);
  }
}

/**
 * Checks the input and solves the impact: on the express path (unless `express` is false: the
 * solver only, for traces and tests), or by the solver from the start or from where the express
 * path left. Each field is read once and the checks are one expression, the messages built only
 * on failure (validateState and validateParams, the same checks in the same order). vy <= 0 is
 * no impact: a copy of the state. Records impacted and expressCode for cushionImpact.
 */
function impact(
  state: CushionState, params: CushionParams, options: CushionOptions | undefined, express: boolean,
): CushionStateOut {
  if (typeof state !== 'object' || state === null || typeof params !== 'object' || params === null) {
    validateState(state);
    validateParams(params);
  }
  const { vx, vy, wx, wy, wz } = state;
  const { M, R, h, ee, muS, muW } = params;
  // Every check of validateState and validateParams in one expression, written here rather than
  // called: numbers passed to a function that is not inlined are boxed (see EXPRESS_IN).
  const valid = Number.isFinite(vx) && Number.isFinite(vy) && Number.isFinite(wx) && Number.isFinite(wy) &&
    Number.isFinite(wz) && Number.isFinite(M) && Number.isFinite(R) && Number.isFinite(h) &&
    Number.isFinite(ee) && Number.isFinite(muS) && Number.isFinite(muW) &&
    M > 0 && R > 0 && h > R && h < 2 * R && ee >= 0 && ee <= 1 && muS >= 0 && muW >= 0;
  if (!valid) throwInvalid(vx, vy, wx, wy, wz, M, R, h, ee, muS, muW);
  const tol = options === undefined ? CUSHION_TOLERANCES.accurate : resolveTolerance(options);
  impacted = vy > 0;
  expressCode = 0;
  if (!impacted) return { vx, vy, wx, wy, wz };
  const input = EXPRESS_IN;
  input[0] = vx;
  input[1] = vy;
  input[2] = wx;
  input[3] = wy;
  input[4] = wz;
  input[5] = R;
  input[6] = h;
  input[7] = ee;
  input[8] = muS;
  input[9] = muW;
  input[10] = tol;
  input[11] = M;
  const out = solveInput(express);
  // A ball that leaves much slower than e_e vy0 after a long restitution: the end of
  // restitution, where the work meets its target, moves by dW / (c |vy|) for an error dW in the
  // work, and |vy| there is far below the vy0 that the work's error weight assumes (c vy0).
  // Solved again with the tolerance scaled by the shortfall (near the both-rolling threshold,
  // 0.4% of e_e vy0 left an error 14 times the tolerance; docs/cushion.md, Limits). On the grid
  // with four sets of constants and on random draws over the range every rebound is at
  // least 0.85 e_e vy0, so this never runs there. (e_e = 0: 0 / 0 or an infinity, not below.)
  const shortfall = -out.vy / (ee * vy);
  if (!(shortfall < SLOW_LEAVE) || (expressCode <= 0 && solver.outcome !== 'restitution')) return out;
  const fine = Math.max(tol * Math.max(shortfall, SLOW_FLOOR), MIN_TOLERANCE);
  if (!(fine < tol)) return out;
  input[10] = fine;
  if (solver.trace !== null) solver.trace.length = 0; // (cushionTrace: the second solve's history)
  return solveInput(express);
}

/**
 * One solve of the impact in EXPRESS_IN (vy > 0; the mass in EXPRESS_IN[11]): on the express
 * path (unless `express` is false), or by the solver from the start or from where the express
 * path left. Records expressCode.
 */
function solveInput(express: boolean): CushionStateOut {
  const n = express ? expressImpact() : 0;
  expressCode = n;
  const input = EXPRESS_IN;
  const vx = input[0]!;
  const vy = input[1]!;
  const wx = input[2]!;
  const wy = input[3]!;
  const wz = input[4]!;
  const R = input[5]!;
  const e0 = energyOf(vx, vy, wx, wy, wz, R);
  if (n > 0) return leaving(expressResult(R), e0, R);
  solverFrom(n, vx, vy, wx, wy, wz, input[11]!, R, input[6]!, input[7]!, input[8]!, input[9]!, input[10]!);
  return leaving(solver.result(), e0, R);
}

function run(
  state: CushionState, params: CushionParams, options: CushionOptions | undefined, express: boolean,
): CushionImpact {
  const out = impact(state, params, options, express);
  if (!impacted) return { state: out, outcome: 'no-impact', steps: 0, rejectedSteps: 0 };
  // (The steps of the solve that gave the result, when a slow rebound was solved again.)
  if (expressCode > 0) return { state: out, outcome: 'restitution', steps: expressCode, rejectedSteps: 0 };
  return { state: out, outcome: solver.outcome, steps: solver.steps - expressCode, rejectedSteps: solver.rejected };
}

/**
 * The ball's velocity and spin after it strikes a cushion, in the cushion frame (x along the
 * cushion, y into it, z up). `vy <= 0` is no impact: a copy of the state is returned.
 * Throws a RangeError naming the field for non-finite input, M or R <= 0, h outside (R, 2R),
 * e_e outside [0, 1], negative friction or a bad tolerance.
 */
export function cushionRebound(state: CushionState, params: CushionParams, options?: CushionOptions): CushionStateOut {
  // (Without run's record: one object per impact, this is called for every cushion hit.)
  return impact(state, params, options, true);
}

/** cushionRebound with its outcome and step counts. */
export function cushionImpact(state: CushionState, params: CushionParams, options?: CushionOptions): CushionImpact {
  return run(state, params, options, true);
}

/** cushionImpact without the express path: the Runge-Kutta solver alone (for checks). */
export function cushionImpactSolver(
  state: CushionState, params: CushionParams, options?: CushionOptions,
): CushionImpact {
  return run(state, params, options, false);
}

/**
 * cushionImpact with the impact's history sampled along the impulse (8 points per step, on the
 * integrator's continuous extension): for figures and checks, not for the simulation.
 */
export function cushionTrace(
  state: CushionState,
  params: CushionParams,
  options?: CushionOptions,
): CushionImpact & { readonly trace: readonly CushionTracePoint[] } {
  const trace: CushionTracePoint[] = [];
  solver.trace = trace;
  try {
    return { ...run(state, params, options, false), trace };
  } finally {
    solver.trace = null;
  }
}
