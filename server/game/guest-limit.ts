// New players per address: a token bucket per address holding `perHour` and refilling `perHour` an
// hour. A bucket that has filled up again is forgotten, so memory holds only the addresses that
// made a player within the last hour, and never more than `maxAddresses` of them.
import { addressKey } from '../address.ts';
import { TokenBucket } from '../token-bucket.ts';

export class GuestLimit {
  private readonly buckets = new Map<string, TokenBucket>();

  constructor(
    private readonly perHour: number,
    private readonly maxAddresses = 100_000,
  ) {}

  /** Addresses remembered now. */
  get size(): number {
    return this.buckets.size;
  }

  /** Takes one new player for the address: 0 when allowed, else how long until one is (ms). */
  take(address: string, now: number): number {
    const key = addressKey(address);
    let bucket = this.buckets.get(key);
    if (!bucket) {
      if (this.buckets.size >= this.maxAddresses) {
        this.sweep(now);
        // Still full: the oldest address is forgotten (a flood of addresses, not of guests from one).
        if (this.buckets.size >= this.maxAddresses) this.buckets.delete(this.buckets.keys().next().value!);
      }
      this.buckets.set(key, (bucket = new TokenBucket(this.perHour / 3600, this.perHour, now)));
    }
    return bucket.take(now) ? 0 : bucket.waitMs(now);
  }

  /** Forgets the addresses whose buckets are full again. */
  sweep(now: number): void {
    for (const [key, bucket] of this.buckets) if (bucket.full(now)) this.buckets.delete(key);
  }
}
