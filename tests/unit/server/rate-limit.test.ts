// The HTTP API's rate limits: a bucket per key refilling at its rate a minute, a Retry-After that
// is enough, a bounded number of buckets, and addresses keyed as one subscriber's.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { addressKey } from '../../../server/address.ts';
import { MIN_BURST, PRACTICE_LIMITS, RateLimiter } from '../../../server/api/rate-limit.ts';
import { readConfig } from '../../../server/config.ts';

describe('the rate limiter', () => {
  it('takes ten seconds\' worth (at least 5) at once, then one every 60/rate seconds, and says how long to wait', () => {
    expect(new RateLimiter(600).burst).toBe(100);
    expect(new RateLimiter(12).burst).toBe(MIN_BURST);
    const l = new RateLimiter(6); // one every 10 s, 5 at once
    for (let i = 0; i < 5; i++) expect(l.take('a', 0)).toBe(0);
    expect(l.take('a', 0)).toBe(10);
    expect(l.take('a', 4_000)).toBe(6);
    expect(l.take('b', 4_000)).toBe(0); // another key has its own bucket
    expect(l.take('a', 10_000)).toBe(0);
    expect(l.take('a', 10_000)).toBe(10);
  });

  it('never lets more through than a full bucket plus the rate over the time (property)', () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 120 }), fc.array(fc.integer({ min: 0, max: 5_000 }), { minLength: 1, maxLength: 300 }), (perMinute, gaps) => {
        const l = new RateLimiter(perMinute);
        let t = 0;
        let passed = 0;
        for (const g of gaps) {
          t += g;
          const wait = l.take('k', t);
          if (wait === 0) passed++;
          else expect(wait).toBeGreaterThanOrEqual(1);
        }
        expect(passed).toBeLessThanOrEqual(l.burst + Math.floor((perMinute * t) / 60_000));
      }),
    );
  });

  it('after the wait it names, lets the next request through', () => {
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 600 }), fc.integer({ min: 0, max: 59_999 }), (perMinute, at) => {
        const l = new RateLimiter(perMinute);
        for (let i = 0; i < l.burst; i++) l.take('k', 0);
        const wait = l.take('k', at);
        if (wait > 0) expect(l.take('k', at + wait * 1000)).toBe(0);
      }),
    );
  });

  it('holds a bounded number of buckets, and keeps the one of a key that keeps asking', () => {
    const l = new RateLimiter(2, 100);
    for (let i = 0; i < l.burst; i++) l.take('flood', 0);
    for (let i = 0; i < 5_000; i++) {
      l.take(`addr-${i}`, 0);
      if (i % 50 === 0) expect(l.take('flood', 0)).toBeGreaterThan(0);
    }
    expect(l.size).toBeLessThanOrEqual(100);
  });

  it('refuses a rate below one a minute', () => {
    expect(() => new RateLimiter(0)).toThrow(RangeError);
    expect(() => new RateLimiter(Number.NaN)).toThrow(RangeError);
  });
});

describe('address keys', () => {
  it('keep IPv4 as it is and key IPv6 by its /64', () => {
    expect(addressKey('203.0.113.9')).toBe('203.0.113.9');
    expect(addressKey('::ffff:203.0.113.9')).toBe('203.0.113.9');
    expect(addressKey('2001:db8:1:2:3:4:5:6')).toBe('2001:db8:1:2::/64');
    expect(addressKey('2001:db8:1:2::9')).toBe('2001:db8:1:2::/64');
    expect(addressKey('2001:0db8:0001:0002:ffff::1')).toBe('2001:db8:1:2::/64');
    expect(addressKey('2001:db8::1')).toBe('2001:db8:0:0::/64');
    expect(addressKey('::1')).toBe('0:0:0:0::/64');
    expect(addressKey('fe80::1%eth0')).toBe('fe80:0:0:0::/64');
    expect(addressKey(undefined)).toBe('unknown');
  });
});

describe('the practice limits in the configuration', () => {
  it('default to what a player never meets, and refuse anything but a whole number from 1', () => {
    expect(readConfig({})).toMatchObject({ practicePerMinute: PRACTICE_LIMITS.perPlayer, practicePerAddressPerMinute: PRACTICE_LIMITS.perAddress });
    expect(readConfig({ BAIZE_PRACTICE_PER_MINUTE: '5', BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE: '50' })).toMatchObject({ practicePerMinute: 5, practicePerAddressPerMinute: 50 });
    for (const bad of ['0', '-1', '1.5', 'ten', '', '2000000']) {
      expect(() => readConfig({ BAIZE_PRACTICE_PER_MINUTE: bad })).toThrow(/BAIZE_PRACTICE_PER_MINUTE/);
      expect(() => readConfig({ BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE: bad })).toThrow(/BAIZE_PRACTICE_PER_ADDRESS_PER_MINUTE/);
    }
  });
});
