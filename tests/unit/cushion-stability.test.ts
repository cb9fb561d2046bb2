// Hard cases and invariants of the cushion kernel (issue 3, "Stability"): grazing, very slow and
// very fast impacts, extreme spin, exact zeros head-on, mirror symmetry, frictionless and
// extreme restitution, the impact whose restitution can never reach its target, no impact,
// bad input, and energy that never grows.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { cushionRebound } from '../../shared/physics/index.ts';
import { cushionImpact, cushionTrace, MAX_STEPS } from '../../shared/physics/diagnostics.ts';
import type { CushionParams, CushionState } from '../../shared/physics/index.ts';
import { referenceRebound } from '../support/cushion-reference.ts';
import { energy, PAPER, paperState, relError, TABLE_PARAMS } from '../support/cushion-cases.ts';
import { issueRange } from '../support/cushion-arbitraries.ts';

const { M, R } = PAPER;
/** Roundoff allowance on energy: the model dissipates or (frictionless, e_e = 1) conserves. */
const ENERGY_SLACK = 1e-12;

function finite(s: CushionState): boolean {
  return [s.vx, s.vy, s.wx, s.wy, s.wz].every(Number.isFinite);
}

/** The rebound, checked finite and with no energy gained by the solver itself (before the guard). */
function noEnergyGained(s: CushionState, params: CushionParams = PAPER): CushionState {
  const k = cushionImpact(s, params);
  expect(finite(k.state)).toBe(true);
  expect(energy(k.unguarded, params.M, params.R)).toBeLessThanOrEqual(energy(s, params.M, params.R) * (1 + ENERGY_SLACK));
  return k.state;
}

/** The same outcome as the reference, within 1e-5 V0, in fewer than maxSteps steps. */
function matchesReference(
  s: CushionState, params: CushionParams = PAPER, maxSteps = MAX_STEPS,
): ReturnType<typeof cushionImpact> {
  const k = cushionImpact(s, params);
  const r = referenceRebound(s, params);
  expect(k.outcome).toBe(r.outcome);
  expect(k.steps).toBeLessThan(maxSteps);
  expect(relError(k.state, r.state, params.R, Math.hypot(s.vx, s.vy))).toBeLessThan(1e-5);
  return k;
}

/**
 * A near-threshold draw (h / R, e_e, μs, μw, incidence in degrees, topspin k, sidespin k; paper
 * R and M, V0 = 1) that rebounds as the reference does, in fewer than maxSteps steps.
 */
function reboundsAsReference(c: readonly [number, number, number, number, number, number, number], maxSteps: number): void {
  const [hR, ee, muS, muW, alpha, kT, kS] = c;
  const k = matchesReference(paperState(1, alpha, kT, kS, R), { M, R, h: hR * R, ee, muS, muW }, maxSteps);
  expect(k.outcome).toBe('restitution');
  expect(k.state.vy).toBeLessThan(-1e-3);
}

describe('grazing incidence', () => {
  it.each([0.5, 0.1])('%f°: rebounds, loses energy, matches the reference', (alpha) => {
    for (const kT of [-1, 0, 1, 2]) {
      for (const kS of [-2, 0, 2]) {
        const s = paperState(2, alpha, kT, kS, R);
        const out = noEnergyGained(s);
        expect(out.vy).toBeLessThan(0);
        matchesReference(s);
      }
    }
  });
});

describe('speed extremes', () => {
  it.each([0.01, 0.05])('very slow, %f m/s: finite, no energy gained, matches the reference', (V0) => {
    for (const alpha of [1, 30, 60, 89]) {
      const s = paperState(V0, alpha, 1, 1, R);
      noEnergyGained(s);
      matchesReference(s);
    }
  });

  it('5 m/s, beyond the rigid-cushion limit: finite, no energy gained', () => {
    for (const alpha of [10, 45, 80, 90]) {
      for (const kT of [-1, 2]) noEnergyGained(paperState(5, alpha, kT, -2, R));
    }
  });

  it('extreme spin, |ω| R = 3 V0, in every direction: finite, no energy gained, matches the reference', () => {
    for (const [kT, kS] of [[3, 0], [-3, 0], [0, 3], [0, -3], [2.1, 2.1], [-2.1, -2.1]] as const) {
      for (const alpha of [5, 45, 85]) {
        const s = paperState(1, alpha, kT, kS, R);
        noEnergyGained(s);
        matchesReference(s);
      }
    }
  });
});

