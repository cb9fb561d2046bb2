// The constants of the cushion solver's step and event control, and its step-size factors,
// shared by the general solver (cushion-solver.ts) and its scalar fast path (cushion-fast.ts)
// so that both control their steps alike. docs/cushion.md explains each choice.

/** Steps (accepted or rejected) after which the solver gives up with an Error. */
export const MAX_STEPS = 20000;
/**
 * A falling slip below this fraction of the step tolerance counts as zero (slip-zero event).
 * Declaring a slip zero early by e changes the result by O(e): the true solution would slide
 * on for dp = e / |rate|, with a friction that differs from the rolling one by O(|rate|).
 */
export const EVENT_FRACTION = 0.1;
/** An initial slip below this fraction of the speed counts as exactly zero. */
export const ZERO_FRACTION = 1e-13;
/** Slip below this fraction of the speed: a slipping contact uses its onset direction. */
export const HINT_FRACTION = 1e-14;
/**
 * Quasi-static slip (see CushionModel.qsI). A slip below QS_RHO × speed whose direction u is
 * within δ of the slaved direction u*, with δ × slip <= QS_FRACTION × tolerance × speed, is
 * slaved from then on (the neglected part of its motion is O(δ × slip)); a slaved slip that
 * grows beyond QS_EXIT × speed follows its own direction again. Slaving is exact only while
 * the slaved direction turns slowly against the slip's relaxation time (slip / (7/2 μ N)),
 * which shrinks with the slip: at 1e-2 a carom impact's cushion slip was slaved at 8e-3 V0 and
 * its direction drifted from the slaved one over the long steps that followed (4.3e-5 V0 off
 * at the default); 1e-3 changes nothing else on the test sets.
 */
export const QS_RHO = 1e-3;
/**
 * A sliding slip up to this fraction of the speed whose rates are negligible (it would change
 * by less than the event tolerance over an impulse of V) is held in its direction
 * (CushionModel.frozenI): it stays put, and integrating its stiff direction would take steps of
 * a fraction of it, without end.
 */
export const QS_HOLD_RHO = 1e-1;
export const QS_FRACTION = 0.1;
export const QS_EXIT = 1e-5;
/**
 * A slaved slip that grows is not carried beyond QS_GROW × speed by one step: slaving
 * neglects O(slip²) terms that the step's error estimate cannot see. Without this bound a first
 * step twice as long (0.5 vy/c) left 1.6e-5 V0 errors on natural-roll impacts; with it 4e-6.
 */
export const QS_GROW = 0.1;
/**
 * With the table contact rolling, a cushion slip whose x part is at most this fraction of its y
 * part, and shrinking, is put exactly on ±y (CushionSolver.run): there it stays, and its
 * relaxation no longer bounds the steps.
 */
export const PIN_FRACTION = 1e-7;
/** Largest turn of a slip direction in one step (radians), predicted from its rate. */
export const TURN_MAX = 0.5;
/**
 * Largest step, times a sliding slip's relaxation rate. Near its equilibrium direction a small
 * slip turns back toward it at about k / |slip| per unit impulse (k = 7/2 μw at I, 7/2 μs × the
 * table's normal at C: the friction's weight in the slip's own rates); an explicit step longer
 * than about 3.3 / that rate oscillates about it instead (the Dormand-Prince pair's stability
 * limit on the real axis), and the error estimate, seeing a bounded wobble, may let it. Found on
 * a pool impact whose cushion slip left a stuck spell slowly: 1.1e-5 V0 wrong at 1e-6 without
 * this bound.
 */
export const RELAX_MAX = 2;

/**
 * The step after an accepted one of size `step` and error `err`, with `prev` the previous
 * accepted error as errorMemory keeps it: PI control (Gustafsson), err^(-1/8) × prev^(1/16),
 * roughly the usual err^(-0.7/5) × prev^(0.4/5) with square roots only, which damps the growth
 * after a step that went well just before a hard region; between 0.2 and 5 times the step.
 * The next step waits for this factor, so only three square roots and a division lie between
 * a step's error and the next step: prev's root was taken while the step ran.
 */
export function nextStep(step: number, err: number, prev: number): number {
  return step * Math.min(5, Math.max(0.2, 0.9 * piFactor(err, prev)));
}

/**
 * What the step control remembers of an accepted error for the next one: its 16th root
 * (the error floored at 1e-4: one tiny error is no trend).
 */
export function errorMemory(err: number): number {
  return Math.sqrt(Math.sqrt(Math.sqrt(Math.sqrt(err > 1e-4 ? err : 1e-4))));
}

/**
 * The factor on the next step's size for slips closing on zero: a sliding slip r shrinking at
 * rate (per unit impulse) is d = r / -rate from its predicted zero, at a step's start (d0) and
 * end (d1). Near the zero its direction turns ever faster (the solution is not smooth there), so
 * a step that the error allows covers about a fixed fraction of the distance left, not a fixed
 * impulse: the PI control, which proposes the next step from the last one's size, then proposes
 * about the whole distance, the step aimed at the zero is rejected, and so on at every step of
 * the approach (half of the attempts on the 75-89.5° impacts without spin). The proposal is
 * scaled by d1 / d0 (the step control then works on the fraction of the distance), the smaller
 * of the two contacts', within [0.2, 1]; 1 when neither slip closes on zero over the step.
 * Not applied to a contact without friction (its slip's direction does not matter), nor once a
 * slip has reached its zero (CushionSolver.afterZero: a slip that leaves zero again is a new
 * start; scaled, the step after a table slip that reached zero and grew again, slaved, was a
 * fifth of the usual, and 268 of 840 impacts head-on with a frictionless cushion took more
 * steps, up to 88 against 51).
 */
export function approachFactor(d0I: number, d1I: number, d0C: number, d1C: number): number {
  let f = 1;
  if (d1I < d0I) f = d1I / d0I;
  if (d1C < d0C && d1C / d0C < f) f = d1C / d0C;
  return f < 0.2 ? 0.2 : f;
}

/**
 * After a sliding contact starts to roll, the step restarts at no less than this fraction of
 * the last step proposed away from every slip's zero (CushionSolver.afterZero). With
 * the whole of it, 20,000 wide draws took 11% fewer steps than growing back from the tiny steps
 * of the approach, but 140 results moved by more than 1e-6 V0, most of them farther from the
 * reference (to 4.5e-6 V0, where they had been within 2e-6); with half, 10.8% fewer steps and 63
 * moved, to at most 3.0e-6 (docs/cushion.md, "Approach to a zero").
 */
export const RESTART_FRACTION = 0.5;

/** Distance in impulse to the zero of a slip r changing along itself at rate; Infinity if it grows. */
export function zeroDistance(r: number, rate: number): number {
  return rate < 0 ? -r / rate : Infinity;
}

/** The memory before any accepted step (an error of 1). */
export const FIRST_MEMORY = 1;

/** err^(-1/8) × prev^(1/16), with prev as errorMemory keeps it. */
export function piFactor(err: number, prev: number): number {
  if (!(err > 1e-30)) return 1e6;
  return prev / Math.sqrt(Math.sqrt(Math.sqrt(err)));
}

/** err^(-3/16) with four square roots: the step-size factor (the optimal exponent is 1/5). */
export function invRoot(err: number): number {
  if (!(err > 1e-30)) return 1e6;
  const q = Math.sqrt(Math.sqrt(Math.sqrt(Math.sqrt(err))));
  return 1 / (q * q * q);
}
