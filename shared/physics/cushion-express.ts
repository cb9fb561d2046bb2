// The cushion impact's express path: the common impact, in which both contacts slip from start
// to end with slips well away from zero, integrated by Taylor series steps of order 8
// (cushion-series.ts) instead of the Runge-Kutta solver (cushion-solver.ts). A series step goes
// about as far as the solution's nearest singularity allows (where a slip speed's square
// vanishes, off the real axis), for about the cost of a Dormand-Prince step (docs/cushion.md).
// The step size is chosen from the series before the step is taken, so no step is rejected,
// and the series is its own continuous extension: the end of compression (vy = 0) and of
// restitution (the work's target, e_e² times the compression's work) are roots of it.
//
// A ball rolling on the cloth (the table slip zero at the start, the common cushion hit) starts
// with cushionSeriesRolling, in which that slip grows from zero in the direction its rates
// enforce, when it does grow (otherwise the table contact rolls: the solver's rolling
// conditions).
//
// It declines whenever the impact leaves the one smooth branch it integrates (the solver takes
// the impact from its start, or continues it from the start of the step that left): a slip
// below EXPRESS_SLIP_MIN of the speed at the start (other than a zero table slip) or at a
// step's end (a slip near zero calls for the rolling conditions and for the solver's slaving),
// constants with which the table's normal impulse could reach zero or the cushion's impulse
// could stop pushing the ball out (sinθ <= μw cosθ, or μw sinθ + μs (sinθ + μw cosθ) >= cosθ;
// never with the tables' constants), more than EXPRESS_MAX_STEPS steps, or a result with more
// energy than the ball brought (see finish).
import { ZERO_FRACTION } from './cushion-control.ts';
import { ROOT_MOVE } from './cushion-dense.ts';
import { cushionSeriesKernel, SERIES_ORDER_K, SERIES_TERMS } from './cushion-series.ts';
import type { CushionSeriesKernel } from './cushion-series.ts';

/**
 * The series step's error tolerance, as a multiple of the solver's. The step is set by the
 * estimated tail of the series (RATIO_GAIN), which is about the error itself, where the last
 * terms alone overstate it many times over on most steps; at half the solver's tolerance the
 * largest errors stay about where the last terms alone at the full tolerance had them (4112
 * impacts, grid and random: 2.5e-6 V0 against 2.5e-6, the grid 1.67e-6 against 1.77e-6).
 */
export const EXPRESS_TOL_FACTOR = 0.5;
/**
 * The ratio test's bounds (see the step choice in expressImpact): a step no longer than this
 * multiple of the last terms' own step, and no longer than RATIO_MAX / r with r the terms'
 * ratio. Two terms can fall by chance faster than the series does: with 2 here and no
 * RATIO_FLOOR, impacts at 65° and 75° with topspin and sidespin k = 2 ended 1.0e-5 and 8.7e-6 V0
 * off (with the floor, 2 takes the same steps on the grid as 1.5, its errors up to 1.97e-6).
 */
export const RATIO_GAIN = 1.5;
export const RATIO_MAX = 0.5;
/**
 * The ratio test takes the last term's level as at least this fraction of what the two before it
 * extrapolate to (n7² / n6): a last term small by chance (a coefficient passing zero) would make
 * the tail look small. On the grid it binds on the impacts where a gain of 2 failed (topspin and
 * sidespin k = 2 at 65-75°), 75° ending 1.4e-6 V0 off instead of 1.95e-6, at the cost of 4 of the
 * 528 impacts taking a fourth step.
 */
export const RATIO_FLOOR = 0.5;
/**
 * A slip below this fraction of the speed sends the impact to the solver. Near a slip's close
 * approach to zero the series' last terms understate the error of a step: at 2% a random impact
 * (μs 0.34, μw 0.09, 86°) whose table slip passed zero at 2% of the speed ended 8.9e-6 V0 off
 * (the solver alone: 2e-7); at 5%, 8.6e-7, and the largest error on this path over the test sets
 * (3.9e-6 V0 over 18,000 random draws) stays below the solver's own largest (4.5e-6).
 */
export const EXPRESS_SLIP_MIN = 0.05;
/** More series steps than this send the impact to the solver. */
export const EXPRESS_MAX_STEPS = 16;

