// The integrator: the Dormand-Prince 5(4) pair with its 4th-order continuous extension, for the
// impact's six variables. Tableau: J. R. Dormand and P. J. Prince, J. Comp. Appl. Math. 6 (1980)
// 19-26; dense output: L. F. Shampine, Math. Comp. 46 (1986), as given by Hairer, Nørsett and
// Wanner, "Solving ODEs I", 2nd ed., sec. II.6. The 5th-order solution is propagated; its
// difference from the 4th-order one is the error estimate. The last stage is the next step's
// first (FSAL): six evaluations a step.

/** The impact's variables: [vx, vy, R ωx, R ωy, R ωz, W]. */
export const DIM = 6;

const A21 = 1 / 5;
const A31 = 3 / 40, A32 = 9 / 40;
const A41 = 44 / 45, A42 = -56 / 15, A43 = 32 / 9;
const A51 = 19372 / 6561, A52 = -25360 / 2187, A53 = 64448 / 6561, A54 = -212 / 729;
const A61 = 9017 / 3168, A62 = -355 / 33, A63 = 46732 / 5247, A64 = 49 / 176, A65 = -5103 / 18656;
const B1 = 35 / 384, B3 = 500 / 1113, B4 = 125 / 192, B5 = -2187 / 6784, B6 = 11 / 84;
// 5th-order minus 4th-order weights.
const E1 = 71 / 57600, E3 = -71 / 16695, E4 = 71 / 1920, E5 = -17253 / 339200, E6 = 22 / 525, E7 = -1 / 40;
// Continuous extension.
const D1 = -12715105075 / 11282082432, D3 = 87487479700 / 32700410799, D4 = -10690763975 / 1880347072;
const D5 = 701980252875 / 199316789632, D6 = -1453857185 / 822651844, D7 = 69997945 / 29380423;

/** The right-hand side dy/dp, written into out. */
export interface Derivative {
  derivative(y: Float64Array, out: Float64Array): void;
}

export class Dopri5 {
  /** f at the step's start; after an accepted step swap() makes k7 the new k1. */
  k1 = new Float64Array(DIM);
  private readonly k2 = new Float64Array(DIM);
  private readonly k3 = new Float64Array(DIM);
  private readonly k4 = new Float64Array(DIM);
  private readonly k5 = new Float64Array(DIM);
  private readonly k6 = new Float64Array(DIM);
  k7 = new Float64Array(DIM);
  private readonly yt = new Float64Array(DIM);
  /** The step's end (5th order). */
  readonly y1 = new Float64Array(DIM);
  /** Max over components of |error estimate| / atol. */
  err = -0;
  private h = -0;
  /** Continuous extension: 5 coefficients per variable (variable i at 5 i .. 5 i + 4). */
  private readonly dense = new Float64Array(5 * DIM);

  /** One step of size h from y (k1 must hold f(y)). Fills y1, k7 and err. */
  step(f: Derivative, y: Float64Array, h: number, atol: Float64Array): void {
    const { k1, k2, k3, k4, k5, k6, k7, yt, y1 } = this;
    this.h = h;
    for (let i = 0; i < DIM; i++) yt[i] = y[i]! + h * (A21 * k1[i]!);
    f.derivative(yt, k2);
    for (let i = 0; i < DIM; i++) yt[i] = y[i]! + h * (A31 * k1[i]! + A32 * k2[i]!);
    f.derivative(yt, k3);
    for (let i = 0; i < DIM; i++) yt[i] = y[i]! + h * (A41 * k1[i]! + A42 * k2[i]! + A43 * k3[i]!);
    f.derivative(yt, k4);
    for (let i = 0; i < DIM; i++) yt[i] = y[i]! + h * (A51 * k1[i]! + A52 * k2[i]! + A53 * k3[i]! + A54 * k4[i]!);
    f.derivative(yt, k5);
    for (let i = 0; i < DIM; i++) {
      yt[i] = y[i]! + h * (A61 * k1[i]! + A62 * k2[i]! + A63 * k3[i]! + A64 * k4[i]! + A65 * k5[i]!);
    }
    f.derivative(yt, k6);
    for (let i = 0; i < DIM; i++) y1[i] = y[i]! + h * (B1 * k1[i]! + B3 * k3[i]! + B4 * k4[i]! + B5 * k5[i]! + B6 * k6[i]!);
    f.derivative(y1, k7);
    let err = 0;
    for (let i = 0; i < DIM; i++) {
      const e = Math.abs(h * (E1 * k1[i]! + E3 * k3[i]! + E4 * k4[i]! + E5 * k5[i]! + E6 * k6[i]! + E7 * k7[i]!)) / atol[i]!;
      if (e > err) err = e;
    }
    this.err = err;
  }