describe('exact zeros and symmetry', () => {
  it('head-on with natural roll: vx, wy and wz stay exactly 0', () => {
    for (const [, params] of TABLE_PARAMS) {
      for (const V0 of [0.05, 1, 5]) {
        const out = cushionRebound({ vx: 0, vy: V0, wx: -V0 / params.R, wy: 0, wz: 0 }, params);
        expect(out.vx).toBe(0);
        expect(out.wy).toBe(0);
        expect(out.wz).toBe(0);
        expect(out.vy).toBeLessThan(0);
      }
    }
  });

  it('a slip that is exactly zero at the start (the table contact of a rolling ball) is handled by the rolling conditions', () => {
    for (const alpha of [20, 50, 80]) {
      const s = paperState(1, alpha, 1, 0, R);
      expect(Math.hypot(s.vx - s.wy * R, s.vy + s.wx * R)).toBeLessThan(1e-12);
      matchesReference(s);
    }
    // The cushion contact at zero slip: ω_x R = vy sin θ, vx = 0, no spin about y or z.
    const sin = (PAPER.h - R) / R;
    matchesReference({ vx: 0, vy: 1, wx: sin / R, wy: 0, wz: 0 });
    matchesReference({ vx: 0.3, vy: 1, wx: sin / R, wy: 0, wz: 0.3 / (R * Math.sqrt(1 - sin * sin)) });
  });

  it('mirror symmetry x -> -x (vx, wy, wz change sign; vy, wx do not) holds to 1e-12', () => {
    fc.assert(
      fc.property(
        issueRange.V0,
        issueRange.alpha,
        issueRange.kT,
        issueRange.kS,
        (V0, alpha, kT, kS) => {
          const s = paperState(V0, alpha, kT, kS, R);
          const a = cushionRebound(s, PAPER);
          const b = cushionRebound({ vx: -s.vx, vy: s.vy, wx: s.wx, wy: -s.wy, wz: -s.wz }, PAPER);
          const tol = 1e-12 * V0;
          return Math.abs(a.vx + b.vx) <= tol && Math.abs(a.vy - b.vy) <= tol &&
            R * Math.abs(a.wx - b.wx) <= tol && R * Math.abs(a.wy + b.wy) <= tol && R * Math.abs(a.wz + b.wz) <= tol;
        },
      ),
      { numRuns: 200, seed: 7 },
    );
  });

  it('is deterministic: the same input gives the same bits', () => {
    const s = paperState(2, 45, 1.5, 2, R);
    expect(cushionRebound(s, PAPER)).toEqual(cushionRebound(s, PAPER));
  });
});

