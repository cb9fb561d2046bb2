import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { detAtan2, detExp, sinCos, wrapAngle } from '../../../shared/physics/det-math.ts';

describe('deterministic elementary functions', () => {
  it('agree with Math to a few ulp on the ranges the physics uses', () => {
    fc.assert(
      fc.property(fc.double({ min: -50, max: 50, noNaN: true }), (x) => {
        const { sin, cos } = sinCos(x);
        expect(Math.abs(sin - Math.sin(x))).toBeLessThan(1e-15);
        expect(Math.abs(cos - Math.cos(x))).toBeLessThan(1e-15);
      }),
      { numRuns: 5000 },
    );
    fc.assert(
      fc.property(fc.double({ min: -60, max: 60, noNaN: true }), (x) => {
        expect(Math.abs(detExp(x) / Math.exp(x) - 1)).toBeLessThan(2e-15);
      }),
      { numRuns: 5000 },
    );
    fc.assert(
      fc.property(fc.double({ min: -10, max: 10, noNaN: true }), fc.double({ min: -10, max: 10, noNaN: true }), (y, x) => {
        fc.pre(x !== 0 || y !== 0); // atan2 of two zeros depends on their signs; the physics never asks
        expect(Math.abs(detAtan2(y, x) - Math.atan2(y, x))).toBeLessThan(2e-15);
      }),
      { numRuns: 5000 },
    );
  });

  it('are exactly odd and even: sin(-x) = -sin(x) and cos(-x) = cos(x) to the bit, at multiples of π/4 too', () => {
    const check = (x: number) => {
      const p = sinCos(x);
      const m = sinCos(-x);
      expect(m.sin === -p.sin, `sin(${x})`).toBe(true); // === is bitwise but for the sign of zero
      expect(m.cos === p.cos, `cos(${x})`).toBe(true);
    };
    for (let k = -16; k <= 16; k++) check((k * Math.PI) / 4);
    fc.assert(fc.property(fc.double({ min: -50, max: 50, noNaN: true }), check), { numRuns: 5000 });
  });

  it('hit exact values where they must', () => {
    expect(sinCos(0)).toEqual({ sin: 0, cos: 1 });
    expect(detExp(0)).toBe(1);
    expect(detAtan2(0, 1)).toBe(0);
    expect(detAtan2(1, 0)).toBe(Math.PI / 2);
    expect(detAtan2(0, -1)).toBe(Math.PI);
    expect(detAtan2(0, 0)).toBe(0);
    expect(wrapAngle(-Math.PI / 2)).toBeCloseTo((3 * Math.PI) / 2, 15);
  });

  it('give the same bits on every engine: golden values computed once in Node', () => {
    const bits = (x: number) => {
      const v = new DataView(new ArrayBuffer(8));
      v.setFloat64(0, x);
      return v.getBigUint64(0).toString(16);
    };
    expect([sinCos(1).sin, sinCos(1).cos, sinCos(100).sin, detExp(-1.088), detAtan2(0.3, -0.7), detExp(3.5)].map(bits)).toEqual([
      '3feaed548f090cee',
      '3fe14a280fb5068c',
      'bfe03425b78c4db8',
      '3fd58f9965228e5f',
      '4005e4c36ca0118a',
      '40408ec721396bdc',
    ]);
  });
});
