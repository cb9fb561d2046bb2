// The continuous extension of a Dormand-Prince step (Hairer, Norsett and Wanner, "Solving ODEs
// I", 2nd ed., sec. II.6, with Shampine's 4th-order weights), stored as 5 coefficients
// per variable, and the location of an event on it. Shared by the general step (cushion-dopri.ts)
// and the inner loop (cushion-fast.ts), so both locate events the same way.

import { D1, D3, D4, D5, D6, D7 } from './cushion-tableau.ts';

/** Coefficients per variable in a dense-output array (variable i at 5 i .. 5 i + 4). */
export const DENSE_STRIDE = 5;

/**
 * The extension of one variable over a step of size h from y0 to y1 with stage derivatives
 * k1, k3..k7 (k2 has no weight), into out[o .. o + 4].
 */
export function denseVariable(
  out: Float64Array, o: number, h: number, y0: number, y1: number,
  k1: number, k3: number, k4: number, k5: number, k6: number, k7: number,
): void {
  const dy = y1 - y0;
  const b = h * k1 - dy;
  out[o] = y0;
  out[o + 1] = dy;
  out[o + 2] = b;
  out[o + 3] = dy - h * k7 - b;
  out[o + 4] = h * (D1 * k1 + D3 * k3 + D4 * k4 + D5 * k5 + D6 * k6 + D7 * k7);
}

/** denseVariable for the first y.length variables, from arrays. */
export function fillDense(
  out: Float64Array, h: number, y: Float64Array, y1: Float64Array,
  k1: Float64Array, k3: Float64Array, k4: Float64Array, k5: Float64Array, k6: Float64Array, k7: Float64Array,
): void {
  for (let i = 0; i < y.length; i++) {
    denseVariable(out, DENSE_STRIDE * i, h, y[i]!, y1[i]!, k1[i]!, k3[i]!, k4[i]!, k5[i]!, k6[i]!, k7[i]!);
  }
}

/** Variable i at fraction theta of the step: q0 + θ(q1 + (1-θ)(q2 + θ(q3 + (1-θ) q4))). */
export function denseValue(q: Float64Array, i: number, theta: number): number {
  const t1 = 1 - theta;
  const o = DENSE_STRIDE * i;
  return q[o]! + theta * (q[o + 1]! + t1 * (q[o + 2]! + theta * (q[o + 3]! + t1 * q[o + 4]!)));
}

/**
 * Newton's method stops after a correction this small (a fraction of the step) that stays
 * inside the bracket: it converges quadratically, so the root is then within about 1e-12 of the
 * step, far below what the tolerances can see (an error dθ moves the state by about dθ × the
 * step's change, under V).
 */
export const ROOT_MOVE = 1e-6;

/**
 * The theta in [lo, hi] where variable i of the extension falls to target, given that it is
 * above target at lo and at or below it at hi (otherwise lo, or hi when it never falls there).
 * Newton's method on the quartic, kept inside the bracket by bisection, from the root of the
 * quadratic q0 + θ q1 + θ(1-θ) q2 (the extension without its two highest terms) when that lies
 * inside the bracket, else from the secant point: 2.1 iterations (value and slope) a root on
 * the benchmark grid, where the secant start took 4 (5 for the work, which is nearly
 * quadratic in θ) and a regula falsi 8 to 9.
 */
export function denseRoot(q: Float64Array, i: number, target: number, lo: number, hi: number): number {
  const o = DENSE_STRIDE * i;
  const q0 = q[o]!;
  const q1 = q[o + 1]!;
  const q2 = q[o + 2]!;
  const q3 = q[o + 3]!;
  const q4 = q[o + 4]!;
  let t = 1 - lo;
  const flo = q0 + lo * (q1 + t * (q2 + lo * (q3 + t * q4))) - target;
  if (!(flo > 0)) return lo;
  t = 1 - hi;
  const fhi = q0 + hi * (q1 + t * (q2 + hi * (q3 + t * q4))) - target;
  if (fhi > 0) return hi;
  // -q2 θ² + (q1 + q2) θ + (q0 - target) = 0, for a falling variable (q1 + q2 < 0): the root
  // 2c / (-b + √(b² - 4ac)), written without cancellation.
  const b = q1 + q2;
  const c0 = q0 - target;
  const disc = b * b + 4 * q2 * c0;
  let x = -1;
  if (b < 0 && disc >= 0) x = (2 * c0) / (Math.sqrt(disc) - b);
  if (!(x > lo && x < hi)) x = lo + (hi - lo) * (flo / (flo - fhi));
  for (let it = 0; it < 60; it++) {
    // P = q0 + θA, A = q1 + (1-θ)B, B = q2 + θC, C = q3 + (1-θ)q4, and their derivatives.
    t = 1 - x;
    const c = q3 + t * q4;
    const b = q2 + x * c;
    const a = q1 + t * b;
    const f = q0 + x * a - target;
    if (f === 0) return x;
    if (f > 0) lo = x;
    else hi = x;
    const db = c - x * q4;
    const da = t * db - b;
    const d = a + x * da;
    const dx = f / d;
    let next = x - dx;
    if (!(next > lo && next < hi)) {
      // Newton leaves the bracket: x is the root to rounding (the correction is at the last
      // bits and x a bracket end), or the slope misleads and the bracket is halved.
      if (Math.abs(dx) <= 1e-15) return x;
      next = 0.5 * (lo + hi);
    } else if (Math.abs(dx) <= ROOT_MOVE) {
      return next;
    }
    x = next;
    if (hi - lo <= 1e-15) break;
  }
  return x;
}
