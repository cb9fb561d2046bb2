// The step and event control of the cushion solver (solver.ts): its constants and step-size
// factors. docs/cushion.md, "Numerical hazards", gives the reason for each value.

/** Steps (accepted or rejected) after which the solver throws rather than answer wrongly. */
export const MAX_STEPS = 20000;
/** A falling slip below this fraction of the step tolerance counts as zero (a slip-zero event). */
export const EVENT_FRACTION = 0.1;
/** An initial slip below this fraction of the speed counts as exactly zero. */
export const ZERO_FRACTION = 1e-13;
/** Below this fraction of the speed a slipping contact uses its onset direction (the hint). */
export const HINT_FRACTION = 1e-14;
/**
 * Slaving (quasi-static slip): a slip below QS_RHO × speed whose direction is within δ of the
 * slaved one, with δ × slip <= QS_FRACTION × tolerance × speed, is slaved; a slaved slip that
 * grows past QS_EXIT × speed follows its own direction again, and one step carries a growing
 * slaved slip at most to QS_GROW × speed (slaving neglects O(slip²) terms the error estimate
 * cannot see). A slip up to QS_HOLD_RHO × speed whose rates are negligible is held.
 */
export const QS_RHO = 1e-3;
export const QS_FRACTION = 0.1;
export const QS_EXIT = 1e-5;
export const QS_GROW = 0.1;
export const QS_HOLD_RHO = 1e-1;
/** A cushion slip along ±y to within this fraction, shrinking, with the table contact rolling, is put on ±y. */
export const PIN_FRACTION = 1e-7;
/** Largest turn of a slip direction in one step (radians), predicted from its rate. */
export const TURN_MAX = 0.5;
/**
 * Largest step times a sliding slip's relaxation rate (7/2 μ N / |slip|): an explicit step much
 * longer oscillates about the slip's equilibrium direction, a wobble the error estimate can miss.
 */
export const RELAX_MAX = 2;
/** After a contact starts to roll, the step restarts at no less than this fraction of the last free step. */
export const RESTART_FRACTION = 0.5;
/** The error memory before any accepted step (an error of 1). */
export const FIRST_MEMORY = 1;

/**
 * The step after an accepted one of size `step` and error `err`, `prev` the previous accepted
 * error as errorMemory keeps it: PI control (Gustafsson), err^(-1/8) × prev^(1/16), with square
 * roots only; between 0.2 and 5 times the step.
 */
export function nextStep(step: number, err: number, prev: number): number {
  const f = err > 1e-30 ? prev / Math.sqrt(Math.sqrt(Math.sqrt(err))) : 1e6;
  return step * Math.min(5, Math.max(0.2, 0.9 * f));
}

/** What the step control remembers of an accepted error: its 16th root (floored at 1e-4). */
export function errorMemory(err: number): number {
  return Math.sqrt(Math.sqrt(Math.sqrt(Math.sqrt(err > 1e-4 ? err : 1e-4))));
}

/** err^(-3/16) with four square roots: the factor on a rejected step. */
export function invRoot(err: number): number {
  if (!(err > 1e-30)) return 1e6;
  const q = Math.sqrt(Math.sqrt(Math.sqrt(Math.sqrt(err))));
  return 1 / (q * q * q);
}

/**
 * The factor on the next step for slips closing on zero: a slip d0 from its predicted zero at a
 * step's start and d1 at its end (in impulse) is approached in steps of a fixed fraction of the
 * distance left, so the proposal is scaled by d1 / d0, the smaller of the two contacts', within
 * [0.2, 1]; otherwise the step aimed at the zero is rejected again and again.
 */
export function approachFactor(d0I: number, d1I: number, d0C: number, d1C: number): number {
  let f = 1;
  if (d1I < d0I) f = d1I / d0I;
  if (d1C < d0C && d1C / d0C < f) f = d1C / d0C;
  return f < 0.2 ? 0.2 : f;
}

/** Distance in impulse to the zero of a slip r changing along itself at rate; Infinity if it grows. */
export function zeroDistance(r: number, rate: number): number {
  return rate < 0 ? -r / rate : Infinity;
}

/**
 * Illinois regula falsi for a sign change of g on [lo, hi], g(lo) = flo > 0 >= g(hi) = fhi:
 * returns the bracket's end on the g <= 0 side, after at most 100 iterations or once
 * hi - lo <= rel |hi| + abs.
 */
export function illinois(g: (x: number) => number, lo: number, hi: number, flo: number, fhi: number, rel: number, abs: number): number {
  let side = 0;
  for (let i = 0; i < 100 && fhi !== 0 && hi - lo > rel * Math.abs(hi) + abs; i++) {
    let x = lo + (hi - lo) * (flo / (flo - fhi));
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    if (!(x > lo && x < hi)) break;
    const fx = g(x);
    if (fx > 0) {
      lo = x;
      flo = fx;
      if (side === 1) fhi *= 0.5;
      side = 1;
    } else {
      hi = x;
      fhi = fx;
      if (side === -1) flo *= 0.5;
      side = -1;
    }
  }
  return hi;
}