/**
 * A root is taken as found when its last correction dx is within this fraction of the step.
 * The end of compression matters only through the work there, W_c, at its maximum
 * (dW/dp = c vy, exactly so on the series with the work's last term, SERIES_W_LAST): from x,
 * W(x) - c vy dx / 2 is W_c to within c |d²vy/dp²| |dx|³ / 6 (tested: within 1e-9 of it,
 * measured 2.4e-10; Newton's root itself within 1.1e-7 of the step). The end of restitution is Halley's
 * (cubic convergence), from the root of the work's quadratic part: within 3e-8 of the step
 * (tested), which moves the result by about as little of V0 (3% of the default tolerance). With
 * e_e = 0 the ball leaves at the end of compression itself, which Newton's method then locates to
 * ROOT_MOVE (1e-6) of the step, as the solver does (to about 1e-13). On the benchmark grid the
 * roots took 2.1 and 2.0 Newton iterations each, and the work at the first one another
 * evaluation; now 1.02 and 1.16 evaluations (1.11 and 1.27 with 1e-3 here: 28 of the grid's
 * 132 three-step impacts at 2 m/s evaluated the end of restitution twice, 4 now, the same
 * largest errors over the test sets, 1-3% less time at the three-step impacts' upper
 * percentiles, where the grid's median lies).
 */
export const EVENT_DONE = 2e-3;

/**
 * The largest of a coefficient's values in the state's variables (vx, vy, R ωx, R ωy, R ωz) from
 * those of the series' (SERIES_VARIABLES; see stateOf): the step is chosen on the state's
 * coefficients, as the tolerance is stated in them.
 */
export function stateNorm(eIx: number, vy: number, eIy: number, eCx: number, oz: number, s: number, c: number): number {
  const u = eIx + c * oz;
  const i1 = 1 / (1 + s);
  // (vx and R ωy, the longest to form, last: the maximum waits on them only at its end.)
  return Math.max(Math.abs(vy), Math.abs(oz), Math.abs(eIy + s * vy), Math.abs((u + s * eCx) * i1), Math.abs((u - eCx) * i1));
}

/** The express path's kernel: made once (expressKernel), see cushionSeriesKernel. */
interface ExpressKernel {
  readonly sk: CushionSeriesKernel;
  readonly input: Float64Array;
  readonly handover: { restitution: boolean; wEnd: number; p: number };
  readonly from: Float64Array;
  seriesConstants(s: number, c: number, muS: number, muW: number, lim: number): void;
  impact(): number;
  compressionEnd(dp: number, c: number, done: number): number;
  restitutionEnd(target: number, lo: number, hi: number, c: number): number;
}

/**
 * Makes the express path's kernel, once. Its arrays and functions are constants of this one
 * closure (and of the series kernel's), so that V8's optimizing compiler embeds them: no loads of
 * an array's address and length, no bounds or map checks on its accesses, direct calls. (At a
 * module's top level they would not be: the bundler turns a module's `const` into `var`, which
 * the compiler must reload and check at each use. The same bits; a three-step impact 8,162
 * instructions in the kernel's functions against 9,336, 6-7% less time.)
 */
