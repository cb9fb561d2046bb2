// The cushion impact's express path (shared/physics/cushion-express.ts): Taylor series steps of
// order 8 (shared/physics/cushion-series.ts) while both slips stay away from zero, the
// Runge-Kutta solver otherwise. Its accuracy against the converged reference is tested with the
// rest of the kernel (cushion-accuracy.test.ts goes through cushionRebound); here: the series is
// the equations' own, the path is taken where it should be and declines where it should, and it
// agrees with the solver.
import { readFileSync } from 'node:fs';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { cushionImpactSolver } from '../../shared/physics/cushion.ts';
import {
  compressionEnd, EVENT_DONE, EXPRESS_EVENT, EXPRESS_HANDOVER, EXPRESS_IN, EXPRESS_OUT, EXPRESS_SERIES, EXPRESS_SLIP_MIN,
  expressImpact, restitutionEnd, seriesConstants, stateNorm,
} from '../../shared/physics/cushion-express.ts';
import { CushionModel } from '../../shared/physics/cushion-model.ts';
import { SERIES_AT, SERIES_CUT, SERIES_LENGTH, SERIES_NORMS, SERIES_TERMS } from '../../shared/physics/cushion-series.ts';
import { cushionImpact } from '../../shared/physics/diagnostics.ts';
import type { CushionParams, CushionState } from '../../shared/physics/index.ts';
import { CUSHION_SERIES_FILE, CUSHION_SERIES_SOURCE } from '../../scripts/gen-cushion-series.ts';
import { benchGrid, PAPER, paperState, relError, TABLE_PARAMS } from '../support/cushion-cases.ts';
import { issueImpact } from '../support/cushion-arbitraries.ts';
import { referenceRebound } from '../support/cushion-reference.ts';

const NT = SERIES_TERMS;
// The express path's own series kernel (its arrays are shared: each test fills them and reads
// them before the next impact).
const S = EXPRESS_SERIES;
const q = S.q;

/**
 * The series' variables (SERIES_VARIABLES: e_I,x, vy, e_I,y, e_C,x, R ωz, W) of the internal
 * state y = [vx, vy, R ωx, R ωy, R ωz, W], with the kernel's sinθ and cosθ (constants()).
 */
function variables(y: ArrayLike<number>): number[] {
  const s = S.k[0]!;
  const c = S.k[1]!;
  return [y[0]! + s * y[3]! - c * y[4]!, y[1]!, y[2]! - s * y[1]!, y[0]! - y[3]!, y[4]!, y[5]!];
}

/** The series about the internal state y into q (false: the table's normal impulse would not be positive). */
function seriesAbout(y: Float64Array): boolean {
  S.start.set(variables(y));
  return S.series() === 1;
}

/** The series q at p = t into out. */
function at(t: number, out: Float64Array): void {
  q[SERIES_AT] = t;
  S.valueAt();
  out.set(S.out);
}

/** The series' constants, as expressImpact sets them (no cut: lim 0), into the kernel's. */
function constants(p: CushionParams): { s: number; c: number; k: Float64Array } {
  const s = (p.h - p.R) / p.R;
  const c = Math.sqrt((1 - s) * (1 + s));
  seriesConstants(s, c, p.muS, p.muW, 0);
  return { s, c, k: S.k };
}

function internal(st: CushionState, R: number): Float64Array {
  return new Float64Array([st.vx, st.vy, R * st.wx, R * st.wy, R * st.wz, 0]);
}

/** Series steps the express path took (0 declined at the start, < 0 handed over later). */
function expressSteps(st: CushionState, p: CushionParams, tol = 1e-6): number {
  EXPRESS_IN.set([st.vx, st.vy, st.wx, st.wy, st.wz, p.R, p.h, p.ee, p.muS, p.muW, tol]);
  return expressImpact();
}

/** The express path's result when it ends the impact itself, else null. */
function express(st: CushionState, p: CushionParams, tol = 1e-6): number[] | null {
  if (expressSteps(st, p, tol) <= 0) return null;
  return [EXPRESS_OUT[0]!, EXPRESS_OUT[1]!, EXPRESS_OUT[2]! / p.R, EXPRESS_OUT[3]! / p.R, EXPRESS_OUT[4]! / p.R];
}

