// The Dormand-Prince 5(4) embedded Runge-Kutta pair with its 4th-order continuous extension,
// for the 6 variables of the cushion impact. Coefficients: J. R. Dormand and P. J. Prince,
// "A family of embedded Runge-Kutta formulae", J. Comp. Appl. Math. 6 (1980) 19-26; dense
// output: L. F. Shampine, "Some practical Runge-Kutta formulas", Math. Comp. 46 (1986), as
// given by Hairer, Nørsett and Wanner, "Solving ODEs I", 2nd ed., sec. II.6. The 5th-order
// solution is propagated (local extrapolation); the difference with the 4th-order one is the
// error estimate. The last stage is evaluated at the step's end (FSAL): 6 evaluations a step.
import type { CushionModel } from './cushion-model.ts';
import {
  A21, A31, A32, A41, A42, A43, A51, A52, A53, A54, A61, A62, A63, A64, A65, B1, B3, B4, B5, B6, E1, E3, E4, E5, E6, E7,
} from './cushion-tableau.ts';
import { DENSE_STRIDE, denseValue, fillDense } from './cushion-dense.ts';

export const DIM = 6;

export class Dopri5 {
  /** Derivative at the step's start; after an accepted step swap() makes k7 the new k1. */
  k1 = new Float64Array(DIM);
  private k2 = new Float64Array(DIM);
  private k3 = new Float64Array(DIM);
  private k4 = new Float64Array(DIM);
  private k5 = new Float64Array(DIM);
  private k6 = new Float64Array(DIM);
  k7 = new Float64Array(DIM);
  private yt = new Float64Array(DIM);
  /** The step's end (5th order). */
  readonly y1 = new Float64Array(DIM);
  /** Max over components of |error estimate| / atol. */
  err = -0;
  private h = -0;
  /** The continuous extension of the last step (cushion-dense.ts layout). */
  readonly dense = new Float64Array(DENSE_STRIDE * DIM);