function expressKernel(): ExpressKernel {
  const sk = cushionSeriesKernel();
  const q = sk.q;
  const K = sk.k;
  const start = sk.start;
  const out = sk.out;
  const ev = sk.ev;
  const series = sk.series;
  const seriesRolling = sk.seriesRolling;
  const valueAt = sk.valueAt;
  const endFirst = sk.endFirst;
  const endRest = sk.endRest;
  const event = sk.event;
  // The input (EXPRESS_IN), 96 bytes: an ArrayBuffer of its own (see cushionSeriesKernel).
  const IN = new Float64Array(new ArrayBuffer(12 * 8));
  const HANDOVER = { restitution: false, wEnd: 0, p: 0 };
  // The roots' arguments, in, and the root, out at 4 (a number passed to or returned by a function
  // that is not inlined is boxed: a heap allocation each).
  const ARG = new Float64Array(new ArrayBuffer(5 * 8));
  // The impact's sinθ, cosθ, μs, μw, the slips' threshold, the step's choice's weights iv,
  // iw, L^6 and L^7 (for constants and stateOf), and twice its energy per unit mass (finish).
  const GEOM = new Float64Array(new ArrayBuffer(10 * 8));
  // The variables at the start of the step being taken (for handOver).
  const PREV = new Float64Array(new ArrayBuffer(6 * 8));
  // The work's target and the impulse at the start of the step being taken (for handOver).
  const STEP = new Float64Array(new ArrayBuffer(2 * 8));
  // The last impact's R and h, with their sinθ and cosθ (NaN at first: no match).
  const LAST = new Float64Array(new ArrayBuffer(4 * 8)).fill(NaN);
  // sinθ, cosθ, μs and μw of the series' constants K[0..11] and K[17] (NaN at first: no match).
  const KEY = new Float64Array(new ArrayBuffer(4 * 8)).fill(NaN);
  // The state the solver continues from (EXPRESS_FROM), formed by handOver from PREV.
  const FROM = new Float64Array(new ArrayBuffer(6 * 8));
  // The tuning constants as constants of the closure, which the compiler embeds: a module-level
  // binding is a context slot (the bundler makes a module's `const` a `var`) that the optimized
  // code loads, and checks at each use in the loop.
  const ratioGain = RATIO_GAIN;
  const ratioMax = RATIO_MAX;
  const ratioFloor = RATIO_FLOOR;
  const maxSteps = EXPRESS_MAX_STEPS;
  const slipMin = EXPRESS_SLIP_MIN;
  const zeroFraction = ZERO_FRACTION;
  const tolFactor = EXPRESS_TOL_FACTOR;
  const rootMove = ROOT_MOVE;
  const eventDone = EVENT_DONE;
  /**
   * The end of compression in a step of length dp (ARG = [dp, cosθ, done]) whose series q takes vy
   * from above 0 to 0 or below: the impulse of vy = 0 into ARG[4], with the work there in
   * EXPRESS_EVENT[2]. From the root of vy's
   * quadratic part, Newton's method kept inside the bracket (bisection otherwise) until its
   * correction dx is below done × dp; the work at the root is then W(x) - c vy(x) dx / 2
   * (dW/dp = c vy: the second-order Taylor step to the root, its error of order dx³), from the
   * same pass.
   */
  function compressionEnd(): void {
    const dp = ARG[0]!;
    const c = ARG[1]!;
    const done = ARG[2]!;
    const a0 = q[9]!; // vy's first three coefficients (q[9 i + k], i = 1)
    const a1 = q[10]!;
    const a2 = q[11]!;
    const disc = a1 * a1 - 4 * a2 * a0;
    // a0 + a1 x + a2 x² = 0 with a0 > 0: the smallest positive root, without cancellation.
    const den = disc >= 0 ? Math.sqrt(disc) - a1 : 0;
    let x = den > 0 ? (2 * a0) / den : -a0 / a1;
    let lo = 0;
    let hi = dp;
    if (!(x > lo && x < hi)) x = 0.5 * dp;
    const eps = done * dp;
    for (let it = 0; it < 60; it++) {
      q[56] = x; // q[SERIES_AT]
      event();
      const v = ev[0]!;
      const d = ev[1]!;
      if (v > 0) lo = x;
      else hi = x;
      const dx = v / d;
      const next = x - dx;
      if (next >= lo && next <= hi && d < 0) {
        if (Math.abs(dx) <= eps) {
          ev[2] = ev[2]! - 0.5 * c * v * dx;
          ARG[4] = next;
          return;
        }
        x = next;
      } else {
        x = 0.5 * (lo + hi);
      }
      if (hi - lo <= 1e-12 * dp) break; // (bisection alone: to rounding)
    }
    ARG[4] = x;
  }

  /**
   * The end of restitution in [lo, hi] of a step of length hi (ARG = [target, lo, hi, cosθ]; the
   * work above target at lo, at or below it at hi), into ARG[4]: where W falls to target, by
   * Halley's method (W' = c vy and W'' = c dvy/dp from the same pass; Newton's correction where
   * Halley's would not be defined) kept inside the bracket by bisection, from the root of the
   * work's quadratic part (workStart) or the bracket's middle, until its correction is below
   * EVENT_DONE of the step.
   */
  function restitutionEnd(): void {
    const target = ARG[0]!;
    let lo = ARG[1]!;
    let hi = ARG[2]!;
    const c = ARG[3]!;
    const dp = hi;
    const eps = eventDone * dp;
    const x0 = workStart(target);
    let x = x0 > lo && x0 < hi ? x0 : 0.5 * (lo + hi);
    for (let it = 0; it < 60; it++) {
      q[56] = x; // q[SERIES_AT]
      event();
      const f = ev[2]! - target;
      if (f === 0) {
        ARG[4] = x;
        return;
      }
      if (f > 0) lo = x;
      else hi = x;
      const f1 = c * ev[0]!;
      const den = f1 * f1 - 0.5 * f * (c * ev[1]!);
      const dx = den > 0 ? (f * f1) / den : f / f1;
      const next = x - dx;
      if (next > lo && next < hi) {
        if (Math.abs(dx) <= eps) {
          ARG[4] = next;
          return;
        }
        x = next;
      } else {
        x = 0.5 * (lo + hi);
      }
      if (hi - lo <= 1e-12 * dp) break; // (bisection alone: to rounding)
    }
    ARG[4] = x;
  }

  /** Whether both slips at the step's end are at least √min2. */
  function slipsAbove(s: number, min2: number): boolean {
    const z = start;
    const ix = z[0]!;
    const iy = z[2]!;
    const cx = z[3]!;
    const cy = iy + (1 + s) * z[1]!;
    return ix * ix + iy * iy >= min2 && cx * cx + cy * cy >= min2;
  }

  /**
   * The impact in EXPRESS_IN, with vy > 0 (checked by the caller), on the express path: the
   * number of series steps it took, with the result in EXPRESS_OUT; 0 when it declines at the
   * start; minus the steps it took when it leaves its branch later (the solver continues from
   * EXPRESS_FROM and EXPRESS_HANDOVER).
   */
  function expressImpact(): number {
    const input = IN;
    const vx = input[0]!;
    const vy = input[1]!;
    const wx = input[2]!;
    const wy = input[3]!;
    const wz = input[4]!;
    const R = input[5]!;
    const h = input[6]!;
    const ee = input[7]!;
    const muS = input[8]!;
    const muW = input[9]!;
    const tol = input[10]!;
    // sinθ and cosθ, kept from the last impact when R and h are the same (a division and a
    // square root on the way to the first series; the same bits either way).
    let s: number;
    let c: number;
    if (R === LAST[0] && h === LAST[1]) {
      s = LAST[2]!;
      c = LAST[3]!;
    } else {
      s = (h - R) / R;
      c = Math.sqrt((1 - s) * (1 + s));
      LAST[0] = R;
      LAST[1] = h;
      LAST[2] = s;
      LAST[3] = c;
    }
    // The table's normal impulse stays positive (sinθ + μw cosθ u_I,y > 0 for every direction), and
    // the impulse always pushes the ball out (dvy/dp < 0 for every pair of slip directions).
    if (!(s > c * muW) || !(s * muW + muS * (s + c * muW) < c)) return 0;
    const V = Math.sqrt(vx * vx + vy * vy);
    const lim = slipMin * V;
    const min2 = lim * lim;
    const ox = R * wx;
    const oy = R * wy;
    const oz = R * wz;
    // A table slip that is zero (a ball rolling on the cloth, within ZERO_FRACTION of the speed,
    // as the solver counts it) starts the impact with cushionSeriesRolling.
    let rolling = false;
    {
      const ix = vx + s * oy - c * oz;
      const iy = ox - s * vy;
      const cx = vx - oy;
      const cy = vy + ox;
      const zero = zeroFraction * V;
      if (!(ix * ix + iy * iy >= min2)) return 0;
      if (cx * cx + cy * cy <= zero * zero) rolling = true;
      else if (!(cx * cx + cy * cy >= min2)) return 0;
    }
    // The series' variables (SERIES_VARIABLES): e_I, vy, e_C,x, R ωz and the work.
    start[0] = vx + s * oy - c * oz;
    start[1] = vy;
    start[2] = ox - s * vy;
    start[3] = vx - oy;
    start[4] = oz;
    start[5] = 0;
    // Error weights: the speeds against tol V, the work against tol V c vy (an error dW moves the
    // end by dW / (c |vy|), as in the solver).
    const iv = 1 / (tolFactor * tol * V);
    const iw = iv / (c * vy);
    // The step is measured in L = vy / c (the frictionless compression's impulse), so that the
    // series' last two terms, each made relative to it (a_k L^k), compare alike however fast the
    // ball (the model is homogeneous in the speeds, and so is every decision here). No step is
    // longer than 3L, half again the whole frictionless impact (2L): with little friction the
    // last terms are tiny and say nothing of the impact's length. A ball rolling on the cloth into
    // the cushion at a shallow angle rebounds after about 2.2L (the table's friction, its slip
    // growing from zero, pushes the ball towards the cushion, so vy falls by less than c per unit
    // impulse): at 2L those impacts took a second step for their last tenth (5-35°, natural roll:
    // the grid's mean 6.74 steps, 6.64 now, errors unchanged).
    const L = vy / c;
    const L2 = L * L;
    const L4 = L2 * L2;
    const w6 = L4 * L2;
    const w7 = w6 * L;
    const w8 = L4 * L4;
    GEOM[0] = s;
    GEOM[1] = c;
    GEOM[2] = muS;
    GEOM[3] = muW;
    GEOM[4] = lim;
    GEOM[5] = iv;
    GEOM[6] = iw;
    GEOM[7] = w6;
    GEOM[8] = w7;
    constants();
    const hMax = 3 * L;
    const ee2 = ee * ee;
    // Twice the kinetic and rotational energy per unit mass (I = 2/5 M R²), for finish.
    GEOM[9] = vx * vx + vy * vy + 0.4 * (ox * ox + oy * oy + oz * oz);
    let restitution = false;
    let wEnd = 0;
    let p = 0;
    for (let step = 1; step <= maxSteps; step++) {
      // If this step leaves the branch, the solver continues from its start (handOver).
      // (The work's target and the impulse at the step's start through an array: numbers passed
      // to handOver, which is not inlined, would be boxed, and the loop's variables with them.)
      const rest0 = restitution;
      STEP[0] = wEnd;
      STEP[1] = p;
      const done = 1 - step; // 0 or minus the steps taken
      // The step's start, kept for a hand-over: its end is evaluated into start, where the next
      // series starts (copied here, beside the series, rather than on the way from one step's
      // end to the next series).
      PREV[0] = start[0]!;
      PREV[1] = start[1]!;
      PREV[2] = start[2]!;
      PREV[3] = start[3]!;
      PREV[4] = start[4]!;
      PREV[5] = start[5]!;
      if ((rolling ? seriesRolling() : series()) === 0) return handOver(rest0, done);
      // The step from the series' two last terms (after Jorba and Zou 2005): the largest h with
      // |a_k L^k| (h / L)^8 within the tolerance for k = 7 and 8, each variable against its weight.
      // The largest weighted coefficients of p^6, p^7 and p^8 (q[9 i + k], SERIES_TERMS = 9: the
      // indices are written out, a loop with computed indices cost 4% of an impact).
      // n6, n7 and n7's eighth root come from the series (SERIES_NORMS), formed there beside
      // order 8; n8 here, the same way (stateNorm: the state's coefficients against iv, the
      // work's against iw, in units of L^8).
      const n6 = q[57]!;
      const n7 = q[58]!;
      let n8 = Math.abs(q[53]!) * iw;
      const a8 = stateNorm(q[8]!, q[17]!, q[26]!, q[35]!, q[44]!, s, c) * iv;
      if (a8 > n8) n8 = a8;
      n8 *= w8;
      const n = n7 > n8 ? n7 : n8;
      // L / (the last terms' step)
      const t = n7 >= n8 ? q[59]! : Math.sqrt(Math.sqrt(Math.sqrt(n8)));
      let dp = n > 0 ? L / t : hMax;
      // The ratio test: with the terms falling by r = n8 / n7 an order (in units of L; n8 floored,
      // below; each n_k is the largest over the variables, so r may mix two of them), the
      // series' tail past p^8 at x = h / L is about n8 x^8 · x r / (1 - x r), a geometric series,
      // which on most steps is far below the last terms themselves. The step where that tail meets
      // the tolerance, with x r / (1 - x r) taken at the last terms' step x0 = 1 / t:
      // x^8 = g n7 / n8² with g = (1 - x0 r) / x0 = t - r, so x = (n7 / n8²)^(1/8) g^(1/8), the
      // first factor's square roots beside t's and g^(1/8) by its Padé approximant
      // (7 + 9g) / (9 + 7g) (g > 1/4 here, as x0 < 2 and x0 r < 1/2: within 2.4% up to g = 4,
      // above g^(1/8) below g = 1 and below it above); at most RATIO_GAIN x0, with x r <= RATIO_MAX,
      // and only when x0 r < RATIO_MAX. Taken at x0, the factor understates the tail at the longer
      // x, by up to 2 at the caps: the halved tolerance (EXPRESS_TOL_FACTOR) covers it. On the
      // benchmark grid (paper constants) 296 of the 528 impacts end on this path in at most three
      // steps, where 200 did.
      // The last term's level for the test: at least RATIO_FLOOR of the two before's extrapolation,
      // n7² / n6 (compared without a division, which only the rare floor needs; n6 = 0 makes the
      // floor infinite, and the test then keeps x0).
      const f8 = ratioFloor * n7 * n7;
      const m8 = n8 * n6 < f8 ? f8 / n6 : n8;
      if (m8 > 0 && n7 > 0 && dp < hMax) {
        const r = m8 / n7;
        if (r < ratioMax * t) {
          const g = t - r;
          // ((n7 / m8²)^(1/8) as n7^(1/8) / m8^(1/4): two roots after the series, not three.)
          let x = (q[59]! / Math.sqrt(Math.sqrt(m8))) * ((7 + 9 * g) / (9 + 7 * g));
          if (x * r > ratioMax) x = ratioMax / r;
          const xt = x * t; // x / x0
          if (xt > ratioGain) dp = (ratioGain * L) / t;
          else if (xt > 1) dp = x * L;
        }
      }
      if (!(dp <= hMax)) dp = hMax;
      // A shrinking slip is not carried below EXPRESS_SLIP_MIN by a step, as predicted from its
      // rate along itself (as the solver aims its steps at a slip's zero): a slip closing on zero
      // nearly head-on makes the series' last terms small however near the zero is (its direction
      // flips across a width that those terms cannot see), and past it the series would go on
      // slipping where the contact sticks. Where that leaves less than a quarter step, the solver
      // continues from here.
      const cut = q[54]!; // q[SERIES_CUT]
      if (cut < dp) {
        if (cut < 0.25 * dp) return handOver(rest0, done);
        dp = cut;
      }
      let from = 0;
      // vy and the work at the step's end first: when restitution ends inside the step, the rest
      // of the end is never needed (the result is evaluated where it ends).
      q[56] = dp; // q[SERIES_AT]
      endFirst();
      if (!restitution && start[1]! <= 0) {
        ARG[0] = dp;
        ARG[1] = c;
        ARG[2] = ee2 === 0 ? rootMove : eventDone;
        compressionEnd();
        from = ARG[4]!;
        const wc = ev[2]!;
        wEnd = wc - ee2 * wc;
        restitution = true;
        if (ee2 === 0) {
          ARG[0] = from;
          return finish() ? step : handOver(rest0, done);
        }
      }
      if (restitution) {
        if (start[5]! <= wEnd) {
          ARG[0] = wEnd;
          ARG[1] = from;
          ARG[2] = dp;
          ARG[3] = c;
          restitutionEnd();
          ARG[0] = ARG[4]!;
          return finish() ? step : handOver(rest0, done);
        }
        if (start[1]! >= 0) return handOver(rest0, done); // vy back at zero: stalled (the solver decides)
      }
      q[56] = dp; // (the roots above move it)
      endRest();
      // The slips at the step's end only: with the cut above, a slip whose closest approach to zero
      // is below the threshold reaches the step's end before it (to first order in the step), so a
      // dip inside the step shows at its end. (A check in the middle as well never fired over
      // 217,836 impacts, random and structured, and cost 9% of the time.)
      if (!slipsAbove(s, min2)) return handOver(rest0, done);
      rolling = false;
      p += dp;
    }
    PREV.set(start); // (the state where the last step ended: the solver continues from there)
    STEP[0] = wEnd;
    STEP[1] = p;
    return handOver(restitution, -maxSteps);
  }

  /**
   * Records where the solver continues (EXPRESS_HANDOVER, the work's target and the impulse from
   * STEP, and the state from PREV in EXPRESS_FROM) and returns code.
   */
  function handOver(restitution: boolean, code: number): number {
    // (Through out, which the solver's result does not use.)
    out.set(PREV);
    stateOf();
    FROM.set(out);
    const h = HANDOVER;
    h.restitution = restitution;
    h.wEnd = STEP[0]!;
    h.p = STEP[1]!;
    return code;
  }

  /**
   * Where the work's series without its terms above p² falls to target (the work is nearly
   * quadratic in p: its rate c vy is nearly linear), as a start for restitutionEnd; -1 when it
   * does not.
   */
  function workStart(target: number): number {
    const a = q[47]!; // the work's first three coefficients (q[9 i + k], i = 5)
    const b = q[46]!;
    const c0 = q[45]! - target;
    // a p² + b p + c0 = 0 with a < 0 (vy falls) and c0 > 0: the positive root, without cancellation.
    const disc = b * b - 4 * a * c0;
    if (!(a < 0) || !(disc >= 0)) return -1;
    const sq = Math.sqrt(disc);
    return b >= 0 ? (-b - sq) / (2 * a) : (2 * c0) / (sq - b);
  }

  /**
   * The constants the series functions read (K, cushion-series.ts), for sinθ = s, cosθ = c, the
   * frictions and the slip speed lim at which a shrinking slip's cut is aimed (SERIES_CUT), from
   * GEOM: sinθ, cosθ, -μw, -μs μw cosθ, μs sinθ (the table's normal times -μs is k3 u_I,y - k4),
   * then the weights of u_I and h in the slips' rates (cushion-model.ts) and sinθ cosθ. Without
   * arguments: numbers passed to a function that is not inlined are boxed (expressImpact's
   * inlining budget goes to the evaluations at each step).
   */
  function constants(): void {
    const s = GEOM[0]!;
    const c = GEOM[1]!;
    const muS = GEOM[2]!;
    const muW = GEOM[3]!;
    // Those of the table's constants alone are kept while sinθ, cosθ and the frictions are the
    // same as the last impact's (KEY).
    if (!(s === KEY[0] && c === KEY[1] && muS === KEY[2] && muW === KEY[3])) {
      K[0] = s;
      K[1] = c;
      K[2] = -muW;
      K[3] = -(muS * c * muW);
      K[4] = muS * s;
      K[5] = -3.5 * muW;
      K[6] = 1 - 2.5 * s;
      K[7] = -(s * s + 2.5) * muW;
      K[8] = 2.5 - s;
      K[9] = -(1 - 2.5 * s) * muW;
      K[10] = -(2.5 - s) * muW;
      K[11] = s * c;
      K[17] = 1 / (1 + s);
      // Each order's weights divided by k + 1 (SERIES_ORDER_K): of u_I and h in the slips' next
      // coefficients, of u_I,y in vy's (-sinθ (-μw)), of u_I,x in R ωz's (-2.5 cosθ (-μw)), and
      // of vy in the work's (cosθ).
      for (let o = 0, b = SERIES_ORDER_K; o < SERIES_TERMS - 1; o++, b += 9) {
        const inv = 1 / (o + 1);
        K[b] = K[5]! * inv;
        K[b + 1] = K[6]! * inv;
        K[b + 2] = K[7]! * inv;
        K[b + 3] = K[8]! * inv;
        K[b + 4] = K[9]! * inv;
        K[b + 5] = K[10]! * inv;
        K[b + 6] = s * muW * inv;
        K[b + 7] = 2.5 * c * muW * inv;
        K[b + 8] = c * inv;
      }
      KEY[0] = s;
      KEY[1] = c;
      KEY[2] = muS;
      KEY[3] = muW;
    }
    K[12] = GEOM[4]!;
    // The step's choice's weights (SERIES_NORMS): the speeds', the work's, L^6, L^7 (and K[17],
    // 1 / (1 + sinθ), for stateNorm).
    K[13] = GEOM[5]!;
    K[14] = GEOM[6]!;
    K[15] = GEOM[7]!;
    K[16] = GEOM[8]!;
  }

  /**
   * The internal state y = [vx, vy, R ωx, R ωy, R ωz, W] of the series' variables z (e_I,x, vy,
   * e_I,y, e_C,x, R ωz, W; SERIES_VARIABLES), for sinθ and cosθ in GEOM: R ωx = e_I,y + sinθ vy,
   * and from e_I,x = vx + sinθ R ωy - cosθ R ωz and e_C,x = vx - R ωy,
   * R ωy = (e_I,x + cosθ R ωz - e_C,x) / (1 + sinθ). In place on out, a constant of the closure
   * (an array passed in would be checked at each access).
   */
  function stateOf(): void {
    const o = out;
    const s = GEOM[0]!;
    const c = GEOM[1]!;
    const oy = (o[0]! + c * o[4]! - o[3]!) / (1 + s);
    o[0] = o[3]! + oy;
    o[2] = o[2]! + s * o[1]!;
    o[3] = oy;
  }

  /**
   * The result at p = ARG[0] into EXPRESS_OUT (in the state's variables); false (the solver
   * continues from the step's start) when it has more kinetic and rotational energy than the ball
   * brought (twice it per unit mass in GEOM[9]). The model only dissipates; near grazing, with
   * e_e near 1, it dissipates so little that the series' error could show as a gain, which the
   * solver, stepping more finely there, does not make. (Its arguments through arrays: numbers
   * passed to a function that is not inlined are boxed.)
   */
  function finish(): boolean {
    const o = out;
    q[56] = ARG[0]!; // q[SERIES_AT]
    valueAt();
    stateOf();
    return o[0]! * o[0]! + o[1]! * o[1]! + 0.4 * (o[2]! * o[2]! + o[3]! * o[3]! + o[4]! * o[4]!) <= GEOM[9]!;
  }

  return {
    sk, input: IN, handover: HANDOVER, from: FROM, impact: expressImpact,
    seriesConstants: (s: number, c: number, muS: number, muW: number, lim: number): void => {
      GEOM[0] = s;
      GEOM[1] = c;
      GEOM[2] = muS;
      GEOM[3] = muW;
      GEOM[4] = lim;
      GEOM.fill(0, 5);
      constants();
    },
    compressionEnd: (dp: number, c: number, done: number): number => {
      ARG[0] = dp;
      ARG[1] = c;
      ARG[2] = done;
      compressionEnd();
      return ARG[4]!;
    },
    restitutionEnd: (target: number, lo: number, hi: number, c: number): number => {
      ARG[0] = target;
      ARG[1] = lo;
      ARG[2] = hi;
      ARG[3] = c;
      restitutionEnd();
      return ARG[4]!;
    },
  };
}