function asState(v: number[]): CushionState {
  return { vx: v[0]!, vy: v[1]!, wx: v[2]!, wy: v[3]!, wz: v[4]! };
}

describe('cushion series', () => {
  it('is the generator\'s output (regenerate with node --import tsx scripts/gen-cushion-series.ts)', () => {
    expect(readFileSync(CUSHION_SERIES_FILE, 'utf8')).toBe(CUSHION_SERIES_SOURCE);
  });

  it('has the layout the express path reads by literal indices (q[9 i + k], the cut at 54, the point at 56, the norms at 57)', () => {
    expect(SERIES_TERMS).toBe(9);
    expect(SERIES_CUT).toBe(54);
    expect(SERIES_AT).toBe(56);
    expect(SERIES_NORMS).toBe(57);
    expect(SERIES_LENGTH).toBe(60);
  });

  it('leaves the step\'s choice n6, n7 (the weighted largest state coefficients of p^6 and p^7) and n7\'s eighth root, as the express path forms n8', () => {
    fc.assert(
      fc.property(
        issueImpact, fc.double({ min: 1e-3, max: 1e3, noNaN: true }), fc.double({ min: 1e-3, max: 1e3, noNaN: true }),
        (g, iv, iw) => {
          const { s, c, k } = constants(g.params);
          const L = g.state.vy / c;
          k[13] = iv;
          k[14] = iw;
          k[15] = L ** 6;
          k[16] = L ** 7;
          k[17] = 1 / (1 + s);
          if (!seriesAbout(internal(g.state, g.params.R))) return;
          for (const [order, slot] of [[6, 57], [7, 58]] as const) {
            const a = stateNorm(q[order]!, q[NT + order]!, q[2 * NT + order]!, q[3 * NT + order]!, q[4 * NT + order]!, s, c) * iv;
            const nW = Math.abs(q[5 * NT + order]!) * iw;
            expect(q[slot]).toBe((a > nW ? a : nW) * k[order === 6 ? 15 : 16]!);
          }
          expect(q[59]).toBe(Math.sqrt(Math.sqrt(Math.sqrt(q[58]!))));
        },
      ),
      { numRuns: 300, seed: 11 },
    );
  });

  it('is the Taylor series of the equations: a fine Runge-Kutta integration of the model lands on it', () => {
    const model = new CushionModel();
    for (const [, p] of TABLE_PARAMS) {
      const { s, c, k } = constants(p);
      model.setConstants(s, c, p.muW, p.muS);
      for (const [alpha, kT, kS] of [[30, 0, 1], [60, 2, -1], [10, -1, 2], [80, 0.5, 0]] as const) {
        const st = paperState(1, alpha, kT, kS, p.R);
        const y0 = internal(st, p.R);
        expect(seriesAbout(y0)).toBe(true);
        // Classic RK4 with the model's derivative over a short impulse, to rounding.
        const span = 0.05 * st.vy / c;
        const n = 400;
        const dp = span / n;
        const y = Float64Array.from(y0);
        const k1 = new Float64Array(6);
        const k2 = new Float64Array(6);
        const k3 = new Float64Array(6);
        const k4 = new Float64Array(6);
        const t = new Float64Array(6);
        for (let i = 0; i < n; i++) {
          model.derivative(y, k1);
          for (let j = 0; j < 6; j++) t[j] = y[j]! + 0.5 * dp * k1[j]!;
          model.derivative(t, k2);
          for (let j = 0; j < 6; j++) t[j] = y[j]! + 0.5 * dp * k2[j]!;
          model.derivative(t, k3);
          for (let j = 0; j < 6; j++) t[j] = y[j]! + dp * k3[j]!;
          model.derivative(t, k4);
          for (let j = 0; j < 6; j++) y[j] = y[j]! + (dp / 6) * (k1[j]! + 2 * k2[j]! + 2 * k3[j]! + k4[j]!);
        }
        const z = variables(y);
        for (let j = 0; j < 6; j++) {
          let v = q[j * NT + NT - 1]!;
          for (let m = NT - 2; m >= 0; m--) v = v * span + q[j * NT + m]!;
          expect(Math.abs(v - z[j]!), `${alpha} ${kT} ${kS} variable ${j}`).toBeLessThan(1e-12);
        }
        // Its first coefficient is the model's derivative (the variables are linear in the state).
        model.derivative(y0, k1);
        const dz = variables(k1);
        for (let j = 0; j < 6; j++) expect(Math.abs(q[j * NT + 1]! - dz[j]!)).toBeLessThan(1e-14);
      }
    }
  });

  it('is evaluated at a step\'s end in two parts (vy and the work, then the rest) with the bits of the whole', () => {
    const whole = new Float64Array(6);
    const parts = S.start;
    fc.assert(
      fc.property(issueImpact, fc.double({ min: 0, max: 3, noNaN: true }), (g, x) => {
        const { k } = constants(g.params);
        if (!seriesAbout(internal(g.state, g.params.R))) return;
        at((x * g.state.vy) / k[1]!, whole);
        parts.fill(NaN);
        S.endFirst();
        expect([parts[1], parts[5]]).toEqual([whole[1], whole[5]]);
        S.endRest();
        expect(Array.from(parts)).toEqual(Array.from(whole));
      }),
      { numRuns: 500, seed: 5 },
    );
  });
});