describe('frictionless and extreme restitution', () => {
  it('μ_w = 0: the cushion exerts no torque about z (wz unchanged), matches the reference', () => {
    const params = { ...PAPER, muW: 0 };
    for (const alpha of [10, 45, 80]) {
      const s = paperState(1, alpha, 0.5, 1, R);
      expect(cushionRebound(s, params).wz).toBe(s.wz);
      matchesReference(s, params);
    }
  });

  it('μ_s = 0 within 1e-14 to 1e-6 rad of head-on, no spin: ends and matches the reference', () => {
    // A rule tried at the third stop of 2026-12-01 (a slaved slip that three aimed steps left in
    // place taken as zero) sent four of these to the step cap.
    const params = { ...PAPER, h: 1.29 * R, muS: 0, muW: 0.098 };
    for (const vx of [1e-14, 1e-12, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6]) matchesReference({ vx, vy: 1, wx: 0, wy: 0, wz: 0 }, params, 200);
  });

  it('μ_s = 0: matches the reference', () => {
    for (const alpha of [10, 45, 80]) matchesReference(paperState(1, alpha, 1, -1, R), { ...PAPER, muS: 0 });
  });

  it('μ_s = μ_w = 0, e_e = 1: vy reverses, nothing else changes, energy is conserved', () => {
    const params = { ...PAPER, muS: 0, muW: 0, ee: 1 };
    const s = paperState(1.3, 37, 1, 2, R);
    const out = cushionRebound(s, params);
    expect(out.vy).toBeCloseTo(-s.vy, 12);
    expect(out.vx).toBe(s.vx);
    expect(out.wx).toBe(s.wx);
    expect(out.wy).toBe(s.wy);
    expect(out.wz).toBe(s.wz);
    expect(Math.abs(energy(out, M, R) / energy(s, M, R) - 1)).toBeLessThan(1e-12);
  });

  it('e_e = 0: the ball leaves with vy = 0 at the end of compression; e_e = 1 matches the reference', () => {
    for (const alpha of [20, 60, 89]) {
      const s = paperState(1, alpha, 1, 1, R);
      const k = cushionImpact(s, { ...PAPER, ee: 0 });
      expect(k.outcome).toBe('restitution');
      expect(Math.abs(k.state.vy)).toBeLessThan(1e-12);
      matchesReference(s, { ...PAPER, ee: 0 });
      matchesReference(s, { ...PAPER, ee: 1 });
    }
  });

  it('e_e near 0 but not 0: the ball never leaves moving into the cushion (vy <= 0)', () => {
    // Restitution then ends at the rounding of W_c, which can fall a hair before vy's zero: on
    // random draws vy came out at 1e-39 to 1e-238 m/s, into the cushion.
    fc.assert(
      fc.property(
        fc.double({ min: 1e-6, max: 5, noNaN: true }),
        fc.double({ min: 0.5, max: 89.5, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: 1.02, max: 1.98, noNaN: true }),
        fc.double({ min: 0, max: 1e-8, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (V0, alpha, kT, kS, hR, ee, muS, muW) => {
          const p = { M, R, h: hR * R, ee, muS, muW };
          const st = paperState(V0, alpha, kT, kS, R);
          return cushionRebound(st, p).vy <= 0 && cushionImpact(st, p).state.vy <= 0;
        },
      ),
      { numRuns: 500, seed: 12 },
    );
  });
});

describe('an impact whose restitution can never reach its target', () => {
  // With friction at least cos θ / (1 + sin θ) at both contacts, both contacts can roll at once:
  // the rolling conditions then make every rate zero with vy = 0, and the impulse can do no more
  // work. The documented result: outcome 'stalled', the state at that instant, vy = 0.
  const sticky = { ...PAPER, muS: 0.8, muW: 0.8, h: 1.8 * R };

  it('ends, outcome stalled, vy = 0, the same as the reference', () => {
    for (const [alpha, kT, kS] of [[90, 0, 0], [60, -1, 0], [45, 2, 0], [80, 0, 1]] as const) {
      const s = paperState(1, alpha, kT, kS, R);
      const k = cushionImpact(s, sticky);
      expect(k.outcome).toBe('stalled');
      expect(k.state.vy).toBe(0);
      expect(k.steps).toBeLessThan(MAX_STEPS / 20);
      const r = referenceRebound(s, sticky);
      expect(r.outcome).toBe('stalled');
      expect(relError(k.state, r.state, R, 1)).toBeLessThan(1e-5);
      expect(energy(k.state, M, R)).toBeLessThan(energy(s, M, R));
    }
  });

  it('never loops: friction up to 2 with the extreme cushion heights ends too', () => {
    for (const mu of [1, 2]) {
      for (const h of [1.2 * R, 1.5 * R, 1.99 * R]) {
        for (const alpha of [3, 45, 89.5]) {
          const k = cushionImpact(paperState(1, alpha, 1, 1, R), { ...PAPER, muS: mu, muW: mu, h });
          expect(finite(k.state)).toBe(true);
          expect(k.steps).toBeLessThan(MAX_STEPS);
        }
      }
    }
  });

  it('friction at the both-rolling threshold: a slip whose rates vanish is held, and the long creep ends', () => {
    // μ = cos θ / (1 + sin θ) = 0.5 at h = 1.6 R: one direction of the cushion slip has rate zero
    // whatever its size, so the slip stays put while vy stays small and the work falls slowly.
    // Integrated as it is, the stiff slip took steps of a fraction of itself until the step cap
    // threw (164 impacts of a 21,000-impact high-friction grid); held, it ends in < 100 steps.
    const knife = { ...PAPER, muW: 0.5, muS: 1, ee: 0.5, h: 1.6 * R };
    matchesReference(paperState(1, 60, 0, 2, R), knife, MAX_STEPS / 20);
    for (const muS of [0.5, 0.8, 2]) {
      for (const [alpha, kT, kS] of [[60, 1, 0], [85, 0, 0], [89.5, -1, 0], [60, 0, 2]] as const) {
        for (const ee of [0.5, 0.98]) {
          const st = paperState(1, alpha, kT, kS, R);
          const out = cushionImpact(st, { ...knife, muS, ee });
          expect(finite(out.state)).toBe(true);
          expect(out.steps).toBeLessThan(MAX_STEPS / 20);
          expect(energy(out.state, M, R)).toBeLessThanOrEqual(energy(st, M, R) * (1 + 1e-12));
        }
      }
    }
  });

  it('a table slip creeping to zero along y with the cushion contact rolling is slaved, and the impact stalls as the reference does', () => {
    // μw 1.27, μs 0.71: the cushion contact rolls, the table slip shrinks along -y at a rate
    // proportional to itself, and vy with it; followed in its own direction the stiff slip took
    // steps of a fraction of itself until the step cap threw. Slaved along y it reaches zero.
    const params = { M, R, h: 1.3341578364372255 * R, ee: 0.8355621099472046, muS: 0.7066681981086731, muW: 1.26960951089859 };
    matchesReference(paperState(0.011325368881225586, 71.5063042064663, 0.5401804447174072, 1.7965729236602783, R), params, MAX_STEPS / 2);
  });

  it('a slaved slip whose slaved direction jumps however short the step is released, not retried without end', () => {
    // μw 1.49, μs 1.21, h 1.7 R: two roots of the slaved direction's equation trade places, so
    // the slaving bound's turn stayed 0.07 rad at steps of 1e-18 and every step was rejected
    // until the step cap threw.
    const params = { M, R, h: 1.7022169598937036 * R, ee: 0.19457193976268172, muS: 1.2128499154932797, muW: 1.486025221645832 };
    matchesReference(paperState(0.4092257998324931, 79.18773647546769, 1.2336058742366731, 1.4062920520082116, R), params, MAX_STEPS / 20);
  });

  it('contacts trading sticking at vy = 0 in restitution end stalled, as the reference does', () => {
    // μw 1.74, μs 0.91, h 1.06 R: with vy within 2e-8 m/s of zero the contacts took turns to
    // stick, each turn a step too short to move p, until the step cap threw.
    const params = { M, R, h: 1.0632734904438257 * R, ee: 0.32232774212025106, muS: 0.9093467891216278, muW: 1.7445664103142917 };
    const k = matchesReference(paperState(0.22942520793527366, 83.03270887886174, -2.9974050200544298, -2.9147382848896086, R), params, MAX_STEPS / 20);
    expect(k.outcome).toBe('stalled');
    expect(k.state.vy).toBe(0);
  });

  it('a cushion slip pinned along y while the table contact rolls is not held to its relaxation steps', () => {
    // Cushion friction just below the both-rolling threshold cos θ / (1 + sin θ): the cushion
    // slip leaves a zero along +y with the table contact rolling, and stays exactly along y.
    // Bounded by its relaxation limit, the first crept 700 m/s of impulse in steps of 0.011, the
    // second grew from 4e-9 m/s by 0.03% a step: both threw at the step cap (20000).
    const creep = { M, R, h: 1.6650346096605062 * R, ee: 0.8014948160853237, muS: 1.2499928763136268, muW: 0.44839130714535713 };
    const k = matchesReference(paperState(3.9794944187067447, 64.91499972613528, 0.8641871865838766, 0.6115618469193578, R), creep, 200);
    expect(k.outcome).toBe('restitution');
    const onset = { M, R, h: 1.4682583466917276 * R, ee: 0.02180321072228253, muS: 1.5290587563067675, muW: 0.6015911819413304 };
    matchesReference(paperState(0.1757225973904133, 72.11855995615478, -0.6047184211201966, 1.7527369279414415, R), onset, 200);
    // Inputs next to the first (topspin + 0.001, incidence + 0.001°, μs × (1 + 1e-4)): the
    // cushion slip grows along y with an x part of 5e-8 of it, relaxing away, which kept its
    // relaxation bound on every step: these three threw at the step cap.
    const near: [number, number, number][] = [[0, 0, 0.001], [0, 0.001, 0], [1e-4, 0, 0]];
    for (const [dmu, da, dk] of near) {
      const p = { ...creep, muS: creep.muS * (1 + dmu) };
      const st = paperState(3.9794944187067447, 64.91499972613528 + da, 0.8641871865838766 + dk, 0.6115618469193578, R);
      expect(matchesReference(st, p, 200).outcome).toBe('restitution');
    }
  });

  it('head-on with the cushion contact rolling through the end of compression: both slips are zero there, and the impact goes on as the reference does', () => {
    // The table slip is then (1 + s) vy, zero with vy. With the cushion high and its friction
    // above cot θ, the approximation both-slipping (the cushion slip upward) pushed the ball back
    // in and the impact stalled with vy = 0, up to 0.93 V0 off; the cushion contact rolling on
    // with the table slip leaving downward is consistent, and what impacts a hair off head-on do
    // (the reference, which had the same gap, now takes it too).
    const cases: [number, number, number, number, number, number][] = [
      // h / R, e_e, μs, μw, incidence (°), topspin k
      [1.9, 0.9, 0.2, 0.6, 90, 1],
      [1.8623, 0.5, 0, 0.6, 90, 1],
      [1.8623, 0.5, 0.2, 0.6, 89.9999, 1],
      [1.8, 0.9, 0.2, 0.5, 90, 0],
    ];
    for (const [hR, ee, muS, muW, alpha, kT] of cases) {
      const k = matchesReference(paperState(1, alpha, kT, 0, R), { M, R, h: hR * R, ee, muS, muW }, 200);
      expect(k.outcome).toBe('restitution');
      expect(k.state.vy).toBeLessThan(-0.1);
    }
  });

  it('a slaved cushion slip along y with the table contact rolling shrinks at its own rate, not at the pole of its direction\'s equation', () => {
    // Friction 3e-5 to 4e-4 below the both-rolling threshold: the slaved slip's rates are
    // a + B g with b12 = 0, and the pole of the slaved direction's equation gave NaN (0 times
    // an infinite u_y), taken for "no root": the slip was said to shrink at -0.91 where it shrank
    // at -3.5e-4, every step was aimed at a zero 2,600 times nearer than its own, and the step
    // cap threw (88 of 6,000 draws near the threshold).
    const cases: [number, number, number, number, number, number, number][] = [
      // h / R, e_e, μs, μw, incidence (°), topspin k, sidespin k
      [1.6590209867805241, 0.4746052418136969, 1.0553775248583406, 0.4532224922279454, 87.39343702211045, 0, 0],
      [1.8619899913668632, 0.6873574970522895, 1.1030285432469098, 0.27225850548322345, 80.82972832373343, 0, 0],
      [1.3914182542823255, 0.43944079251959917, 0.8504162668483332, 0.6615990768159611, 76.76027192850597, 0.35637546610087156, -0.24471214786171913],
    ];
    for (const [hR, ee, muS, muW, alpha, kT, kS] of cases) {
      matchesReference(paperState(1, alpha, kT, kS, R), { M, R, h: hR * R, ee, muS, muW }, 1000);
    }
  });

  it('vy back at zero in restitution with the table slip a hair from zero: the rolling conditions decide again, and the ball leaves as in the reference', () => {
    // Cushion friction 0.05-0.2% below the both-rolling threshold cos θ / (1 + sin θ), little or
    // no spin: a slip closes on zero with vy. It was left sliding at 1e-7 to 4e-7 of the speed,
    // vy came back to zero, and the impact stalled 5e-3 to 5e-2 V0 from the reference's slow
    // rebound (58 of 6,000 draws near the threshold; on the fast loop's path, the last case).
    const cases: [number, number, number, number, number, number][] = [
      // h / R, e_e, μs, μw, incidence (°), topspin k
      [1.6122919867280872, 0.6462997163180262, 0.9607881414704025, 0.4895980169530958, 87, 0],
      [1.6141485673375429, 0.866636358271353, 1.0494992047548295, 0.48862780219146873, 86.07586593017913, 0],
      [1.7004319837782533, 0.9876791607122868, 0.9202322002267465, 0.41874873677252095, 84.94881680700928, 0],
      [1.4702735241968186, 0.9507725919364021, 1.013840520568192, 0.5998324644057368, 89.39188068732619, -0.5010545034892857],
    ];
    for (const [hR, ee, muS, muW, alpha, kT] of cases) reboundsAsReference([hR, ee, muS, muW, alpha, kT, 0], 200);
  });

  it('the same with the slip 2e-6 to 1e-5 of the speed when vy comes back: taken as zero (within 10 times the tolerance), and the ball leaves as in the reference', () => {
    // At 10 event tolerances (the tolerance itself) these stalled 2e-3 to 5.7e-2 V0 from the
    // reference (an 85.57° impact and 6 of 6,000 draws near the threshold).
    const cases: [number, number, number, number, number, number, number][] = [
      // h / R, e_e, μs, μw, incidence (°), topspin k, sidespin k
      [1.6122919867280872, 0.6462997163180262, 0.9607881414704025, 0.4895980169530958, 85.57, 0, 0],
      [1.7031438344158232, 0.7819281188771128, 0.9673215072834864, 0.4151619477963602, 75.35438954480924, 0, 0.6032808218151331],
      [1.6343053915537893, 0.9237692585214972, 0.9902880762005224, 0.4686748085694954, 83.92199288704433, 0, 0],
      [1.682426886446774, 0.8883247916121035, 0.8890057177050039, 0.4309130004232755, 84.1169145971071, -0.8918974287807941, 0.3367413328960538],
    ];
    for (const c of cases) reboundsAsReference(c, 200);
  });

  it('vy within the event tolerance of zero at a step\'s start in restitution, both slips a hair from zero: the rolling conditions decide again there too', () => {
    // Draws near the both-rolling threshold that stalled at a step's start (1.75e-2 V0 off), and
    // one that did so once solved again as a slow rebound (1.10e-2 V0 off).
    const cases: [number, number, number, number, number, number, number][] = [
      // h / R, e_e, μs, μw, incidence (°), topspin k, sidespin k
      [1.8175504868850112, 0.37646371335722506, 1.0277235160348936, 0.31435817134585314, 87.31451284023933, -0.5964774712920189, 0.026756049133837223],
      [1.7965903766918927, 0.4409796231193468, 0.9724203117191792, 0.33579065146264725, 86.49672050960362, -0.7003643256612122, 0.8167714481242001],
    ];
    for (const c of cases) reboundsAsReference(c, 400);
  });

  it('a hair above the both-rolling threshold the impact stalls, and the reference\'s slow rebound shrinks with its step toward that stall', () => {
    // μw 1e-6 above cos θ / (1 + sin θ): both contacts end rolling with vy = 0. The reference
    // at its default 4,000 steps rebounded at -1.74e-4 V0 (1.7e-4 from the kernel, once taken
    // for the kernel's error); its rebound halves with each halving of its step (-1.1e-5 at
    // 64,000 steps, 'stalled' at 8,000 and 32,000).
    const R0 = 0.028;
    const s = 0.34;
    const c = Math.sqrt(1 - s * s);
    const params = { M: 0.17, R: R0, h: (1 + s) * R0, ee: 0.3, muS: 1, muW: (c / (1 + s)) * (1 + 1e-6) };
    const state = paperState(1, 85, 0, 0, R0);
    const k = cushionImpact(state, params);
    expect(k.outcome).toBe('stalled');
    expect(k.state.vy).toBe(0);
    const coarse = referenceRebound(state, params, 2000).state.vy;
    const fine = referenceRebound(state, params, 4000).state.vy;
    expect(coarse).toBeLessThan(0);
    expect(Math.abs(fine / coarse - 0.5)).toBeLessThan(0.01);
  });

  it('a ball that leaves at a small fraction of e_e vy0 after a long restitution is solved again at a finer tolerance, and matches the reference', () => {
    // μw 0.19% above the both-rolling threshold: vy leaves at 0.4% of e_e vy0, where an error in
    // the work moves the end by hundreds of times more than the work's error weight assumes; at
    // the default tolerance alone this ended 1.39e-5 V0 from the reference.
    const params = { M, R, h: 1.8841595744248478 * R, ee: 0.8235459947260095, muS: 0.862118892231956, muW: 0.24842732849770688 };
    const s = paperState(1, 80.43961425544694, 0, -0.982480697799474, R);
    const k = matchesReference(s, params, 400);
    expect(k.outcome).toBe('restitution');
    expect(-k.state.vy).toBeLessThan(0.1 * params.ee * s.vy);
    expect(relError(k.state, referenceRebound(s, params).state, R, 1)).toBeLessThan(1e-6);
  });

  it('a contact decided rolling is never aimed at zero again (regression: a loop of steps too small to move)', () => {
    // μw 0.5 at the paper's height: both slips reach zero together, the table contact rolls and
    // the cushion contact slips on; a stale slaving flag on the rolling contact made every step
    // aim its 4e-22 m/s residual at zero with a step of 1e-21, which did not move p, until the
    // step cap threw.
    for (const [muS, ee] of [[0.8, 0.5], [2, 0.98]] as const) {
      matchesReference(paperState(1, 60, 1, 0, R), { ...PAPER, muW: 0.5, muS, ee }, MAX_STEPS / 20);
    }
  });
});

describe('step control', () => {
  it('a slip closing on zero is approached in steps the error allows, not rejected at every step, and the step restarts once it rolls', () => {
    // Near head-on without spin the cushion contact sticks: its slip closes on zero while its
    // direction turns ever faster, so each step can cover only a fraction of the distance left.
    // Control on the step's size alone proposed about the whole distance each time, and the step
    // aimed at the zero was rejected (13, 18 and 19 rejections here; approachFactor). Once the
    // contact rolls, the step restarts from the steps before the approach, not from its last
    // tiny one (afterZero): 59, 70 and 75 steps before both, 44, 52 and 55 with the
    // first alone, 37, 43 and 46 now.
    for (const alpha of [75, 85, 89.5]) {
      const k = matchesReference(paperState(2, alpha, 0, 0, R));
      expect(k.rejectedSteps).toBeLessThanOrEqual(3);
      expect(k.steps).toBeLessThan(50);
      const r = referenceRebound(paperState(2, alpha, 0, 0, R), PAPER);
      expect(relError(k.state, r.state, R, 2)).toBeLessThan(2e-6);
    }
  });

  it('the step after a slip reached its zero is not scaled as an approach, nor is a frictionless contact\'s', () => {
    // Head-on with a frictionless cushion: the table slip reaches zero and grows again, slaved.
    // Scaled by its approach (a fifth), the next steps crept up from there: 88 steps where 51
    // did before the approach was controlled, and 268 of 840 such impacts took more steps.
    const R0 = 0.028;
    const params = { M: 0.17, R: R0, h: 1.92 * R0, ee: 0.7, muS: 0.119, muW: 0 };
    const k = matchesReference(paperState(1, 90, 0.9, -3, R0), params);
    expect(k.steps).toBeLessThanOrEqual(51);
  });
});

describe('no impact and bad input', () => {
  it('vy <= 0 returns an equal copy, not the same object', () => {
    for (const s of [{ vx: 1, vy: 0, wx: 2, wy: 3, wz: 4 }, { vx: -1, vy: -0.5, wx: 0, wy: 1, wz: -4 }]) {
      const out = cushionRebound(s, PAPER);
      expect(out).toEqual(s);
      expect(out).not.toBe(s);
      expect(cushionImpact(s, PAPER).outcome).toBe('no-impact');
    }
  });

  const good: CushionState = { vx: 0.5, vy: 1, wx: 0, wy: 0, wz: 0 };
  it.each([
    ['state.vx', { ...good, vx: Number.NaN }, PAPER],
    ['state.vy', { ...good, vy: Number.POSITIVE_INFINITY }, PAPER],
    ['state.wx', { ...good, wx: Number.NEGATIVE_INFINITY }, PAPER],
    ['state.wy', { ...good, wy: Number.NaN }, PAPER],
    ['state.wz', { ...good, wz: Number.NaN }, PAPER],
    ['params.M', good, { ...PAPER, M: 0 }],
    ['params.M', good, { ...PAPER, M: -1 }],
    ['params.M', good, { ...PAPER, M: Number.NaN }],
    ['params.R', good, { ...PAPER, R: 0 }],
    ['params.R', good, { ...PAPER, R: Number.POSITIVE_INFINITY }],
    ['params.h', good, { ...PAPER, h: PAPER.R }],
    ['params.h', good, { ...PAPER, h: 2 * PAPER.R }],
    ['params.h', good, { ...PAPER, h: 0.5 * PAPER.R }],
    ['params.ee', good, { ...PAPER, ee: -0.1 }],
    ['params.ee', good, { ...PAPER, ee: 1.01 }],
    ['params.muS', good, { ...PAPER, muS: -0.01 }],
    ['params.muW', good, { ...PAPER, muW: -0.01 }],
    ['params.muW', good, { ...PAPER, muW: Number.NaN }],
  ])('%s: a RangeError that names it', (field, s, p) => {
    expect(() => cushionRebound(s, p)).toThrow(RangeError);
    expect(() => cushionRebound(s, p)).toThrow(`cushionRebound: ${field} `);
  });

  it('a field that is not a number, or a state or params that is not an object: a RangeError that names it', () => {
    const cases: [string, unknown, unknown][] = [
      ['state.vx', { ...good, vx: '0.5' }, PAPER],
      ['state.wz', { ...good, wz: 1n }, PAPER],
      ['state.wy', { vx: 0.5, vy: 1, wx: 0, wz: 0 }, PAPER],
      ['params.h', good, { ...PAPER, h: undefined }],
      ['params.muS', good, { ...PAPER, muS: null }],
      ['state', null, PAPER],
      ['state', 3, PAPER],
      ['params', good, null],
      ['params', good, 'paper'],
      // The state is checked before the params, as the fields are in order.
      ['state.vx', { ...good, vx: Number.NaN }, null],
      ['state.vy', { ...good, vy: Number.NaN }, { ...PAPER, M: -1 }],
    ];
    for (const [field, s, p] of cases) {
      expect(() => cushionRebound(s as CushionState, p as CushionParams)).toThrow(new RegExp(`^cushionRebound: ${field.replace('.', '\\.')} `));
      expect(() => cushionImpact(s as CushionState, p as CushionParams)).toThrow(new RegExp(`^cushionRebound: ${field.replace('.', '\\.')} `));
    }
  });

  it('cushionRebound, cushionImpact and cushionTrace give the same bits: one solver for every caller', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.05, max: 5, noNaN: true }),
        fc.double({ min: 0.5, max: 89.5, noNaN: true }),
        fc.double({ min: -1, max: 2, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.constantFrom(...TABLE_PARAMS.map(([, p]) => p)),
        (V0, alpha, kT, kS, params) => {
          const s = paperState(V0, alpha, kT, kS, params.R);
          const k = cushionImpact(s, params);
          expect(cushionRebound(s, params)).toStrictEqual(k.state);
          expect(cushionTrace(s, params).state).toStrictEqual(k.state);
        },
      ),
      { numRuns: 200, seed: 3 },
    );
  });

  it('a bad tolerance: a RangeError naming options.tolerance', () => {
    for (const tolerance of [0, -1, 1, Number.NaN, 'precise' as never]) {
      expect(() => cushionRebound(good, PAPER, { tolerance })).toThrow(/options\.tolerance/);
    }
  });
});

