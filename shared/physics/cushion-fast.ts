// The cushion solver's inner loop for its most common stretch: both contacts slipping, neither
// slaved, or the table contact slaved while it grows from zero (see cushion-solver.ts). It takes
// the steps CushionSolver's general loop would take (the same Dormand-Prince steps, step
// limits, rejections, event location and step control) on
// local numbers, with the arithmetic arranged for a short chain from one stage to the next: the
// four slips are stepped as variables of their own with their rates (so a stage's slip is one
// sum away, not rebuilt from the velocities), the tableau is scaled by the step (a stage's
// newest term is one product and one sum) and only vy of the other variables is formed at the
// stages (for the work's rate). The two loops agree to rounding; where rounding tips a step
// decision, to within the tolerance (tests/unit/cushion-fast.test.ts). About twice as fast per
// step as the general loop (docs/cushion.md). Whatever needs the rolling conditions, a
// slaved slip or a stalled ending is handed back to the general loop at the start of the
// iteration that needs it, or right after a step when a slip has become small. One step (taken
// or rejected) a call of fastStep, its state carried in S (see runFast for why).
// Equations: cushion-model.ts (Mathavan et al. 2010, eq. 14 with both contacts slipping).
import {
  approachFactor, errorMemory, invRoot, MAX_STEPS, nextStep, QS_EXIT, QS_GROW, QS_RHO, RELAX_MAX, TURN_MAX,
  zeroDistance,
} from './cushion-control.ts';
import type { CushionModel } from './cushion-model.ts';
import {
  A21, A31, A32, A41, A42, A43, A51, A52, A53, A54, A61, A62, A63, A64, A65, B1, B3, B4, B5, B6,
  E1, E3, E4, E5, E6, E7,
} from './cushion-tableau.ts';
import { denseRoot, denseValue, denseVariable } from './cushion-dense.ts';

/** What the general loop does next (the return value of runFast and fastStep). */
export const FAST_GENERAL = 0;
/** The impact ended: the result is in the host's y, the outcome is 'restitution'. */
export const FAST_END = 1;
/**
 * A step was accepted and a slip is now small: the general loop settles the slips (a zero
 * slip, a slaved one) and then applies the step control with host.lastErr.
 */
export const FAST_SETTLE = 2;
/** A step was taken or rejected: call again. */
export const FAST_AGAIN = 3;

/** The solver state the inner loop reads and advances (CushionSolver implements it). */
export interface FastHost {
  readonly model: CushionModel;
  /** How fast each sliding slip's direction relaxes, times its speed (RELAX_MAX). */
  readonly relaxI: number;
  readonly relaxC: number;
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
  /** After FAST_SETTLE: the factor on the next step for slips closing on zero (approachFactor). */
  lastApproach: number;
  /** The last step proposed away from every slip's zero (CushionSolver.stepFree). */
  stepFree: number;
  rI0: number;
  rC0: number;
  /** After FAST_SETTLE: vy at the accepted step's start. */
  vy0: number;
  /** Steps taken by this inner loop during the impact (a diagnostic for the tests). */
  innerSteps: number;
  /** A slaved contact (0: I, 1: C) with slip (ex, ey), |slip| = r, follows its own direction. */
  release(contact: number, ex: number, ey: number, r: number): void;
}

// The continuous extension of a step (5 coefficients per variable, cushion-dense.ts).
const Q = new Float64Array(30);
// What fastStep carries from one step to the next: the slips and their rates (0-9), the step
// control and counts (10-14), restitution (15), the work's target (16), C slaved (17),
// slaving rejections in a row (18) and the step proposed away from the zeros (19); and the
// constants of a run of the inner loop (32-60, fastBegin). (One array, passed to fastStep as an
// argument: read from the module's scope, every element's load re-checked the array, 20%
// slower; two arrays, 4% slower than one.)
const S = new Float64Array(61);

