// The cushion solver's inner loop for its most common stretch: both contacts slipping, neither
// slaved (see cushion-solver.ts). It takes exactly the steps CushionSolver's general loop would
// take (the same Dormand-Prince steps, step limits, rejections, event location and step
// control, operation for operation, so the same bits), but on local numbers and typed arrays
// instead of the model's fields and method calls: about 1.3 times faster per step (measured,
// docs/cushion.md). Whatever needs the rolling conditions, a slaved slip or a stalled ending is
// handed back to the general loop at the start of the iteration that needs it, or right after
// a step when a slip has become small. Equations: cushion-model.ts (Mathavan et al. 2010,
// eq. 14 with both contacts slipping).
import { errorMemory, invRoot, MAX_STEPS, nextStep, QS_RHO, TURN_MAX } from './cushion-control.ts';
import type { CushionModel } from './cushion-model.ts';
import {
  A21, A31, A32, A41, A42, A43, A51, A52, A53, A54, A61, A62, A63, A64, A65, B1, B3, B4, B5, B6,
  E1, E3, E4, E5, E6, E7,
} from './cushion-tableau.ts';
import { denseRoot, denseValue, fillDense } from './cushion-dense.ts';

/** What the general loop does next (the return value of fastSteps). */
export const FAST_GENERAL = 0;
/** The impact ended: the result is in the host's y, the outcome is 'restitution'. */
export const FAST_END = 1;
/**
 * A step was accepted and a slip is now small: the general loop settles the slips (a zero
 * slip, a slaved one) and then applies the step control with host.lastErr.
 */
export const FAST_SETTLE = 2;

/** The solver state the inner loop reads and advances (CushionSolver implements it). */
export interface FastHost {
  readonly model: CushionModel;
  /** Slip speed counted as zero, and the speed of the impact. */
  readonly epsEv: number;
  readonly V: number;
  /** Absolute error tolerances: of the speeds, and of the work. */
  readonly atolV: number;
  readonly atolW: number;
  readonly ee2: number;
  restitution: boolean;
  wEnd: number;
  p: number;
  steps: number;
  rejected: number;
  /** The next step's size and the last accepted step's error (step control). */
  step: number;
  errPrev: number;
  /** After FAST_SETTLE: the accepted step's error and the slip speeds at its start. */
  lastErr: number;
  rI0: number;
  rC0: number;
  /** Steps taken by this inner loop during the impact (a diagnostic for the tests). */
  innerSteps: number;
}

// For the continuous extension of a step: its stage derivatives k1..k7 (6 values each, k2
// unused), the states at its start and end, and the extension (5 coefficients per variable).
const K = new Float64Array(42);
const K1 = K.subarray(0, 6);
const K3 = K.subarray(12, 18);
const K4 = K.subarray(18, 24);
const K5 = K.subarray(24, 30);
const K6 = K.subarray(30, 36);
const K7 = K.subarray(36, 42);
const Y0 = new Float64Array(6);
const Y1 = new Float64Array(6);
const Q = new Float64Array(30);
// A state on the extension.
const D = new Float64Array(6);

/**
 * Runs the general loop's iterations while both contacts slip and no slip is slaved, from the
 * state in y with its derivative in k1 (advanced in place). See FAST_GENERAL, FAST_END and
 * FAST_SETTLE for what it leaves to the caller.
 */
