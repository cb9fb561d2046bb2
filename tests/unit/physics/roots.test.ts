import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { evalPoly, firstEntry, quadraticRoots, rootsIn } from '../../../shared/physics/roots.ts';

/** (t - r1)(t - r2)... times k, ascending coefficients. */
function fromRoots(roots: number[], k = 1): number[] {
  let c = [k];
  for (const r of roots) {
    const next = new Array<number>(c.length + 1).fill(0);
    c.forEach((v, i) => {
      next[i + 1]! += v;
      next[i]! -= r * v;
    });
    c = next;
  }
  return c;
}

describe('polynomial roots', () => {
  it('finds every root of a quartic with four real roots, ascending', () => {
    const roots = rootsIn(fromRoots([0.1, 0.5, 0.9, 1.7]), 0, 2);
    expect(roots).toHaveLength(4);
    [0.1, 0.5, 0.9, 1.7].forEach((r, i) => expect(roots[i]).toBeCloseTo(r, 12));
  });

  it('solves quadratics without cancellation', () => {
    const [a, b] = quadraticRoots(1e-10, -1, 1); // roots 1e-10 (approx) and 1
    expect(Math.abs(a! - 1.0000000001e-10) / 1e-10).toBeLessThan(1e-14); // the small root, to full precision
    expect(b).toBeCloseTo(0.9999999999, 14);
    expect(quadraticRoots(1, 0, 1)).toEqual([]);
  });

  it('firstEntry returns the last time before the gap closes, never after', () => {
    const c = fromRoots([0.3, 0.8], 1); // positive before 0.3
    const t = firstEntry(c, 0, 1, 1e-14);
    expect(t).toBeLessThanOrEqual(0.3);
    expect(0.3 - t).toBeLessThan(1e-13);
    expect(evalPoly(c, t)).toBeGreaterThanOrEqual(0);
  });

  it('catches a dip that is positive at both ends of the interval (a grazing pass)', () => {
    // (t - 0.5)^2 - 1e-12: dips to -1e-12 around t = 0.5, positive at 0 and 1.
    const c = [0.25 - 1e-12, -1, 1];
    const t = firstEntry(c, 0, 1, 1e-15);
    expect(t).toBeGreaterThan(0.49);
    expect(t).toBeLessThan(0.5);
    // A double root that only touches zero also counts as contact.
    expect(firstEntry([0.25, -1, 1], 0, 1, 1e-15)).toBeCloseTo(0.5, 6);
    // And a pass that stays clear does not.
    expect(firstEntry([0.25 + 1e-12, -1, 1], 0, 1, 1e-15)).toBe(Infinity);
  });

  it('handles vanishing leading coefficients (equal accelerations make the quartic a quadratic)', () => {
    expect(firstEntry([1, -2, 0, 0, 0], 0, 10, 1e-14)).toBeCloseTo(0.5, 12);
    expect(firstEntry([1, 0, 0, 0, 0], 0, 10, 1e-14)).toBe(Infinity);
  });

  it('never misses a sign change that dense sampling finds (property)', () => {
    fc.assert(
      fc.property(fc.array(fc.double({ min: -1, max: 2, noNaN: true }), { minLength: 0, maxLength: 4 }), fc.double({ min: 0.05, max: 3, noNaN: true }), (roots, k) => {
        const c = fromRoots(roots, k);
        c[0]! += 1e-3; // lift it so it starts positive more often
        if (!(evalPoly(c, 0) > 0)) return;
        const t = firstEntry(c, 0, 2, 1e-13);
        let sampled = Infinity;
        for (let i = 0; i <= 4000; i++) {
          const s = (2 * i) / 4000;
          if (evalPoly(c, s) <= 0) {
            sampled = s;
            break;
          }
        }
        if (sampled !== Infinity) expect(t).toBeLessThanOrEqual(sampled);
        if (t !== Infinity) {
          expect(evalPoly(c, t)).toBeGreaterThanOrEqual(0);
          // Just after t the gap is closed (or within the bracket width of closing).
          expect(evalPoly(c, t + 2e-13)).toBeLessThanOrEqual(Math.max(1e-9, Math.abs(evalPoly(c, t)) * 10));
        }
      }),
      { numRuns: 3000 },
    );
  });
});
