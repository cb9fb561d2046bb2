import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { hashFinalState } from '../../../shared/physics/hash.ts';
import type { FinalBall } from '../../../shared/physics/index.ts';

/** The same encoding hashed with BigInt FNV-1a 64, straight from its definition. */
function reference(balls: readonly FinalBall[], duration: number, count: number): string {
  let h = 0xcbf29ce484222325n;
  const byte = (b: number) => {
    h = ((h ^ BigInt(b & 0xff)) * 0x100000001b3n) & 0xffffffffffffffffn;
  };
  const text = (s: string) => {
    for (let i = 0; i < s.length; i++) {
      byte(s.charCodeAt(i) & 0xff);
      byte(s.charCodeAt(i) >> 8);
    }
    byte(0);
  };
  const num = (x: number) => {
    const v = new DataView(new ArrayBuffer(8));
    v.setFloat64(0, x === 0 ? 0 : x, true);
    for (let i = 0; i < 8; i++) byte(v.getUint8(i));
  };
  for (const b of balls) {
    text(b.id);
    byte(b.pocketed ? 1 : 0);
    text(b.pocket ?? '');
    num(b.x);
    num(b.y);
  }
  num(duration);
  num(count);
  return h.toString(16).padStart(16, '0');
}

const ball = fc.record({ id: fc.string({ minLength: 1, maxLength: 6 }), x: fc.double({ noNaN: true }), y: fc.double({ noNaN: true }), pocketed: fc.boolean() }).map((b) => (b.pocketed ? { ...b, pocket: 'TL' } : b));

describe('the final-state hash', () => {
  it('is FNV-1a 64 of the canonical encoding, exactly (property against BigInt)', () => {
    fc.assert(
      fc.property(fc.array(ball, { maxLength: 5 }), fc.double({ noNaN: true }), fc.nat(), (balls, d, n) => {
        expect(hashFinalState(balls, d, n)).toBe(reference(balls, d, n));
      }),
      { numRuns: 500 },
    );
  });

  it('treats -0 as 0 and tells apart every other change', () => {
    const a: FinalBall[] = [{ id: 'cue', x: 0, y: 0.5, pocketed: false }];
    expect(hashFinalState([{ ...a[0]!, x: -0 }], 1, 2)).toBe(hashFinalState(a, 1, 2));
    expect(hashFinalState([{ ...a[0]!, x: 5e-324 }], 1, 2)).not.toBe(hashFinalState(a, 1, 2));
    expect(hashFinalState(a, 1, 3)).not.toBe(hashFinalState(a, 1, 2));
  });
});