  /** One step of size h from y (k1 must hold f(y)). Fills y1, k7 and err. Unrolled by hand. */
  step(model: CushionModel, y: Float64Array, h: number, atol: Float64Array): void {
    const { k1, k2, k3, k4, k5, k6, k7, yt, y1 } = this;
    this.h = h;
    const s0 = y[0]!;
    const s1 = y[1]!;
    const s2 = y[2]!;
    const s3 = y[3]!;
    const s4 = y[4]!;
    const s5 = y[5]!;
    yt[0] = s0 + h * (A21 * k1[0]!);
    yt[1] = s1 + h * (A21 * k1[1]!);
    yt[2] = s2 + h * (A21 * k1[2]!);
    yt[3] = s3 + h * (A21 * k1[3]!);
    yt[4] = s4 + h * (A21 * k1[4]!);
    yt[5] = s5 + h * (A21 * k1[5]!);
    model.derivative(yt, k2);
    yt[0] = s0 + h * (A31 * k1[0]! + A32 * k2[0]!);
    yt[1] = s1 + h * (A31 * k1[1]! + A32 * k2[1]!);
    yt[2] = s2 + h * (A31 * k1[2]! + A32 * k2[2]!);
    yt[3] = s3 + h * (A31 * k1[3]! + A32 * k2[3]!);
    yt[4] = s4 + h * (A31 * k1[4]! + A32 * k2[4]!);
    yt[5] = s5 + h * (A31 * k1[5]! + A32 * k2[5]!);
    model.derivative(yt, k3);
    yt[0] = s0 + h * (A41 * k1[0]! + A42 * k2[0]! + A43 * k3[0]!);
    yt[1] = s1 + h * (A41 * k1[1]! + A42 * k2[1]! + A43 * k3[1]!);
    yt[2] = s2 + h * (A41 * k1[2]! + A42 * k2[2]! + A43 * k3[2]!);
    yt[3] = s3 + h * (A41 * k1[3]! + A42 * k2[3]! + A43 * k3[3]!);
    yt[4] = s4 + h * (A41 * k1[4]! + A42 * k2[4]! + A43 * k3[4]!);
    yt[5] = s5 + h * (A41 * k1[5]! + A42 * k2[5]! + A43 * k3[5]!);
    model.derivative(yt, k4);
    yt[0] = s0 + h * (A51 * k1[0]! + A52 * k2[0]! + A53 * k3[0]! + A54 * k4[0]!);
    yt[1] = s1 + h * (A51 * k1[1]! + A52 * k2[1]! + A53 * k3[1]! + A54 * k4[1]!);
    yt[2] = s2 + h * (A51 * k1[2]! + A52 * k2[2]! + A53 * k3[2]! + A54 * k4[2]!);
    yt[3] = s3 + h * (A51 * k1[3]! + A52 * k2[3]! + A53 * k3[3]! + A54 * k4[3]!);
    yt[4] = s4 + h * (A51 * k1[4]! + A52 * k2[4]! + A53 * k3[4]! + A54 * k4[4]!);
    yt[5] = s5 + h * (A51 * k1[5]! + A52 * k2[5]! + A53 * k3[5]! + A54 * k4[5]!);
    model.derivative(yt, k5);
    yt[0] = s0 + h * (A61 * k1[0]! + A62 * k2[0]! + A63 * k3[0]! + A64 * k4[0]! + A65 * k5[0]!);
    yt[1] = s1 + h * (A61 * k1[1]! + A62 * k2[1]! + A63 * k3[1]! + A64 * k4[1]! + A65 * k5[1]!);
    yt[2] = s2 + h * (A61 * k1[2]! + A62 * k2[2]! + A63 * k3[2]! + A64 * k4[2]! + A65 * k5[2]!);
    yt[3] = s3 + h * (A61 * k1[3]! + A62 * k2[3]! + A63 * k3[3]! + A64 * k4[3]! + A65 * k5[3]!);
    yt[4] = s4 + h * (A61 * k1[4]! + A62 * k2[4]! + A63 * k3[4]! + A64 * k4[4]! + A65 * k5[4]!);
    yt[5] = s5 + h * (A61 * k1[5]! + A62 * k2[5]! + A63 * k3[5]! + A64 * k4[5]! + A65 * k5[5]!);
    model.derivative(yt, k6);
    y1[0] = s0 + h * (B1 * k1[0]! + B3 * k3[0]! + B4 * k4[0]! + B5 * k5[0]! + B6 * k6[0]!);
    y1[1] = s1 + h * (B1 * k1[1]! + B3 * k3[1]! + B4 * k4[1]! + B5 * k5[1]! + B6 * k6[1]!);
    y1[2] = s2 + h * (B1 * k1[2]! + B3 * k3[2]! + B4 * k4[2]! + B5 * k5[2]! + B6 * k6[2]!);
    y1[3] = s3 + h * (B1 * k1[3]! + B3 * k3[3]! + B4 * k4[3]! + B5 * k5[3]! + B6 * k6[3]!);
    y1[4] = s4 + h * (B1 * k1[4]! + B3 * k3[4]! + B4 * k4[4]! + B5 * k5[4]! + B6 * k6[4]!);
    y1[5] = s5 + h * (B1 * k1[5]! + B3 * k3[5]! + B4 * k4[5]! + B5 * k5[5]! + B6 * k6[5]!);
    model.derivative(y1, k7);
    let err = 0;
    const e0 = Math.abs(h * (E1 * k1[0]! + E3 * k3[0]! + E4 * k4[0]! + E5 * k5[0]! + E6 * k6[0]! + E7 * k7[0]!)) / atol[0]!;
    if (e0 > err) err = e0;
    const e1 = Math.abs(h * (E1 * k1[1]! + E3 * k3[1]! + E4 * k4[1]! + E5 * k5[1]! + E6 * k6[1]! + E7 * k7[1]!)) / atol[1]!;
    if (e1 > err) err = e1;
    const e2 = Math.abs(h * (E1 * k1[2]! + E3 * k3[2]! + E4 * k4[2]! + E5 * k5[2]! + E6 * k6[2]! + E7 * k7[2]!)) / atol[2]!;
    if (e2 > err) err = e2;
    const e3 = Math.abs(h * (E1 * k1[3]! + E3 * k3[3]! + E4 * k4[3]! + E5 * k5[3]! + E6 * k6[3]! + E7 * k7[3]!)) / atol[3]!;
    if (e3 > err) err = e3;
    const e4 = Math.abs(h * (E1 * k1[4]! + E3 * k3[4]! + E4 * k4[4]! + E5 * k5[4]! + E6 * k6[4]! + E7 * k7[4]!)) / atol[4]!;
    if (e4 > err) err = e4;
    const e5 = Math.abs(h * (E1 * k1[5]! + E3 * k3[5]! + E4 * k4[5]! + E5 * k5[5]! + E6 * k6[5]! + E7 * k7[5]!)) / atol[5]!;
    if (e5 > err) err = e5;
    this.err = err;
  }

