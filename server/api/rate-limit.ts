// Rate limits of the HTTP API: a token bucket per key (a player, an address), each refilling at
// `perMinute` a minute and holding ten seconds' worth (at least MIN_BURST), so that a burst cannot
// pile up a minute of work at once. The buckets kept are bounded: the one used least recently goes
// first, and a bucket left idle long enough to refill is no different from a new one.

import { TokenBucket } from '../token-bucket.ts';

/** Practice requests a minute when not configured: a player's, and an address's (several players). */
export const PRACTICE_LIMITS = { perPlayer: 30, perAddress: 300 } as const;

export interface PracticeLimits {
  readonly perPlayer: number;
  readonly perAddress: number;
}

/** The fewest requests a bucket holds: a player's few quick runs in a row always pass. */
export const MIN_BURST = 5;

export class RateLimiter {
  private readonly buckets = new Map<string, TokenBucket>();
  /** Requests a full bucket holds. */
  readonly burst: number;

  constructor(
    private readonly perMinute: number,
    private readonly maxKeys = 10_000,
  ) {
    if (!(Number.isFinite(perMinute) && perMinute >= 1)) throw new RangeError(`perMinute must be 1 or more, got ${perMinute}`);
    if (!(Number.isInteger(maxKeys) && maxKeys >= 1)) throw new RangeError(`maxKeys must be a whole number from 1, got ${maxKeys}`);
    this.burst = Math.max(MIN_BURST, Math.ceil(perMinute / 6));
  }

  /** Takes one request from `key`'s bucket at `now` (ms): 0 when allowed, else the whole seconds to wait. */
  take(key: string, now: number): number {
    const bucket = this.buckets.get(key) ?? new TokenBucket(this.perMinute / 60, this.burst, now);
    // Moved to the end of the map's order: the first key is the least recently used.
    this.buckets.delete(key);
    this.buckets.set(key, bucket);
    if (this.buckets.size > this.maxKeys) this.buckets.delete(this.buckets.keys().next().value!);
    return bucket.take(now) ? 0 : Math.max(1, Math.ceil(bucket.waitMs(now) / 1000));
  }

  /** Buckets held (for tests of the bound). */
  get size(): number {
    return this.buckets.size;
  }
}