describe('energy never increases', () => {
  it('property: over the range and beyond, any constants', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.01, max: 8, noNaN: true }),
        fc.double({ min: 0.1, max: 90, noNaN: true }),
        fc.double({ min: -3, max: 3, noNaN: true }),
        fc.double({ min: -3, max: 3, noNaN: true }),
        fc.double({ min: 1.05, max: 1.95, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 0.6, noNaN: true }),
        fc.double({ min: 0, max: 0.6, noNaN: true }),
        (V0, alpha, kT, kS, hR, ee, muS, muW) => {
          const params = { M, R, h: hR * R, ee, muS, muW };
          const s = paperState(V0, alpha, kT, kS, R);
          // The solver itself, before the guard that scales a gain away: within its tolerance
          // (1e-6 of the speed per step, so about 1e-6 of the energy at most).
          const k = cushionImpact(s, params);
          const e0 = energy(s, M, R);
          return finite(k.unguarded) && energy(k.unguarded, M, R) <= e0 * (1 + 1e-6) &&
            energy(k.state, M, R) <= e0 * (1 + ENERGY_SLACK);
        },
      ),
      { numRuns: 400, seed: 42 },
    );
  });

  it('where the model dissipates next to nothing (friction near 0, e_e near 1), the integration error does not show as a gain', () => {
    // A random draw on which the solver once ended 3.0e-8 of the energy above what the ball
    // brought (the model's own loss here is about 5e-8 of it).
    const params = { M, R, h: 1.02 * R, ee: 0.9999999999999984, muS: 8.505816967877362e-7, muW: 4.825683239264199e-253 };
    const s = { vx: 1.4424003543007855, vy: 4.138207367143064, wx: -3.2e-321, wy: 1.117e-321, wz: -1.8482245042516025e-300 };
    // The solver's own error is inside its tolerance.
    expect(energy(cushionImpact(s, params).unguarded, M, R)).toBeLessThanOrEqual(energy(s, M, R) * (1 + 1e-6));
    for (const out of [cushionRebound(s, params), cushionImpact(s, params).state]) {
      expect(energy(out, M, R)).toBeLessThanOrEqual(energy(s, M, R));
      // Scaled down, not replaced: still within the tolerance of the reference.
      expect(relError(out, referenceRebound(s, params).state, R, Math.hypot(s.vx, s.vy))).toBeLessThan(1e-5);
    }
    fc.assert(
      fc.property(
        fc.double({ min: 0.05, max: 5, noNaN: true }),
        fc.double({ min: 0.5, max: 89.5, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: -2, max: 2, noNaN: true }),
        fc.double({ min: 1.02, max: 1.98, noNaN: true }),
        fc.double({ min: 0, max: 1e-5, noNaN: true }),
        fc.double({ min: 0, max: 1e-5, noNaN: true }),
        (V0, alpha, kT, kS, hR, muS, muW) => {
          const p = { M, R, h: hR * R, ee: 1, muS, muW };
          const st = paperState(V0, alpha, kT, kS, R);
          const k = cushionImpact(st, p);
          const e0 = energy(st, M, R);
          return energy(k.state, M, R) <= e0 && energy(k.unguarded, M, R) <= e0 * (1 + 1e-6);
        },
      ),
      { numRuns: 300, seed: 8 },
    );
  });
});