/** Fills S for a run of fastStep from the host, the state y and its derivative k1. */
function fastBegin(host: FastHost, y: Float64Array, k1: Float64Array): void {
  const m = host.model;
  const s = m.s;
  const c = m.c;
  const muW = m.muW;
  const muS = m.muS;
  S[32] = s;
  S[33] = c;
  S[34] = -muW;
  S[35] = muS;
  // The table's normal times -μs is kMu uIy - muSs (with g = -μw uI); the slips' rates
  // (cushion-model.ts) are w uI + (-μs n) z uC.
  S[36] = muS * s;
  S[37] = -(muS * c * muW);
  S[38] = s * c;
  S[39] = s * muW + muS * (s + c * muW) < c ? 1 : 0;
  S[40] = -3.5 * muW;
  S[41] = 1 - 2.5 * s;
  S[42] = -(s * s + 2.5) * muW;
  S[43] = 2.5 - s;
  S[44] = -(1 - 2.5 * s) * muW;
  S[45] = -(2.5 - s) * muW;
  S[46] = m.epsSlip;
  const oIx = m.offIx;
  const oIy = m.offIy;
  const oCx = m.offCx;
  const oCy = m.offCy;
  S[47] = oIx;
  S[48] = oIy;
  S[49] = oCx;
  S[50] = oCy;
  S[51] = host.epsEv;
  S[52] = host.relaxI;
  S[53] = host.relaxC;
  S[54] = QS_RHO * host.V;
  S[55] = host.atolV;
  S[56] = 1 / host.atolV;
  S[57] = QS_EXIT * host.V;
  S[58] = QS_GROW * host.V;
  S[59] = 1 / host.atolW;
  S[60] = host.ee2;
  const y0 = y[0]!;
  const y1 = y[1]!;
  const y2 = y[2]!;
  const y3 = y[3]!;
  const y4 = y[4]!;
  const a0 = k1[0]!;
  const a1 = k1[1]!;
  const a3 = k1[3]!;
  const a2 = k1[2]!;
  const a4 = k1[4]!;
  const eIx = y0 + s * y3 - c * y4 - oIx;
  const eIy = -s * y1 + y2 - oIy;
  const eCx = y0 - y3 - oCx;
  const eCy = y1 + y2 - oCy;
  S[0] = eIx;
  S[1] = eIy;
  S[2] = eCx;
  S[3] = eCy;
  S[4] = a0 + s * a3 - c * a4;
  S[5] = -s * a1 + a2;
  S[6] = a0 - a3;
  S[7] = a1 + a2;
  S[8] = Math.sqrt(eIx * eIx + eIy * eIy);
  S[9] = Math.sqrt(eCx * eCx + eCy * eCy);
  S[10] = host.step;
  S[11] = host.errPrev;
  S[12] = host.steps;
  S[13] = host.rejected;
  S[14] = host.p;
  S[15] = host.restitution ? 1 : 0;
  S[16] = host.wEnd;
  S[17] = m.qsC ? 1 : 0;
  S[18] = 0;
  S[19] = host.stepFree;
}

/**
 * Runs the inner loop (fastStep) step by step until it hands back: see FAST_GENERAL, FAST_END
 * and FAST_SETTLE. One step a call keeps fastStep free of a loop: with the steps looping inside
 * it, V8 (Node 20) sometimes re-optimized it after its one deoptimization (the first time it
 * met an operation it had not yet executed) only for entry at the loop (on-stack replacement),
 * and every call then began in unoptimized code: the whole process ran the kernel four times
 * slower (1 run in 6 of a benchmark, 3 in 4 of another). This costs 8 to 10% against the loop
 * when that does not happen (docs/cushion.md).
 */
export function runFast(host: FastHost, y: Float64Array, k1: Float64Array): number {
  fastBegin(host, y, k1);
  let code = fastStep(host, y, k1, S);
  while (code === FAST_AGAIN) code = fastStep(host, y, k1, S);
  const steps = S[12]!;
  host.innerSteps += steps - host.steps;
  host.step = S[10]!;
  host.errPrev = S[11]!;
  host.steps = steps;
  host.rejected = S[13]!;
  host.p = S[14]!;
  host.restitution = S[15] !== 0;
  host.wEnd = S[16]!;
  host.stepFree = S[19]!;
  return code;
}

/**
 * One iteration of the general loop (a step, taken or rejected) while both contacts slip (the
 * table contact perhaps slaved from zero), from the state in y with its derivative in k1
 * (advanced in place), the carried state and the constants in st (S). FAST_AGAIN:
 * call again; see FAST_GENERAL, FAST_END and FAST_SETTLE for what it leaves to the caller.
 */