/** Where variable i of q, above target at lo and at or below it at hi, falls to it: bisection to rounding. */
function bisect(i: number, target: number, lo: number, hi: number): number {
  const y = new Float64Array(6);
  for (let n = 0; n < 200 && hi - lo > 0; n++) {
    const m = 0.5 * (lo + hi);
    if (m === lo || m === hi) break;
    at(m, y);
    if (y[i]! > target) lo = m;
    else hi = m;
  }
  return 0.5 * (lo + hi);
}

describe('express path: the ends of the phases on the series', () => {
  it('finds the end of compression, the work there and the end of restitution as bisection to rounding does', () => {
    // On the first step's series of grid impacts (natural roll, k_T = 1, has a zero table slip:
    // cushionSeriesRolling's case), over a step 1.3 times as long as vy's first-order root,
    // and for restitution from there to 1.5 times as far, to half the way down.
    let compressions = 0;
    let restitutions = 0;
    let rootC = 0; // Newton's method to EVENT_DONE: the root, relative to the step
    let workC = 0; // the work there, relative
    let rootC0 = 0; // Newton's method to 1e-6 (e_e = 0), relative to the step
    let rootR = 0; // Halley's method to EVENT_DONE, relative to the step
    for (const [, p] of TABLE_PARAMS) {
      const { c } = constants(p);
      for (const g of benchGrid(p.R).filter((c, i) => i % 5 === 0 && c.kT !== 1)) {
        const y = new Float64Array(6);
        if (!seriesAbout(internal(g.state, p.R))) continue;
        const dp = 1.3 * (-q[NT]! / q[NT + 1]!);
        at(dp, y);
        if (!(dp > 0) || !(y[1]! <= 0)) continue;
        compressions++;
        const pc = bisect(1, 0, 0, dp);
        at(pc, y);
        const wc = y[5]!;
        rootC = Math.max(rootC, Math.abs(compressionEnd(dp, c, EVENT_DONE) - pc) / dp);
        workC = Math.max(workC, Math.abs(EXPRESS_EVENT[2]! - wc) / wc);
        rootC0 = Math.max(rootC0, Math.abs(compressionEnd(dp, c, 1e-6) - pc) / dp);
        const end = 1.5 * pc;
        let falls = true;
        let last = wc;
        for (let j = 1; j <= 50; j++) {
          at(pc + ((end - pc) * j) / 50, y);
          falls &&= y[5]! < last;
          last = y[5]!;
        }
        if (!falls) continue;
        restitutions++;
        const target = 0.5 * (wc + last);
        const pe = bisect(5, target, pc, end);
        rootR = Math.max(rootR, Math.abs(restitutionEnd(target, pc, end, c) - pe) / end);
      }
    }
    expect(compressions).toBeGreaterThan(200);
    expect(restitutions).toBeGreaterThan(200);
    // Newton's correction below EVENT_DONE (2e-3) of the step leaves the root within about 1e-6
    // of it (quadratic convergence; measured 1.1e-7, 3.0e-8 with 1e-3), and the work, at its
    // maximum there, within about 1e-9 of it (measured 2.4e-10, 3.3e-11 with 1e-3): a relative
    // 1e-9 would move the end of restitution by about 1e-9 of the impact.
    expect(rootC).toBeLessThan(1e-5);
    expect(workC).toBeLessThan(1e-9);
    // Newton's method to 1e-6 of the step: to rounding (measured: 6e-14). Halley's to 2e-3 of
    // it from the root of the work's quadratic part, which is already close: the last correction
    // is taken without another, within 3e-8 of the step (measured: 2.9e-8; 3.9e-9 with 1e-3;
    // from the bracket's middle, where the corrections before it are large, 7e-16).
    expect(rootC0).toBeLessThan(1e-12);
    expect(rootR).toBeLessThan(5e-8);
  });
});