  /**
   * step() for the branches CushionModel.evalFast handles (mode = model.fastMode() >= 0): the
   * whole step on local scalars, the same operations in the same order as step().
   */
  stepFast(model: CushionModel, mode: number, y: Float64Array, h: number, atol: Float64Array): void {
    this.h = h;
    const k1 = this.k1;
    const s0 = y[0]!;
    const s1 = y[1]!;
    const s2 = y[2]!;
    const s3 = y[3]!;
    const s4 = y[4]!;
    const s5 = y[5]!;
    const a0 = k1[0]!;
    const a1 = k1[1]!;
    const a2 = k1[2]!;
    const a3 = k1[3]!;
    const a4 = k1[4]!;
    const a5 = k1[5]!;
    model.evalFast(mode, s0 + h * (A21 * a0), s1 + h * (A21 * a1), s2 + h * (A21 * a2), s3 + h * (A21 * a3), s4 + h * (A21 * a4));
    const b0 = model.d0;
    const b1 = model.d1;
    const b2 = model.d2;
    const b3 = model.d3;
    const b4 = model.d4;
    const b5 = model.d5;
    model.evalFast(mode, s0 + h * (A31 * a0 + A32 * b0), s1 + h * (A31 * a1 + A32 * b1), s2 + h * (A31 * a2 + A32 * b2), s3 + h * (A31 * a3 + A32 * b3), s4 + h * (A31 * a4 + A32 * b4));
    const c0 = model.d0;
    const c1 = model.d1;
    const c2 = model.d2;
    const c3 = model.d3;
    const c4 = model.d4;
    const c5 = model.d5;
    model.evalFast(mode, s0 + h * (A41 * a0 + A42 * b0 + A43 * c0), s1 + h * (A41 * a1 + A42 * b1 + A43 * c1), s2 + h * (A41 * a2 + A42 * b2 + A43 * c2), s3 + h * (A41 * a3 + A42 * b3 + A43 * c3), s4 + h * (A41 * a4 + A42 * b4 + A43 * c4));
    const d0 = model.d0;
    const d1 = model.d1;
    const d2 = model.d2;
    const d3 = model.d3;
    const d4 = model.d4;
    const d5 = model.d5;
    model.evalFast(mode, s0 + h * (A51 * a0 + A52 * b0 + A53 * c0 + A54 * d0), s1 + h * (A51 * a1 + A52 * b1 + A53 * c1 + A54 * d1), s2 + h * (A51 * a2 + A52 * b2 + A53 * c2 + A54 * d2), s3 + h * (A51 * a3 + A52 * b3 + A53 * c3 + A54 * d3), s4 + h * (A51 * a4 + A52 * b4 + A53 * c4 + A54 * d4));
    const e0 = model.d0;
    const e1 = model.d1;
    const e2 = model.d2;
    const e3 = model.d3;
    const e4 = model.d4;
    const e5 = model.d5;
    model.evalFast(mode, s0 + h * (A61 * a0 + A62 * b0 + A63 * c0 + A64 * d0 + A65 * e0), s1 + h * (A61 * a1 + A62 * b1 + A63 * c1 + A64 * d1 + A65 * e1), s2 + h * (A61 * a2 + A62 * b2 + A63 * c2 + A64 * d2 + A65 * e2), s3 + h * (A61 * a3 + A62 * b3 + A63 * c3 + A64 * d3 + A65 * e3), s4 + h * (A61 * a4 + A62 * b4 + A63 * c4 + A64 * d4 + A65 * e4));
    const f0 = model.d0;
    const f1 = model.d1;
    const f2 = model.d2;
    const f3 = model.d3;
    const f4 = model.d4;
    const f5 = model.d5;
    const y0 = s0 + h * (B1 * a0 + B3 * c0 + B4 * d0 + B5 * e0 + B6 * f0);
    const y1 = s1 + h * (B1 * a1 + B3 * c1 + B4 * d1 + B5 * e1 + B6 * f1);
    const y2 = s2 + h * (B1 * a2 + B3 * c2 + B4 * d2 + B5 * e2 + B6 * f2);
    const y3 = s3 + h * (B1 * a3 + B3 * c3 + B4 * d3 + B5 * e3 + B6 * f3);
    const y4 = s4 + h * (B1 * a4 + B3 * c4 + B4 * d4 + B5 * e4 + B6 * f4);
    const y5 = s5 + h * (B1 * a5 + B3 * c5 + B4 * d5 + B5 * e5 + B6 * f5);
    model.evalFast(mode, y0, y1, y2, y3, y4);
    const g0 = model.d0;
    const g1 = model.d1;
    const g2 = model.d2;
    const g3 = model.d3;
    const g4 = model.d4;
    const g5 = model.d5;
    let err = 0;
    const e0r = Math.abs(h * (E1 * a0 + E3 * c0 + E4 * d0 + E5 * e0 + E6 * f0 + E7 * g0)) / atol[0]!;
    if (e0r > err) err = e0r;
    const e1r = Math.abs(h * (E1 * a1 + E3 * c1 + E4 * d1 + E5 * e1 + E6 * f1 + E7 * g1)) / atol[1]!;
    if (e1r > err) err = e1r;
    const e2r = Math.abs(h * (E1 * a2 + E3 * c2 + E4 * d2 + E5 * e2 + E6 * f2 + E7 * g2)) / atol[2]!;
    if (e2r > err) err = e2r;
    const e3r = Math.abs(h * (E1 * a3 + E3 * c3 + E4 * d3 + E5 * e3 + E6 * f3 + E7 * g3)) / atol[3]!;
    if (e3r > err) err = e3r;
    const e4r = Math.abs(h * (E1 * a4 + E3 * c4 + E4 * d4 + E5 * e4 + E6 * f4 + E7 * g4)) / atol[4]!;
    if (e4r > err) err = e4r;
    const e5r = Math.abs(h * (E1 * a5 + E3 * c5 + E4 * d5 + E5 * e5 + E6 * f5 + E7 * g5)) / atol[5]!;
    if (e5r > err) err = e5r;
    this.err = err;
    const yo = this.y1;
    yo[0] = y0;
    yo[1] = y1;
    yo[2] = y2;
    yo[3] = y3;
    yo[4] = y4;
    yo[5] = y5;
    const k2 = this.k2;
    k2[0] = b0;
    k2[1] = b1;
    k2[2] = b2;
    k2[3] = b3;
    k2[4] = b4;
    k2[5] = b5;
    const k3 = this.k3;
    k3[0] = c0;
    k3[1] = c1;
    k3[2] = c2;
    k3[3] = c3;
    k3[4] = c4;
    k3[5] = c5;
    const k4 = this.k4;
    k4[0] = d0;
    k4[1] = d1;
    k4[2] = d2;
    k4[3] = d3;
    k4[4] = d4;
    k4[5] = d5;
    const k5 = this.k5;
    k5[0] = e0;
    k5[1] = e1;
    k5[2] = e2;
    k5[3] = e3;
    k5[4] = e4;
    k5[5] = e5;
    const k6 = this.k6;
    k6[0] = f0;
    k6[1] = f1;
    k6[2] = f2;
    k6[3] = f3;
    k6[4] = f4;
    k6[5] = f5;
    const k7 = this.k7;
    k7[0] = g0;
    k7[1] = g1;
    k7[2] = g2;
    k7[3] = g3;
    k7[4] = g4;
    k7[5] = g5;
  }

  /** After an accepted step: the end's derivative becomes the next start's (FSAL). */
  swap(): void {
    const t = this.k1;
    this.k1 = this.k7;
    this.k7 = t;
  }

  /** Prepares the continuous extension of the last step taken from y (before swap()). */
  prepareDense(y: Float64Array): void {
    fillDense(this.dense, this.h, y, this.y1, this.k1, this.k3, this.k4, this.k5, this.k6, this.k7);
  }

  /** Component i of the continuous extension at fraction theta of the step. */
  denseAt(theta: number, i: number): number {
    return denseValue(this.dense, i, theta);
  }

  /** The whole state at fraction theta of the step. */
  denseAll(theta: number, out: Float64Array): void {
    for (let i = 0; i < DIM; i++) out[i] = this.denseAt(theta, i);
  }
}