export function fastStep(
  host: FastHost, y: Float64Array, k1: Float64Array, st: Float64Array,
): number {
  const m = host.model;
  const s = st[32]!;
  const c = st[33]!;
  const nmuW = st[34]!;
  const muS = st[35]!;
  const muSs = st[36]!;
  const kMu = st[37]!;
  const sc = st[38]!;
  const pushesOut = st[39]! !== 0;
  const wIx = st[40]!;
  const zIx = st[41]!;
  const wIy = st[42]!;
  const zIy = st[43]!;
  const wCx = st[44]!;
  const wCy = st[45]!;
  const epsSlip = st[46]!;
  const oIx = st[47]!;
  const oIy = st[48]!;
  const oCx = st[49]!;
  const oCy = st[50]!;
  const epsEv = st[51]!;
  const relaxI = st[52]!;
  const relaxC = st[53]!;
  const tol0 = -epsEv;
  const small = st[54]!;
  const atolV = st[55]!;
  const iat = st[56]!;
  const qsExit = st[57]!;
  const qsGrow = st[58]!;
  const iat5 = st[59]!;
  const ee2 = st[60]!;
  // C slaved while growing from zero (see the step start).
  let slavC = st[17] !== 0;
  let slavRejects = st[18]!;
  let step = st[10]!;
  let errPrev = st[11]!;
  let steps = st[12]!;
  let rejected = st[13]!;
  let p = st[14]!;
  let restitution = st[15] !== 0;
  let wEnd = st[16]!;
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
  // The slips (minus their offsets) and their rates, stepped alongside y (fastBegin).
  let eIx = st[0]!;
  let eIy = st[1]!;
  let eCx = st[2]!;
  let eCy = st[3]!;
  let aIx = st[4]!;
  let aIy = st[5]!;
  let aCx = st[6]!;
  let aCy = st[7]!;
  let r = st[8]!;
  let rc = st[9]!;
  let code = FAST_GENERAL;
  attempt: {
    if (steps >= MAX_STEPS) break attempt; // the general loop throws
    if (!(r > epsSlip) || !(slavC || rc > epsSlip)) break attempt; // onset directions: the general loop
    steps++;
    // Slip directions at the step's start and the step limits (CushionSolver.limitBySlip).
    const rIx = eIx / r;
    const rIy = eIy / r;
    let h = step;
    let rate = (eIx * aIx + eIy * aIy) / r;
    const dI0 = nmuW < 0 ? zeroDistance(r, rate) : Infinity; // (without friction its direction does not matter)
    let dC0 = Infinity;
    if (rate < 0 && r <= -rate * h) h = -r / rate;
    let turn = Math.abs(aIx * eIy - aIy * eIx) / r;
    if (turn * h > TURN_MAX * r) h = TURN_MAX * r / turn;
    if (relaxI * h > RELAX_MAX * r) h = RELAX_MAX * r / relaxI;
    let rCx = 0;
    let rCy = 0;
    if (slavC) {
      // C slaved, growing from zero (a ball rolling on the cloth; CushionSolver.slavedStart and
      // releaseGrown): the direction its rates enforce, here along C's rates without its own
      // friction, a + 3.5 (-μs n) u with |a| > 3.5 μs n.
      const ax = wCx * rIx;
      const ay = wCy * rIy - c;
      const an = Math.sqrt(ax * ax + ay * ay);
      let nmu = kMu * rIy - muSs;
      if (nmu > 0) nmu = 0;
      const lam = an + 3.5 * nmu;
      if (!(an > 0)) {
        steps--;
        break attempt;
      }
      if (rc > qsExit && lam > 0) {
        // Grown: it follows its own direction again (CushionSolver.release).
        slavC = false;
        host.release(1, eCx, eCy, rc);
      } else if (!(lam > 0) || rc > epsSlip) {
        steps--; // shrinking or partly grown: the general loop
        break attempt;
      } else {
        rCx = ax / an;
        rCy = ay / an;
        // One step carries it at most to QS_GROW × V: the error estimate does not see what
        // slaving neglects.
        const t = (qsGrow - rc) / lam;
        if (t > 0 && t < h) h = t;
      }
    }
    if (!slavC) {
      rCx = eCx / rc;
      rCy = eCy / rc;
      rate = (eCx * aCx + eCy * aCy) / rc;
      if (muS > 0) dC0 = zeroDistance(rc, rate);
      if (rate < 0 && rc <= -rate * h) h = -rc / rate;
      turn = Math.abs(aCx * eCy - aCy * eCx) / rc;
      if (turn * h > TURN_MAX * rc) h = TURN_MAX * rc / turn;
      if (relaxC * h > RELAX_MAX * rc) h = RELAX_MAX * rc / relaxC;
    }

    // One Dormand-Prince step. The tableau is scaled by the step, so that a stage's newest
    // term costs one product and one sum on the way to the next stage; the slips are stepped
    // with their own rates, vy only for the work's rate, the other variables only to the end.
    const hA21 = h * A21;
    const hA31 = h * A31;
    const hA32 = h * A32;
    const hA41 = h * A41;
    const hA42 = h * A42;
    const hA43 = h * A43;
    const hA51 = h * A51;
    const hA52 = h * A52;
    const hA53 = h * A53;
    const hA54 = h * A54;
    const hA61 = h * A61;
    const hA62 = h * A62;
    const hA63 = h * A63;
    const hA64 = h * A64;
    const hA65 = h * A65;
    const hB1 = h * B1;
    const hB3 = h * B3;
    const hB4 = h * B4;
    const hB5 = h * B5;
    const hB6 = h * B6;
    const hE1 = h * E1;
    const hE3 = h * E3;
    const hE4 = h * E4;
    const hE5 = h * E5;
    const hE6 = h * E6;
    const hE7 = h * E7;
    let mdI = Infinity;
    let mdC = Infinity;
    const bsIx = eIx + hA21 * aIx;
    const bsIy = eIy + hA21 * aIy;
    const bsCx = eCx + hA21 * aCx;
    const bsCy = eCy + hA21 * aCy;
    const bv = y1 + hA21 * a1;
    // dy/dp and the slip rates at stage b.
    let b0: number, b1: number, b2: number, b3: number, b4: number, b5: number;
    let bIx: number, bIy: number, bCx: number, bCy: number;
    {
      const d = bsIx * rIx + bsIy * rIy;
      if (d < mdI) mdI = d;
      const ssI = bsIx * bsIx + bsIy * bsIy;
      const sr = Math.sqrt(ssI);
      const iI = sr * (1 / ssI);
      let uIx = rIx;
      let uIy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        uIx = bsIx * iI;
        uIy = bsIy * iI;
      }
      const dc = bsCx * rCx + bsCy * rCy;
      if (dc < mdC) mdC = dc;
      const ssC = bsCx * bsCx + bsCy * bsCy;
      const tr = Math.sqrt(ssC);
      const iC = tr * (1 / ssC);
      let uCx = rCx;
      let uCy = rCy;
      if (slavC) {
        // Slaved (growing from zero): along C's rates without its own friction.
        const ax = wCx * uIx;
        const ay = wCy * uIy - c;
        const an = Math.sqrt(ax * ax + ay * ay);
        uCx = ax / an;
        uCy = ay / an;
      } else if (!(dc <= 0 || tr <= epsSlip)) {
        uCx = bsCx * iC;
        uCy = bsCy * iC;
      }
      let nmu = kMu * uIy - muSs;
      if (nmu > 0) nmu = 0;
      const gx = nmuW * uIx;
      const gy = nmuW * uIy;
      const hx = nmu * uCx;
      const hy = nmu * uCy;
      b0 = gx + hx;
      b1 = -c - s * gy + hy;
      b2 = 2.5 * (gy + hy);
      b3 = 2.5 * (s * gx - hx);
      b4 = -2.5 * c * gx;
      b5 = c * bv;
      bIx = wIx * uIx + nmu * (zIx * uCx);
      bIy = sc + wIy * uIy + nmu * (zIy * uCy);
      bCx = wCx * uIx + nmu * (3.5 * uCx);
      bCy = wCy * uIy - c + nmu * (3.5 * uCy);
    }
    const csIx = eIx + hA31 * aIx + hA32 * bIx;
    const csIy = eIy + hA31 * aIy + hA32 * bIy;
    const csCx = eCx + hA31 * aCx + hA32 * bCx;
    const csCy = eCy + hA31 * aCy + hA32 * bCy;
    const cv = y1 + hA31 * a1 + hA32 * b1;
    // dy/dp and the slip rates at stage c.
    let c0: number, c1: number, c2: number, c3: number, c4: number, c5: number;
    let cIx: number, cIy: number, cCx: number, cCy: number;
    {
      const d = csIx * rIx + csIy * rIy;
      if (d < mdI) mdI = d;
      const ssI = csIx * csIx + csIy * csIy;
      const sr = Math.sqrt(ssI);
      const iI = sr * (1 / ssI);
      let uIx = rIx;
      let uIy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        uIx = csIx * iI;
        uIy = csIy * iI;
      }
      const dc = csCx * rCx + csCy * rCy;
      if (dc < mdC) mdC = dc;
      const ssC = csCx * csCx + csCy * csCy;
      const tr = Math.sqrt(ssC);
      const iC = tr * (1 / ssC);
      let uCx = rCx;
      let uCy = rCy;
      if (slavC) {
        // Slaved (growing from zero): along C's rates without its own friction.
        const ax = wCx * uIx;
        const ay = wCy * uIy - c;
        const an = Math.sqrt(ax * ax + ay * ay);
        uCx = ax / an;
        uCy = ay / an;
      } else if (!(dc <= 0 || tr <= epsSlip)) {
        uCx = csCx * iC;
        uCy = csCy * iC;
      }
      let nmu = kMu * uIy - muSs;
      if (nmu > 0) nmu = 0;
      const gx = nmuW * uIx;
      const gy = nmuW * uIy;
      const hx = nmu * uCx;
      const hy = nmu * uCy;
      c0 = gx + hx;
      c1 = -c - s * gy + hy;
      c2 = 2.5 * (gy + hy);
      c3 = 2.5 * (s * gx - hx);
      c4 = -2.5 * c * gx;
      c5 = c * cv;
      cIx = wIx * uIx + nmu * (zIx * uCx);
      cIy = sc + wIy * uIy + nmu * (zIy * uCy);
      cCx = wCx * uIx + nmu * (3.5 * uCx);
      cCy = wCy * uIy - c + nmu * (3.5 * uCy);
    }
    const dsIx = eIx + hA41 * aIx + hA42 * bIx + hA43 * cIx;
    const dsIy = eIy + hA41 * aIy + hA42 * bIy + hA43 * cIy;
    const dsCx = eCx + hA41 * aCx + hA42 * bCx + hA43 * cCx;
    const dsCy = eCy + hA41 * aCy + hA42 * bCy + hA43 * cCy;
    const dv = y1 + hA41 * a1 + hA42 * b1 + hA43 * c1;
    // dy/dp and the slip rates at stage d.
    let d0: number, d1: number, d2: number, d3: number, d4: number, d5: number;
    let dIx: number, dIy: number, dCx: number, dCy: number;
    {
      const d = dsIx * rIx + dsIy * rIy;
      if (d < mdI) mdI = d;
      const ssI = dsIx * dsIx + dsIy * dsIy;
      const sr = Math.sqrt(ssI);
      const iI = sr * (1 / ssI);
      let uIx = rIx;
      let uIy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        uIx = dsIx * iI;
        uIy = dsIy * iI;
      }
      const dc = dsCx * rCx + dsCy * rCy;
      if (dc < mdC) mdC = dc;
      const ssC = dsCx * dsCx + dsCy * dsCy;
      const tr = Math.sqrt(ssC);
      const iC = tr * (1 / ssC);
      let uCx = rCx;
      let uCy = rCy;
      if (slavC) {
        // Slaved (growing from zero): along C's rates without its own friction.
        const ax = wCx * uIx;
        const ay = wCy * uIy - c;
        const an = Math.sqrt(ax * ax + ay * ay);
        uCx = ax / an;
        uCy = ay / an;
      } else if (!(dc <= 0 || tr <= epsSlip)) {
        uCx = dsCx * iC;
        uCy = dsCy * iC;
      }
      let nmu = kMu * uIy - muSs;
      if (nmu > 0) nmu = 0;
      const gx = nmuW * uIx;
      const gy = nmuW * uIy;
      const hx = nmu * uCx;
      const hy = nmu * uCy;
      d0 = gx + hx;
      d1 = -c - s * gy + hy;
      d2 = 2.5 * (gy + hy);
      d3 = 2.5 * (s * gx - hx);
      d4 = -2.5 * c * gx;
      d5 = c * dv;
      dIx = wIx * uIx + nmu * (zIx * uCx);
      dIy = sc + wIy * uIy + nmu * (zIy * uCy);
      dCx = wCx * uIx + nmu * (3.5 * uCx);
      dCy = wCy * uIy - c + nmu * (3.5 * uCy);
    }
    const esIx = eIx + hA51 * aIx + hA52 * bIx + hA53 * cIx + hA54 * dIx;
    const esIy = eIy + hA51 * aIy + hA52 * bIy + hA53 * cIy + hA54 * dIy;
    const esCx = eCx + hA51 * aCx + hA52 * bCx + hA53 * cCx + hA54 * dCx;
    const esCy = eCy + hA51 * aCy + hA52 * bCy + hA53 * cCy + hA54 * dCy;
    const ev = y1 + hA51 * a1 + hA52 * b1 + hA53 * c1 + hA54 * d1;
    // dy/dp and the slip rates at stage e.
    let e0: number, e1: number, e2: number, e3: number, e4: number, e5: number;
    let eeIx: number, eeIy: number, eeCx: number, eeCy: number;
    {
      const d = esIx * rIx + esIy * rIy;
      if (d < mdI) mdI = d;
      const ssI = esIx * esIx + esIy * esIy;
      const sr = Math.sqrt(ssI);
      const iI = sr * (1 / ssI);
      let uIx = rIx;
      let uIy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        uIx = esIx * iI;
        uIy = esIy * iI;
      }
      const dc = esCx * rCx + esCy * rCy;
      if (dc < mdC) mdC = dc;
      const ssC = esCx * esCx + esCy * esCy;
      const tr = Math.sqrt(ssC);
      const iC = tr * (1 / ssC);
      let uCx = rCx;
      let uCy = rCy;
      if (slavC) {
        // Slaved (growing from zero): along C's rates without its own friction.
        const ax = wCx * uIx;
        const ay = wCy * uIy - c;
        const an = Math.sqrt(ax * ax + ay * ay);
        uCx = ax / an;
        uCy = ay / an;
      } else if (!(dc <= 0 || tr <= epsSlip)) {
        uCx = esCx * iC;
        uCy = esCy * iC;
      }
      let nmu = kMu * uIy - muSs;
      if (nmu > 0) nmu = 0;
      const gx = nmuW * uIx;
      const gy = nmuW * uIy;
      const hx = nmu * uCx;
      const hy = nmu * uCy;
      e0 = gx + hx;
      e1 = -c - s * gy + hy;
      e2 = 2.5 * (gy + hy);
      e3 = 2.5 * (s * gx - hx);
      e4 = -2.5 * c * gx;
      e5 = c * ev;
      eeIx = wIx * uIx + nmu * (zIx * uCx);
      eeIy = sc + wIy * uIy + nmu * (zIy * uCy);
      eeCx = wCx * uIx + nmu * (3.5 * uCx);
      eeCy = wCy * uIy - c + nmu * (3.5 * uCy);
    }
    const fsIx = eIx + hA61 * aIx + hA62 * bIx + hA63 * cIx + hA64 * dIx + hA65 * eeIx;
    const fsIy = eIy + hA61 * aIy + hA62 * bIy + hA63 * cIy + hA64 * dIy + hA65 * eeIy;
    const fsCx = eCx + hA61 * aCx + hA62 * bCx + hA63 * cCx + hA64 * dCx + hA65 * eeCx;
    const fsCy = eCy + hA61 * aCy + hA62 * bCy + hA63 * cCy + hA64 * dCy + hA65 * eeCy;
    const fv = y1 + hA61 * a1 + hA62 * b1 + hA63 * c1 + hA64 * d1 + hA65 * e1;
    // dy/dp and the slip rates at stage f.
    let f0: number, f1: number, f2: number, f3: number, f4: number, f5: number;
    let fIx: number, fIy: number, fCx: number, fCy: number;
    {
      const d = fsIx * rIx + fsIy * rIy;
      if (d < mdI) mdI = d;
      const ssI = fsIx * fsIx + fsIy * fsIy;
      const sr = Math.sqrt(ssI);
      const iI = sr * (1 / ssI);
      let uIx = rIx;
      let uIy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        uIx = fsIx * iI;
        uIy = fsIy * iI;
      }
      const dc = fsCx * rCx + fsCy * rCy;
      if (dc < mdC) mdC = dc;
      const ssC = fsCx * fsCx + fsCy * fsCy;
      const tr = Math.sqrt(ssC);
      const iC = tr * (1 / ssC);
      let uCx = rCx;
      let uCy = rCy;
      if (slavC) {
        // Slaved (growing from zero): along C's rates without its own friction.
        const ax = wCx * uIx;
        const ay = wCy * uIy - c;
        const an = Math.sqrt(ax * ax + ay * ay);
        uCx = ax / an;
        uCy = ay / an;
      } else if (!(dc <= 0 || tr <= epsSlip)) {
        uCx = fsCx * iC;
        uCy = fsCy * iC;
      }
      let nmu = kMu * uIy - muSs;
      if (nmu > 0) nmu = 0;
      const gx = nmuW * uIx;
      const gy = nmuW * uIy;
      const hx = nmu * uCx;
      const hy = nmu * uCy;
      f0 = gx + hx;
      f1 = -c - s * gy + hy;
      f2 = 2.5 * (gy + hy);
      f3 = 2.5 * (s * gx - hx);
      f4 = -2.5 * c * gx;
      f5 = c * fv;
      fIx = wIx * uIx + nmu * (zIx * uCx);
      fIy = sc + wIy * uIy + nmu * (zIy * uCy);
      fCx = wCx * uIx + nmu * (3.5 * uCx);
      fCy = wCy * uIy - c + nmu * (3.5 * uCy);
    }
    const xIx = eIx + hB1 * aIx + hB3 * cIx + hB4 * dIx + hB5 * eeIx + hB6 * fIx;
    const xIy = eIy + hB1 * aIy + hB3 * cIy + hB4 * dIy + hB5 * eeIy + hB6 * fIy;
    const xCx = eCx + hB1 * aCx + hB3 * cCx + hB4 * dCx + hB5 * eeCx + hB6 * fCx;
    const xCy = eCy + hB1 * aCy + hB3 * cCy + hB4 * dCy + hB5 * eeCy + hB6 * fCy;
    const x0 = y0 + hB1 * a0 + hB3 * c0 + hB4 * d0 + hB5 * e0 + hB6 * f0;
    const x1 = y1 + hB1 * a1 + hB3 * c1 + hB4 * d1 + hB5 * e1 + hB6 * f1;
    const x2 = y2 + hB1 * a2 + hB3 * c2 + hB4 * d2 + hB5 * e2 + hB6 * f2;
    const x3 = y3 + hB1 * a3 + hB3 * c3 + hB4 * d3 + hB5 * e3 + hB6 * f3;
    const x4 = y4 + hB1 * a4 + hB3 * c4 + hB4 * d4 + hB5 * e4 + hB6 * f4;
    const x5 = y5 + hB1 * a5 + hB3 * c5 + hB4 * d5 + hB5 * e5 + hB6 * f5;
    let rN = r;
    let rcN = rc;
    let uCxEnd = 0;
    let uCyEnd = 0;
    // dy/dp and the slip rates at stage g.
    let g0: number, g1: number, g2: number, g3: number, g4: number, g5: number;
    let gIx: number, gIy: number, gCx: number, gCy: number;
    {
      const d = xIx * rIx + xIy * rIy;
      if (d < mdI) mdI = d;
      const ssI = xIx * xIx + xIy * xIy;
      const sr = Math.sqrt(ssI);
      const iI = sr * (1 / ssI);
      let uIx = rIx;
      let uIy = rIy;
      if (!(d <= 0 || sr <= epsSlip)) {
        uIx = xIx * iI;
        uIy = xIy * iI;
      }
      const dc = xCx * rCx + xCy * rCy;
      if (dc < mdC) mdC = dc;
      const ssC = xCx * xCx + xCy * xCy;
      const tr = Math.sqrt(ssC);
      const iC = tr * (1 / ssC);
      let uCx = rCx;
      let uCy = rCy;
      if (slavC) {
        // Slaved (growing from zero): along C's rates without its own friction.
        const ax = wCx * uIx;
        const ay = wCy * uIy - c;
        const an = Math.sqrt(ax * ax + ay * ay);
        uCx = ax / an;
        uCy = ay / an;
      } else if (!(dc <= 0 || tr <= epsSlip)) {
        uCx = xCx * iC;
        uCy = xCy * iC;
      }
      let nmu = kMu * uIy - muSs;
      if (nmu > 0) nmu = 0;
      const gx = nmuW * uIx;
      const gy = nmuW * uIy;
      const hx = nmu * uCx;
      const hy = nmu * uCy;
      g0 = gx + hx;
      g1 = -c - s * gy + hy;
      g2 = 2.5 * (gy + hy);
      g3 = 2.5 * (s * gx - hx);
      g4 = -2.5 * c * gx;
      g5 = c * x1;
      gIx = wIx * uIx + nmu * (zIx * uCx);
      gIy = sc + wIy * uIy + nmu * (zIy * uCy);
      gCx = wCx * uIx + nmu * (3.5 * uCx);
      gCy = wCy * uIy - c + nmu * (3.5 * uCy);
      rN = sr;
      rcN = tr;
      uCxEnd = uCx;
      uCyEnd = uCy;
    }

    if (mdI < tol0 || mdC < tol0) {
      // A slip went through zero inside the step: retry up to the interpolated zero
      // (CushionSolver.crossing).
      rejected++;
      let t = 0.5;
      if (mdI < tol0) t = Math.min(t, crossingFraction(eIx * rIx + eIy * rIy, xIx * rIx + xIy * rIy));
      if (mdC < tol0) t = Math.min(t, crossingFraction(eCx * rCx + eCy * rCy, xCx * rCx + xCy * rCy));
      step = h * t;
      code = FAST_AGAIN;
      break attempt;
    }
    let err = 0;
    const q0 = Math.abs(hE1 * a0 + hE3 * c0 + hE4 * d0 + hE5 * e0 + hE6 * f0 + hE7 * g0) * iat;
    if (q0 > err) err = q0;
    const q1 = Math.abs(hE1 * a1 + hE3 * c1 + hE4 * d1 + hE5 * e1 + hE6 * f1 + hE7 * g1) * iat;
    if (q1 > err) err = q1;
    const q2 = Math.abs(hE1 * a2 + hE3 * c2 + hE4 * d2 + hE5 * e2 + hE6 * f2 + hE7 * g2) * iat;
    if (q2 > err) err = q2;
    const q3 = Math.abs(hE1 * a3 + hE3 * c3 + hE4 * d3 + hE5 * e3 + hE6 * f3 + hE7 * g3) * iat;
    if (q3 > err) err = q3;
    const q4 = Math.abs(hE1 * a4 + hE3 * c4 + hE4 * d4 + hE5 * e4 + hE6 * f4 + hE7 * g4) * iat;
    if (q4 > err) err = q4;
    const q5 = Math.abs(hE1 * a5 + hE3 * c5 + hE4 * d5 + hE5 * e5 + hE6 * f5 + hE7 * g5) * iat5;
    if (q5 > err) err = q5;
    if (err > 1) {
      rejected++;
      step = h * Math.max(0.2, 0.9 * invRoot(err));
      code = FAST_AGAIN;
      break attempt;
    }
    if (slavC) {
      // What slaving neglects, which the error estimate cannot see (CushionSolver.slavingError):
      // about |slip| × the slaved direction's turn / 2.5. A step that exceeds the tolerance is
      // retried shorter; at the third in a row the general loop decides (it releases the slip).
      const dx = uCxEnd - rCx;
      const dy = uCyEnd - rCy;
      const qe = Math.sqrt((xCx * xCx + xCy * xCy) * (dx * dx + dy * dy)) / 2.5;
      if (qe > atolV) {
        rejected++;
        step = h * Math.max(0.2, 0.9 * Math.sqrt(atolV / qe));
        if (++slavRejects >= 3) break attempt;
        code = FAST_AGAIN;
      break attempt;
      }
      slavRejects = 0;
    }

    // Accepted: end of compression and the work target on the continuous extension.
    let endAt = -1;
    let from = 0;
    const compressionEnds = !restitution && x1 <= 0;
    if (compressionEnds || (restitution && x5 <= wEnd)) {
      // The continuous extension of this step (Dopri5.prepareDense) of vy and the work.
      denseVariable(Q, 5, h, y1, x1, a1, c1, d1, e1, f1, g1);
      denseVariable(Q, 25, h, y5, x5, a5, c5, d5, e5, f5, g5);
    }
    if (compressionEnds && slavC) {
      steps--; // with a slaved slip the general loop decides (CushionSolver.slipAtZero)
      break attempt;
    }
    if (compressionEnds) {
      from = denseRoot(Q, 1, 0, 0, 1);
      const wc = denseValue(Q, 5, from);
      // A slip at zero together with vy (CushionSolver.slipAtZero), or an impact that stalls:
      // the general loop takes this iteration again. A slip whose component along the step's
      // starting direction stayed above 1e3 event bands at every stage cannot be at zero at
      // vy = 0, and with μw sinθ + μs (sinθ + μw cosθ) < cosθ the impulse always pushes the
      // ball out (dvy/dp < 0): the common case needs neither check.
      const lim = 10 * epsEv;
      if (!(mdI > 1e3 * lim && mdC > 1e3 * lim) || (ee2 !== 0 && !pushesOut)) {
        denseRest(h, y0, y2, y3, y4, x0, x2, x3, x4, a0, a2, a3, a4, c0, c2, c3, c4, d0, d2, d3, d4, e0, e2, e3, e4,
          f0, f2, f3, f4, g0, g2, g3, g4);
        const v0 = denseValue(Q, 0, from);
        const v1 = denseValue(Q, 1, from);
        const v2 = denseValue(Q, 2, from);
        const v3 = denseValue(Q, 3, from);
        const v4 = denseValue(Q, 4, from);
        const ix = v0 + s * v3 - c * v4 - oIx;
        const iy = -s * v1 + v2 - oIy;
        const cx = v0 - v3 - oCx;
        const cy = v1 + v2 - oCy;
        if (ix * ix + iy * iy <= lim * lim || cx * cx + cy * cy <= lim * lim) {
          steps--;
          break attempt;
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
          break attempt;
        }
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
        break attempt;
      }
    }
    if (endAt >= 0) {
      if (endAt < 1) {
        denseRest(h, y0, y2, y3, y4, x0, x2, x3, x4, a0, a2, a3, a4, c0, c2, c3, c4, d0, d2, d3, d4, e0, e2, e3, e4,
          f0, f2, f3, f4, g0, g2, g3, g4);
        for (let i = 0; i < 6; i++) y[i] = denseValue(Q, i, endAt);
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
      break attempt;
    }
    if (slavC) {
      m.hintCx = uCxEnd;
      m.hintCy = uCyEnd;
    }
    const rI0 = r;
    const rC0 = rc;
    const vyStart = y1;
    // (The slips' distances to zero at the step's end, from the rates there: approachFactor.)
    const approach = approachFactor(dI0, nmuW < 0 ? zeroDistance(rN, (xIx * gIx + xIy * gIy) / rN) : Infinity, dC0,
      slavC || !(muS > 0) ? Infinity : zeroDistance(rcN, (xCx * gCx + xCy * gCy) / rcN));
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
    eIx = xIx;
    eIy = xIy;
    eCx = xCx;
    eCy = xCy;
    aIx = gIx;
    aIy = gIy;
    aCx = gCx;
    aCy = gCy;
    r = rN;
    rc = rcN;
    if (!(r > small) || !(rc > small)) {
      // A small slip may be zero now or become slaved: CushionSolver.settleSlips decides.
      m.minDotI = mdI;
      m.minDotC = mdC;
      host.lastErr = err;
      host.lastApproach = approach;
      host.rI0 = rI0;
      host.rC0 = rC0;
      host.vy0 = vyStart;
      step = h;
      code = FAST_SETTLE;
      break attempt;
    }
    step = nextStep(h, err, errPrev) * approach;
    if (approach === 1 && !slavC) st[19] = step; // (both slips are above QS_RHO V here)
    errPrev = errorMemory(err);
    code = FAST_AGAIN;
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
  st[0] = eIx;
  st[1] = eIy;
  st[2] = eCx;
  st[3] = eCy;
  st[4] = aIx;
  st[5] = aIy;
  st[6] = aCx;
  st[7] = aCy;
  st[8] = r;
  st[9] = rc;
  st[10] = step;
  st[11] = errPrev;
  st[12] = steps;
  st[13] = rejected;
  st[14] = p;
  st[15] = restitution ? 1 : 0;
  st[16] = wEnd;
  st[17] = slavC ? 1 : 0;
  st[18] = slavRejects;
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

/** The extension of vx, R ωx, R ωy and R ωz (vy and the work are filled first), into Q. */
function denseRest(
  h: number, y0: number, y2: number, y3: number, y4: number, x0: number, x2: number, x3: number, x4: number,
  a0: number, a2: number, a3: number, a4: number, c0: number, c2: number, c3: number, c4: number,
  d0: number, d2: number, d3: number, d4: number, e0: number, e2: number, e3: number, e4: number,
  f0: number, f2: number, f3: number, f4: number, g0: number, g2: number, g3: number, g4: number,
): void {
  denseVariable(Q, 0, h, y0, x0, a0, c0, d0, e0, f0, g0);
  denseVariable(Q, 10, h, y2, x2, a2, c2, d2, e2, f2, g2);
  denseVariable(Q, 15, h, y3, x3, a3, c3, d3, e3, f3, g3);
  denseVariable(Q, 20, h, y4, x4, a4, c4, d4, e4, f4, g4);
}