describe('express path', () => {
  it('gives the same bits whatever impact came before (sinθ and cosθ are kept only for the same R and h)', () => {
    // Each set of constants with a slightly different h, the same R: R alone must not match.
    const sets = TABLE_PARAMS.flatMap(([, p]) => [p, { ...p, h: p.h * (1 + 1e-9) }]);
    const cases = sets.flatMap((p) => benchGrid(p.R).filter((_, i) => i % 37 === 0).map((g) => ({ st: g.state, p })));
    const alone = cases.map(({ st, p }) => {
      cushionImpact({ ...st, vx: st.vx + 0.1 }, { ...p, h: 1.5 * p.R }); // another table in between
      return cushionImpact(st, p).state;
    });
    fc.assert(
      fc.property(fc.shuffledSubarray(cases.map((_, i) => i), { minLength: cases.length }), (order) => {
        for (const i of order) expect(cushionImpact(cases[i]!.st, cases[i]!.p).state).toEqual(alone[i]);
      }),
      { numRuns: 20, seed: 3 },
    );
  });

  it('takes most of the benchmark grid and agrees with the solver there, for every set of constants', () => {
    for (const [name, p] of TABLE_PARAMS) {
      let taken = 0;
      let worst = 0;
      let seriesSteps = 0;
      let solverSteps = 0;
      const grid = benchGrid(p.R);
      for (const g of grid) {
        const x = express(g.state, p);
        if (x === null) continue;
        taken++;
        const solver = cushionImpactSolver(g.state, p);
        worst = Math.max(worst, relError(asState(x), solver.state, p.R, g.V0));
        // cushionImpact reports it: the series steps, none rejected.
        const k = cushionImpact(g.state, p);
        expect(k.rejectedSteps).toBe(0);
        seriesSteps += k.steps;
        solverSteps += solver.steps;
      }
      expect(taken / grid.length, name).toBeGreaterThan(0.5);
      // Longer steps: what the path is for.
      expect(seriesSteps, name).toBeLessThan(0.8 * solverSteps);
      // Each is within about 3e-6 V0 of the converged solution (the accuracy tests).
      expect(worst, name).toBeLessThan(6e-6);
    }
  });

  it('chooses its steps by the ratio test: most of the grid in three steps or fewer, the hard ones still accurate', () => {
    // The last terms alone (Jorba and Zou's choice: RATIO_GAIN 1) end 176 of the 528 impacts in
    // at most three series steps at this tolerance (200 at the solver's, as before the ratio
    // test). Topspin and sidespin k = 2 at 65° and 75° is where the terms' ratio misleads: with
    // RATIO_GAIN 2 and no RATIO_FLOOR these ended 1.0e-5 and 8.7e-6 V0 off.
    let short = 0;
    for (const g of benchGrid(PAPER.R)) {
      const n = expressSteps(g.state, PAPER);
      if (n > 0 && n <= 3) short++;
    }
    expect(short).toBeGreaterThan(280); // 296 with the ratio test
    for (const [alpha, kT, kS] of [[75, 2, 2], [65, 2, 2], [25, 2, 2]] as const) {
      const st = paperState(2, alpha, kT, kS, PAPER.R);
      const x = express(st, PAPER);
      expect(x).not.toBeNull();
      expect(relError(asState(x!), referenceRebound(st, PAPER).state, PAPER.R, 2)).toBeLessThan(3e-6);
    }
    // The floor on the last term's level (RATIO_FLOOR) binds at 75°: 1.4e-6 V0 with it, 1.95e-6
    // without.
    const st = paperState(2, 75, 2, 2, PAPER.R);
    expect(relError(asState(express(st, PAPER)!), referenceRebound(st, PAPER).state, PAPER.R, 2)).toBeLessThan(1.6e-6);
  });

  it('agrees with the solver on random impacts with the tables\' constants', () => {
    fc.assert(
      fc.property(issueImpact, ({ V0, params: p, state: st }) => {
        const x = express(st, p);
        if (x === null) return;
        expect(relError(asState(x), cushionImpactSolver(st, p).state, p.R, V0)).toBeLessThan(6e-6);
      }),
      { numRuns: 300, seed: 20261122 },
    );
  });

  it('takes a ball rolling on the cloth (table slip zero) from the start, as the solver does', () => {
    for (const [name, p] of TABLE_PARAMS) {
      let taken = 0;
      let n = 0;
      for (let alpha = 5; alpha < 90; alpha += 10) {
        for (const kS of [-2, -1, 0, 0.5, 1.5]) {
          const st = paperState(1.5, alpha, 1, kS, p.R);
          n++;
          const x = express(st, p);
          if (x === null) continue;
          taken++;
          expect(relError(asState(x), cushionImpactSolver(st, p).state, p.R, 1.5)).toBeLessThan(6e-6);
        }
      }
      expect(taken / n, name).toBeGreaterThan(0.6);
    }
  });

  it('declines a table contact that keeps rolling, and slips that start or come near zero', () => {
    // Natural roll at 45° with table friction 0.7: the friction that keeps the table contact
    // rolling is inside its cone (the solver's rolling conditions).
    const roll = paperState(1, 45, 1, 0, PAPER.R);
    expect(express(roll, PAPER)).not.toBeNull();
    expect(expressSteps(roll, { ...PAPER, muS: 0.7 })).toBe(0);
    // Head-on with no spin: the cushion slip closes on zero and sticks, the solver decides.
    const headOn = paperState(1, 89.5, 0, 0, PAPER.R);
    expect(express(headOn, PAPER)).toBeNull();
    // A table slip just below the threshold at the start (not zero): (vx - R ωy, vy + R ωx) = (e, 0).
    const st = { vx: 0.6, vy: 0.8, wx: -0.8 / PAPER.R, wy: 0, wz: 0 };
    const e = EXPRESS_SLIP_MIN * 0.99;
    expect(express({ ...st, wy: (st.vx - e) / PAPER.R }, PAPER)).toBeNull();
  });

  it('hands an impact that leaves its branch over to the solver, which continues it', () => {
    // Slips that come near zero after some series steps: the solver continues from the start of
    // the step that left, in compression or in restitution; the result is the solver's.
    let handed = 0;
    let inRestitution = 0;
    for (const [, p] of TABLE_PARAMS) {
      for (const g of benchGrid(p.R)) {
        const n = expressSteps(g.state, p);
        if (n >= 0) continue;
        handed++;
        if (EXPRESS_HANDOVER.restitution) inRestitution++;
        const k = cushionImpact(g.state, p);
        expect(k.steps).toBeGreaterThan(-n);
        expect(relError(k.state, cushionImpactSolver(g.state, p).state, p.R, g.V0)).toBeLessThan(6e-6);
      }
    }
    expect(handed).toBeGreaterThan(50);
    expect(inRestitution).toBeGreaterThan(0);
  });

  it('declines constants with which the table could stop pushing or the cushion could stop pushing out', () => {
    const st = paperState(1, 15, 2, 2, PAPER.R);
    expect(express(st, PAPER)).not.toBeNull();
    // sinθ = 0.05 < μw cosθ: the table's normal impulse could reach zero.
    expect(express(st, { ...PAPER, h: 1.05 * PAPER.R, muW: 0.2 })).toBeNull();
    // μw sinθ + μs (sinθ + μw cosθ) >= cosθ: the impulse could stop pushing the ball out.
    expect(express(st, { ...PAPER, muS: 2, muW: 0.1 })).toBeNull();
  });

  it('ends at the end of compression with e_e = 0, as the solver does', () => {
    const p = { ...PAPER, ee: 0 };
    const st = paperState(2, 40, 0.5, -1, p.R);
    const x = express(st, p);
    expect(x).not.toBeNull();
    expect(Math.abs(x![1]!)).toBeLessThan(1e-9);
    expect(relError(asState(x!), cushionImpactSolver(st, p).state, p.R, 2)).toBeLessThan(6e-6);
  });
});