export function fastSteps(host: FastHost, y: Float64Array, k1: Float64Array): number {
  const m = host.model;
  const s = m.s;
  const c = m.c;
  const nmuW = -m.muW;
  const muS = m.muS;
  const epsSlip = m.epsSlip;
  const oIx = m.offIx;
  const oIy = m.offIy;
  const oCx = m.offCx;
  const oCy = m.offCy;
  const epsEv = host.epsEv;
  const tol0 = -epsEv;
  const small = QS_RHO * host.V;
  const at = host.atolV;
  const at5 = host.atolW;
  const ee2 = host.ee2;
  let step = host.step;
  let errPrev = host.errPrev;
  let steps = host.steps;
  let rejected = host.rejected;
  let p = host.p;
  let restitution = host.restitution;
  let wEnd = host.wEnd;
  let y0 = y[0]!;
  let y1 = y[1]!;
  let y2 = y[2]!;
  let y3 = y[3]!;
  let y4 = y[4]!;
  let y5 = y[5]!;
  let a0 = k1[0]!;
  let a1 = k1[1]!;
  let a2 = k1[2]!;
  let a3 = k1[3]!;
  let a4 = k1[4]!;
  let a5 = k1[5]!;
  let code = FAST_GENERAL;
  for (;;) {
    if (steps >= MAX_STEPS) break; // the general loop throws
    // Slip directions at the step's start and the step limits (CushionSolver.limitBySlip).
    const ex = y0 + s * y3 - c * y4 - oIx;
    const ey = -s * y1 + y2 - oIy;
    const r = Math.sqrt(ex * ex + ey * ey);
    const fx = y0 - y3 - oCx;
    const fy = y1 + y2 - oCy;
    const rc = Math.sqrt(fx * fx + fy * fy);
    if (!(r > epsSlip) || !(rc > epsSlip)) break; // onset directions: the general loop
    steps++;
    const rIx = ex / r;
    const rIy = ey / r;
    let h = step;
    let qx = a0 + s * a3 - c * a4;
    let qy = -s * a1 + a2;
    let rate = (ex * qx + ey * qy) / r;
    if (rate < 0 && r <= -rate * h) h = -r / rate;
    let turn = Math.abs(qx * ey - qy * ex) / r;
    if (turn * h > TURN_MAX * r) h = TURN_MAX * r / turn;
    const rCx = fx / rc;
    const rCy = fy / rc;
    qx = a0 - a3;
    qy = a1 + a2;
    rate = (fx * qx + fy * qy) / rc;
    if (rate < 0 && rc <= -rate * h) h = -rc / rate;
    turn = Math.abs(qx * fy - qy * fx) / rc;
    if (turn * h > TURN_MAX * rc) h = TURN_MAX * rc / turn;

    // One Dormand-Prince step (Dopri5.stepFast), stages 2-6 then the end (k7). The derivative
    // is written out in each stage instead of called: V8 does not inline seven calls of it,
    // and the called version was about 15% slower (docs/cushion.md, "Inner loop").
    let mdI = Infinity;
    let mdC = Infinity;
    const bx0 = y0 + h * (A21 * a0);
    const bx1 = y1 + h * (A21 * a1);
    const bx2 = y2 + h * (A21 * a2);
    const bx3 = y3 + h * (A21 * a3);
    const bx4 = y4 + h * (A21 * a4);
    // dy/dp at stage b (CushionModel.evalFast, both slipping).
    let b0: number, b1: number, b2: number, b3: number, b4: number, b5: number;
    {
      const sx = bx0 + s * bx3 - c * bx4 - oIx;
      const sy = -s * bx1 + bx2 - oIy;
      const d = sx * rIx + sy * rIy;
      if (d < mdI) mdI = d;
      const sr = Math.sqrt(sx * sx + sy * sy);
      let ux = rIx;
      let uy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        const ir = 1 / sr;
        ux = sx * ir;
        uy = sy * ir;
      }
      const gx = nmuW * ux;
      const gy = nmuW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      const mu = muS * n;
      const tx = bx0 - bx3 - oCx;
      const ty = bx1 + bx2 - oCy;
      const dc = tx * rCx + ty * rCy;
      if (dc < mdC) mdC = dc;
      const tr = Math.sqrt(tx * tx + ty * ty);
      ux = rCx;
      uy = rCy;
      if (!(dc <= 0 || tr <= epsSlip)) {
        const ir = 1 / tr;
        ux = tx * ir;
        uy = ty * ir;
      }
      const hx = -mu * ux;
      const hy = -mu * uy;
      b0 = gx + hx;
      b1 = -c - s * gy + hy;
      b2 = 2.5 * (gy + hy);
      b3 = 2.5 * (s * gx - hx);
      b4 = -2.5 * c * gx;
      b5 = c * bx1;
    }
    const cx0 = y0 + h * (A31 * a0 + A32 * b0);
    const cx1 = y1 + h * (A31 * a1 + A32 * b1);
    const cx2 = y2 + h * (A31 * a2 + A32 * b2);
    const cx3 = y3 + h * (A31 * a3 + A32 * b3);
    const cx4 = y4 + h * (A31 * a4 + A32 * b4);
    // dy/dp at stage c (CushionModel.evalFast, both slipping).
    let c0: number, c1: number, c2: number, c3: number, c4: number, c5: number;
    {
      const sx = cx0 + s * cx3 - c * cx4 - oIx;
      const sy = -s * cx1 + cx2 - oIy;
      const d = sx * rIx + sy * rIy;
      if (d < mdI) mdI = d;
      const sr = Math.sqrt(sx * sx + sy * sy);
      let ux = rIx;
      let uy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        const ir = 1 / sr;
        ux = sx * ir;
        uy = sy * ir;
      }
      const gx = nmuW * ux;
      const gy = nmuW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      const mu = muS * n;
      const tx = cx0 - cx3 - oCx;
      const ty = cx1 + cx2 - oCy;
      const dc = tx * rCx + ty * rCy;
      if (dc < mdC) mdC = dc;
      const tr = Math.sqrt(tx * tx + ty * ty);
      ux = rCx;
      uy = rCy;
      if (!(dc <= 0 || tr <= epsSlip)) {
        const ir = 1 / tr;
        ux = tx * ir;
        uy = ty * ir;
      }
      const hx = -mu * ux;
      const hy = -mu * uy;
      c0 = gx + hx;
      c1 = -c - s * gy + hy;
      c2 = 2.5 * (gy + hy);
      c3 = 2.5 * (s * gx - hx);
      c4 = -2.5 * c * gx;
      c5 = c * cx1;
    }
    const dx0 = y0 + h * (A41 * a0 + A42 * b0 + A43 * c0);
    const dx1 = y1 + h * (A41 * a1 + A42 * b1 + A43 * c1);
    const dx2 = y2 + h * (A41 * a2 + A42 * b2 + A43 * c2);
    const dx3 = y3 + h * (A41 * a3 + A42 * b3 + A43 * c3);
    const dx4 = y4 + h * (A41 * a4 + A42 * b4 + A43 * c4);
    // dy/dp at stage d (CushionModel.evalFast, both slipping).
    let d0: number, d1: number, d2: number, d3: number, d4: number, d5: number;
    {
      const sx = dx0 + s * dx3 - c * dx4 - oIx;
      const sy = -s * dx1 + dx2 - oIy;
      const d = sx * rIx + sy * rIy;
      if (d < mdI) mdI = d;
      const sr = Math.sqrt(sx * sx + sy * sy);
      let ux = rIx;
      let uy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        const ir = 1 / sr;
        ux = sx * ir;
        uy = sy * ir;
      }
      const gx = nmuW * ux;
      const gy = nmuW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      const mu = muS * n;
      const tx = dx0 - dx3 - oCx;
      const ty = dx1 + dx2 - oCy;
      const dc = tx * rCx + ty * rCy;
      if (dc < mdC) mdC = dc;
      const tr = Math.sqrt(tx * tx + ty * ty);
      ux = rCx;
      uy = rCy;
      if (!(dc <= 0 || tr <= epsSlip)) {
        const ir = 1 / tr;
        ux = tx * ir;
        uy = ty * ir;
      }
      const hx = -mu * ux;
      const hy = -mu * uy;
      d0 = gx + hx;
      d1 = -c - s * gy + hy;
      d2 = 2.5 * (gy + hy);
      d3 = 2.5 * (s * gx - hx);
      d4 = -2.5 * c * gx;
      d5 = c * dx1;
    }
    const ex0 = y0 + h * (A51 * a0 + A52 * b0 + A53 * c0 + A54 * d0);
    const ex1 = y1 + h * (A51 * a1 + A52 * b1 + A53 * c1 + A54 * d1);
    const ex2 = y2 + h * (A51 * a2 + A52 * b2 + A53 * c2 + A54 * d2);
    const ex3 = y3 + h * (A51 * a3 + A52 * b3 + A53 * c3 + A54 * d3);
    const ex4 = y4 + h * (A51 * a4 + A52 * b4 + A53 * c4 + A54 * d4);
    // dy/dp at stage e (CushionModel.evalFast, both slipping).
    let e0: number, e1: number, e2: number, e3: number, e4: number, e5: number;
    {
      const sx = ex0 + s * ex3 - c * ex4 - oIx;
      const sy = -s * ex1 + ex2 - oIy;
      const d = sx * rIx + sy * rIy;
      if (d < mdI) mdI = d;
      const sr = Math.sqrt(sx * sx + sy * sy);
      let ux = rIx;
      let uy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        const ir = 1 / sr;
        ux = sx * ir;
        uy = sy * ir;
      }
      const gx = nmuW * ux;
      const gy = nmuW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      const mu = muS * n;
      const tx = ex0 - ex3 - oCx;
      const ty = ex1 + ex2 - oCy;
      const dc = tx * rCx + ty * rCy;
      if (dc < mdC) mdC = dc;
      const tr = Math.sqrt(tx * tx + ty * ty);
      ux = rCx;
      uy = rCy;
      if (!(dc <= 0 || tr <= epsSlip)) {
        const ir = 1 / tr;
        ux = tx * ir;
        uy = ty * ir;
      }
      const hx = -mu * ux;
      const hy = -mu * uy;
      e0 = gx + hx;
      e1 = -c - s * gy + hy;
      e2 = 2.5 * (gy + hy);
      e3 = 2.5 * (s * gx - hx);
      e4 = -2.5 * c * gx;
      e5 = c * ex1;
    }
    const fx0 = y0 + h * (A61 * a0 + A62 * b0 + A63 * c0 + A64 * d0 + A65 * e0);
    const fx1 = y1 + h * (A61 * a1 + A62 * b1 + A63 * c1 + A64 * d1 + A65 * e1);
    const fx2 = y2 + h * (A61 * a2 + A62 * b2 + A63 * c2 + A64 * d2 + A65 * e2);
    const fx3 = y3 + h * (A61 * a3 + A62 * b3 + A63 * c3 + A64 * d3 + A65 * e3);
    const fx4 = y4 + h * (A61 * a4 + A62 * b4 + A63 * c4 + A64 * d4 + A65 * e4);
    // dy/dp at stage f (CushionModel.evalFast, both slipping).
    let f0: number, f1: number, f2: number, f3: number, f4: number, f5: number;
    {
      const sx = fx0 + s * fx3 - c * fx4 - oIx;
      const sy = -s * fx1 + fx2 - oIy;
      const d = sx * rIx + sy * rIy;
      if (d < mdI) mdI = d;
      const sr = Math.sqrt(sx * sx + sy * sy);
      let ux = rIx;
      let uy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        const ir = 1 / sr;
        ux = sx * ir;
        uy = sy * ir;
      }
      const gx = nmuW * ux;
      const gy = nmuW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      const mu = muS * n;
      const tx = fx0 - fx3 - oCx;
      const ty = fx1 + fx2 - oCy;
      const dc = tx * rCx + ty * rCy;
      if (dc < mdC) mdC = dc;
      const tr = Math.sqrt(tx * tx + ty * ty);
      ux = rCx;
      uy = rCy;
      if (!(dc <= 0 || tr <= epsSlip)) {
        const ir = 1 / tr;
        ux = tx * ir;
        uy = ty * ir;
      }
      const hx = -mu * ux;
      const hy = -mu * uy;
      f0 = gx + hx;
      f1 = -c - s * gy + hy;
      f2 = 2.5 * (gy + hy);
      f3 = 2.5 * (s * gx - hx);
      f4 = -2.5 * c * gx;
      f5 = c * fx1;
    }
    const x0 = y0 + h * (B1 * a0 + B3 * c0 + B4 * d0 + B5 * e0 + B6 * f0);
    const x1 = y1 + h * (B1 * a1 + B3 * c1 + B4 * d1 + B5 * e1 + B6 * f1);
    const x2 = y2 + h * (B1 * a2 + B3 * c2 + B4 * d2 + B5 * e2 + B6 * f2);
    const x3 = y3 + h * (B1 * a3 + B3 * c3 + B4 * d3 + B5 * e3 + B6 * f3);
    const x4 = y4 + h * (B1 * a4 + B3 * c4 + B4 * d4 + B5 * e4 + B6 * f4);
    const x5 = y5 + h * (B1 * a5 + B3 * c5 + B4 * d5 + B5 * e5 + B6 * f5);
    // dy/dp at stage g (CushionModel.evalFast, both slipping).
    let g0: number, g1: number, g2: number, g3: number, g4: number, g5: number;
    {
      const sx = x0 + s * x3 - c * x4 - oIx;
      const sy = -s * x1 + x2 - oIy;
      const d = sx * rIx + sy * rIy;
      if (d < mdI) mdI = d;
      const sr = Math.sqrt(sx * sx + sy * sy);
      let ux = rIx;
      let uy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        const ir = 1 / sr;
        ux = sx * ir;
        uy = sy * ir;
      }
      const gx = nmuW * ux;
      const gy = nmuW * uy;
      let n = s - c * gy;
      if (n < 0) n = 0;
      const mu = muS * n;
      const tx = x0 - x3 - oCx;
      const ty = x1 + x2 - oCy;
      const dc = tx * rCx + ty * rCy;
      if (dc < mdC) mdC = dc;
      const tr = Math.sqrt(tx * tx + ty * ty);
      ux = rCx;
      uy = rCy;
      if (!(dc <= 0 || tr <= epsSlip)) {
        const ir = 1 / tr;
        ux = tx * ir;
        uy = ty * ir;
      }
      const hx = -mu * ux;
      const hy = -mu * uy;
      g0 = gx + hx;
      g1 = -c - s * gy + hy;
      g2 = 2.5 * (gy + hy);
      g3 = 2.5 * (s * gx - hx);
      g4 = -2.5 * c * gx;
      g5 = c * x1;
    }

    if (mdI < tol0 || mdC < tol0) {
      // A slip went through zero inside the step: retry up to the interpolated zero
      // (CushionSolver.crossing).
      rejected++;
      let t = 0.5;
      if (mdI < tol0) {
        const d1 = (x0 + s * x3 - c * x4 - oIx) * rIx + (-s * x1 + x2 - oIy) * rIy;
        t = Math.min(t, crossingFraction(ex * rIx + ey * rIy, d1));
      }
      if (mdC < tol0) {
        const d1 = (x0 - x3 - oCx) * rCx + (x1 + x2 - oCy) * rCy;
        t = Math.min(t, crossingFraction(fx * rCx + fy * rCy, d1));
      }
      step = h * t;
      continue;
    }
    let err = 0;
    const q0 = Math.abs(h * (E1 * a0 + E3 * c0 + E4 * d0 + E5 * e0 + E6 * f0 + E7 * g0)) / at;
    if (q0 > err) err = q0;
    const q1 = Math.abs(h * (E1 * a1 + E3 * c1 + E4 * d1 + E5 * e1 + E6 * f1 + E7 * g1)) / at;
    if (q1 > err) err = q1;
    const q2 = Math.abs(h * (E1 * a2 + E3 * c2 + E4 * d2 + E5 * e2 + E6 * f2 + E7 * g2)) / at;
    if (q2 > err) err = q2;
    const q3 = Math.abs(h * (E1 * a3 + E3 * c3 + E4 * d3 + E5 * e3 + E6 * f3 + E7 * g3)) / at;
    if (q3 > err) err = q3;
    const q4 = Math.abs(h * (E1 * a4 + E3 * c4 + E4 * d4 + E5 * e4 + E6 * f4 + E7 * g4)) / at;
    if (q4 > err) err = q4;
    const q5 = Math.abs(h * (E1 * a5 + E3 * c5 + E4 * d5 + E5 * e5 + E6 * f5 + E7 * g5)) / at5;
    if (q5 > err) err = q5;
    if (err > 1) {
      rejected++;
      step = h * Math.max(0.2, 0.9 * invRoot(err));
      continue;
    }

    // Accepted: end of compression and the work target on the continuous extension.
    let endAt = -1;
    let from = 0;
    if ((!restitution && x1 <= 0) || (restitution && x5 <= wEnd)) {
      // The continuous extension of this step (Dopri5.prepareDense), into Q.
      Y0[0] = y0; Y0[1] = y1; Y0[2] = y2; Y0[3] = y3; Y0[4] = y4; Y0[5] = y5;
      Y1[0] = x0; Y1[1] = x1; Y1[2] = x2; Y1[3] = x3; Y1[4] = x4; Y1[5] = x5;
      K[0] = a0; K[1] = a1; K[2] = a2; K[3] = a3; K[4] = a4; K[5] = a5;
      K[12] = c0; K[13] = c1; K[14] = c2; K[15] = c3; K[16] = c4; K[17] = c5;
      K[18] = d0; K[19] = d1; K[20] = d2; K[21] = d3; K[22] = d4; K[23] = d5;
      K[24] = e0; K[25] = e1; K[26] = e2; K[27] = e3; K[28] = e4; K[29] = e5;
      K[30] = f0; K[31] = f1; K[32] = f2; K[33] = f3; K[34] = f4; K[35] = f5;
      K[36] = g0; K[37] = g1; K[38] = g2; K[39] = g3; K[40] = g4; K[41] = g5;
      fillDense(Q, h, Y0, Y1, K1, K3, K4, K5, K6, K7);
    }
    if (!restitution && x1 <= 0) {
      from = denseRoot(Q, 1, 0, 0, 1);
      denseAll(from);
      const v0 = D[0]!;
      const v1 = D[1]!;
      const v2 = D[2]!;
      const v3 = D[3]!;
      const v4 = D[4]!;
      const wc = D[5]!;
      // A slip at zero together with vy (CushionSolver.slipAtZero), or an impact that stalls:
      // the general loop takes this iteration again.
      const lim = 10 * epsEv;
      const ix = v0 + s * v3 - c * v4 - oIx;
      const iy = -s * v1 + v2 - oIy;
      const cx = v0 - v3 - oCx;
      const cy = v1 + v2 - oCy;
      if (ix * ix + iy * iy <= lim * lim || cx * cx + cy * cy <= lim * lim) {
        steps--;
        break;
      }
      // dvy/dp there (CushionModel.derivative outside a step; it also lowers the smallest
      // slip components along the step's directions).
      const dI = ix * rIx + iy * rIy;
      if (dI < mdI) mdI = dI;
      const dC = cx * rCx + cy * rCy;
      if (dC < mdC) mdC = dC;
      const irI = 1 / Math.sqrt(ix * ix + iy * iy);
      const gy = nmuW * (iy * irI);
      let n = s - c * gy;
      if (n < 0) n = 0;
      const irC = 1 / Math.sqrt(cx * cx + cy * cy);
      const dvy = -c - s * gy + -(muS * n) * (cy * irC);
      if (ee2 !== 0 && !(dvy < 0)) {
        steps--;
        break;
      }
      wEnd = wc - ee2 * wc;
      restitution = true;
      if (ee2 === 0) endAt = from;
    }
    if (endAt < 0 && restitution) {
      if (x5 <= wEnd) {
        endAt = denseRoot(Q, 5, wEnd, from, 1);
      } else if (x1 >= 0) {
        steps--; // vy came back to zero first: stalled
        break;
      }
    }
    if (endAt >= 0) {
      if (endAt < 1) {
        denseAll(endAt);
        for (let i = 0; i < 6; i++) y[i] = D[i]!;
      } else {
        y[0] = x0;
        y[1] = x1;
        y[2] = x2;
        y[3] = x3;
        y[4] = x4;
        y[5] = x5;
      }
      p += endAt * h;
      code = FAST_END;
      break;
    }
    const rI0 = r;
    const rC0 = rc;
    y0 = x0;
    y1 = x1;
    y2 = x2;
    y3 = x3;
    y4 = x4;
    y5 = x5;
    a0 = g0;
    a1 = g1;
    a2 = g2;
    a3 = g3;
    a4 = g4;
    a5 = g5;
    p += h;
    const jx = y0 + s * y3 - c * y4 - oIx;
    const jy = -s * y1 + y2 - oIy;
    const kx = y0 - y3 - oCx;
    const ky = y1 + y2 - oCy;
    if (!(Math.sqrt(jx * jx + jy * jy) > small) || !(Math.sqrt(kx * kx + ky * ky) > small)) {
      // A small slip may be zero now or become slaved: CushionSolver.settleSlips decides.
      m.minDotI = mdI;
      m.minDotC = mdC;
      host.lastErr = err;
      host.rI0 = rI0;
      host.rC0 = rC0;
      step = h;
      code = FAST_SETTLE;
      break;
    }
    step = nextStep(h, err, errPrev);
    errPrev = errorMemory(err);
  }
  if (code !== FAST_END) {
    y[0] = y0;
    y[1] = y1;
    y[2] = y2;
    y[3] = y3;
    y[4] = y4;
    y[5] = y5;
  }
  k1[0] = a0;
  k1[1] = a1;
  k1[2] = a2;
  k1[3] = a3;
  k1[4] = a4;
  k1[5] = a5;
  host.innerSteps += steps - host.steps;
  host.step = step;
  host.errPrev = errPrev;
  host.steps = steps;
  host.rejected = rejected;
  host.p = p;
  host.restitution = restitution;
  host.wEnd = wEnd;
  return code;
}

/**
 * Fraction of a rejected step at which a slip's component along its starting direction went
 * from d0 to d1 through zero, linearly; 0.5 when the end did not cross (CushionSolver.crossing).
 */
function crossingFraction(d0: number, d1: number): number {
  if (!(d0 > 0 && d1 < 0)) return 0.5;
  const t = d0 / (d0 - d1);
  return t < 0.01 ? 0.01 : t > 0.99 ? 0.99 : t;
}

// Returns through a typed array: a call V8 does not inline boxes every double it returns.

/** The continuous extension at fraction theta of the step, all variables, into D (Dopri5.denseAll). */
function denseAll(theta: number): void {
  for (let i = 0; i < 6; i++) D[i] = denseValue(Q, i, theta);
}