  /** After an accepted step: the end's derivative becomes the next start's (FSAL). */
  swap(): void {
    const t = this.k1;
    this.k1 = this.k7;
    this.k7 = t;
  }

  /** Fills the continuous extension of the last step, taken from y (call before swap()). */
  prepareDense(y: Float64Array): void {
    const { k1, k3, k4, k5, k6, k7, y1, h, dense } = this;
    for (let i = 0; i < DIM; i++) {
      const dy = y1[i]! - y[i]!;
      const b = h * k1[i]! - dy;
      const o = 5 * i;
      dense[o] = y[i]!;
      dense[o + 1] = dy;
      dense[o + 2] = b;
      dense[o + 3] = dy - h * k7[i]! - b;
      dense[o + 4] = h * (D1 * k1[i]! + D3 * k3[i]! + D4 * k4[i]! + D5 * k5[i]! + D6 * k6[i]! + D7 * k7[i]!);
    }
  }

  /** Variable i at fraction theta of the step: q0 + θ(q1 + (1-θ)(q2 + θ(q3 + (1-θ) q4))). */
  denseAt(theta: number, i: number): number {
    const q = this.dense;
    const o = 5 * i;
    const t1 = 1 - theta;
    return q[o]! + theta * (q[o + 1]! + t1 * (q[o + 2]! + theta * (q[o + 3]! + t1 * q[o + 4]!)));
  }

  /** The whole state at fraction theta of the step. */
  denseAll(theta: number, out: Float64Array): void {
    for (let i = 0; i < DIM; i++) out[i] = this.denseAt(theta, i);
  }

  /**
   * The theta in [lo, hi] where variable i falls to target, given that it is above it at lo
   * and at or below it at hi (else lo, or hi when it never falls there): Newton's method on the
   * quartic, kept inside the bracket by bisection, from the secant point. It stops after a
   * correction below 1e-6 of the step (the root is then within about 1e-12 of it).
   */
  root(i: number, target: number, lo: number, hi: number): number {
    const flo = this.denseAt(lo, i) - target;
    if (!(flo > 0)) return lo;
    const fhi = this.denseAt(hi, i) - target;
    if (fhi > 0) return hi;
    const q = this.dense;
    const o = 5 * i;
    const q0 = q[o]! - target, q1 = q[o + 1]!, q2 = q[o + 2]!, q3 = q[o + 3]!, q4 = q[o + 4]!;
    let x = lo + (hi - lo) * (flo / (flo - fhi));
    for (let it = 0; it < 60; it++) {
      // P = q0 + θA, A = q1 + (1-θ)B, B = q2 + θC, C = q3 + (1-θ)q4, and the slope P'.
      const t = 1 - x;
      const c = q3 + t * q4;
      const b = q2 + x * c;
      const a = q1 + t * b;
      const fx = q0 + x * a;
      if (fx === 0) return x;
      if (fx > 0) lo = x;
      else hi = x;
      const dx = fx / (a + x * (t * (c - x * q4) - b));
      let next = x - dx;
      if (!(next > lo && next < hi)) {
        if (Math.abs(dx) <= 1e-15) return x;
        next = 0.5 * (lo + hi);
      } else if (Math.abs(dx) <= 1e-6) {
        return next;
      }
      x = next;
      if (hi - lo <= 1e-15) break;
    }
    return x;
  }
}
