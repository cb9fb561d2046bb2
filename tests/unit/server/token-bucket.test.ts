// The per-socket rate limit: bursts up to the bucket, then the rate.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { TokenBucket } from '../../../server/token-bucket.ts';

describe('the token bucket', () => {
  it('takes a burst at once, then refills at the rate', () => {
    const b = new TokenBucket(20, 40, 0);
    for (let i = 0; i < 40; i++) expect(b.take(0)).toBe(true);
    expect(b.take(0)).toBe(false);
    expect(b.take(49)).toBe(false); // 0.98 of a token
    expect(b.take(51)).toBe(true);
    expect(b.take(10_000)).toBe(true); // refilled, but never past the burst
    let n = 1;
    while (b.take(10_000)) n++;
    expect(n).toBe(40);
  });

  it('never lets more than burst + rate × seconds through (property)', () => {
    fc.assert(
      fc.property(fc.array(fc.integer({ min: 0, max: 200 }), { minLength: 1, maxLength: 300 }), (gaps) => {
        const b = new TokenBucket(20, 40, 0);
        let t = 0;
        let passed = 0;
        for (const g of gaps) {
          t += g;
          if (b.take(t)) passed++;
        }
        expect(passed).toBeLessThanOrEqual(40 + Math.floor((20 * t) / 1000));
      }),
    );
  });

  it('holds what a stall earned beyond the burst only while the stall is counted (extra)', () => {
    const b = new TokenBucket(20, 40, 0);
    // 5 s later, with the stall's 100 tokens of extra room: 140 pass at once.
    let n = 0;
    while (b.take(5000, 100)) n++;
    expect(n).toBe(140);
    // Without the extra room the bucket is back to its usual cap.
    const c = new TokenBucket(20, 40, 0);
    n = 0;
    while (c.take(5000)) n++;
    expect(n).toBe(40);
  });

  it('never lets more than burst + extra + rate × seconds through (property)', () => {
    fc.assert(
      fc.property(fc.array(fc.tuple(fc.integer({ min: 0, max: 2000 }), fc.integer({ min: 0, max: 200 })), { minLength: 1, maxLength: 300 }), (steps) => {
        const b = new TokenBucket(20, 40, 0);
        let t = 0;
        let passed = 0;
        for (const [gap, extra] of steps) {
          t += gap;
          if (b.take(t, extra)) passed++;
        }
        const most = Math.max(...steps.map(([, e]) => e));
        expect(passed).toBeLessThanOrEqual(40 + most + Math.floor((20 * t) / 1000));
      }),
    );
  });

  it('says how long until the next token', () => {
    const b = new TokenBucket(0.5, 5, 0);
    for (let i = 0; i < 5; i++) expect(b.take(0)).toBe(true);
    expect(b.waitMs(0)).toBe(2000);
    expect(b.waitMs(1500)).toBe(500);
    expect(b.full(1500)).toBe(false);
    expect(b.full(10_000)).toBe(true);
  });
});