const EXPRESS = expressKernel();

/**
 * The impact in EXPRESS_IN, with vy > 0 (checked by the caller), on the express path: the
 * number of series steps it took, with the result in EXPRESS_OUT; 0 when it declines at the
 * start; minus the steps it took when it leaves its branch later (the solver continues from
 * EXPRESS_FROM and EXPRESS_HANDOVER).
 */
export const expressImpact: () => number = EXPRESS.impact;
/**
 * The end of compression in a step of length dp of the series in EXPRESS_SERIES.q (see
 * compressionEnd inside expressKernel), with the work there in EXPRESS_EVENT[2].
 */
export const compressionEnd: (dp: number, c: number, done: number) => number = EXPRESS.compressionEnd;
/** The end of restitution in [lo, hi] of a step of length hi of the series in EXPRESS_SERIES.q. */
export const restitutionEnd: (target: number, lo: number, hi: number, c: number) => number = EXPRESS.restitutionEnd;
/**
 * Sets the series kernel's constants (EXPRESS_SERIES.k) for sinθ = s, cosθ = c, the frictions and
 * the slip speed lim at which a shrinking slip's cut is aimed, as expressImpact does.
 */
export const seriesConstants: (s: number, c: number, muS: number, muW: number, lim: number) => void =
  EXPRESS.seriesConstants;
