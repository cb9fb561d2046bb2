import { join } from 'node:path';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { nextInt, nextUint32, seedState, shuffle } from '../../../shared/rules/rng.ts';
import { scanTree } from '../../support/determinism-scan.ts';

describe('the seeded generator', () => {
  it('is a pure function of its state, and seeds (numbers or strings) give non-zero states', () => {
    expect(nextUint32(12345)).toEqual(nextUint32(12345));
    expect(seedState(7)).toBe(seedState(7));
    expect(seedState('table-4')).toBe(seedState('table-4'));
    expect(seedState(7)).not.toBe(seedState(8));
    for (const s of [0, 1, -1, 2 ** 32, 'x', '', undefined]) expect(seedState(s)).not.toBe(0);
  });

  it('pins its first outputs (the same bits on every engine: integer arithmetic only)', () => {
    let s = seedState(1);
    const out: number[] = [];
    for (let i = 0; i < 4; i++) {
      const r = nextUint32(s);
      out.push(r.value);
      s = r.state;
    }
    // Recomputed independently below with BigInt (xorshift32 13/17/5, then times 0x2545f491 mod 2^32).
    let x = BigInt(seedState(1));
    const mask = (1n << 32n) - 1n;
    const want: number[] = [];
    for (let i = 0; i < 4; i++) {
      x ^= (x << 13n) & mask;
      x ^= x >> 17n;
      x ^= (x << 5n) & mask;
      want.push(Number((x * 0x2545f491n) & mask));
    }
    expect(out).toEqual(want);
  });

  it('draws integers in range, roughly uniformly', () => {
    const counts = [0, 0, 0, 0, 0, 0, 0];
    let s = seedState(99);
    for (let i = 0; i < 7000; i++) {
      const r = nextInt(s, 7);
      s = r.state;
      counts[r.value]! += 1;
    }
    for (const c of counts) expect(c).toBeGreaterThan(850);
    for (const c of counts) expect(c).toBeLessThan(1150);
  });

  it('shuffles into a permutation, and the state moves on', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 2 ** 32 - 1 }), fc.array(fc.string(), { maxLength: 20 }), (state, items) => {
        const r = shuffle(items, state);
        expect([...r.items].sort()).toEqual([...items].sort());
        if (items.length > 1) expect(r.state).not.toBe(state);
      }),
    );
  });
});

describe('the determinism guard on shared/rules', () => {
  it('finds no clock, no chance and no inexact Math in the referees', () => {
    const findings = scanTree(join(import.meta.dirname, '../../../shared/rules'));
    expect(findings).toEqual([]);
  });
});