/** The series kernel the express path steps with (its arrays and functions). */
export const EXPRESS_SERIES: CushionSeriesKernel = EXPRESS.sk;
/**
 * The express path's input, written by the caller: [vx, vy, wx, wy, wz, R, h, e_e, μs, μw, tol]
 * (tol the solver's tolerance, relative to the speed), and the mass after them, which the
 * express path does not need (the caller's solver does). An array rather than eleven arguments:
 * a number passed to a function that is not inlined is boxed, a heap allocation each (4% of an
 * impact, measured side by side).
 */
export const EXPRESS_IN: Float64Array = EXPRESS.input;
/** The express result, in the internal variables [vx, vy, R ωx, R ωy, R ωz, W]. */
export const EXPRESS_OUT: Float64Array = EXPRESS.sk.out;
/** The state at the start of the step the express path left on (see EXPRESS_HANDOVER). */
export const EXPRESS_FROM: Float64Array = EXPRESS.from;
/** vy, dvy/dp and W at the point of the last event evaluation. */
export const EXPRESS_EVENT: Float64Array = EXPRESS.sk.ev;
/**
 * Where the solver continues an impact the express path left after some steps: the state
 * (internal variables, EXPRESS_FROM), whether compression has ended, the work's target and the
 * impulse per unit mass so far.
 */
export const EXPRESS_HANDOVER: { restitution: boolean; wEnd: number; p: number } = EXPRESS.handover;
