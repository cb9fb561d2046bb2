// New players per address: a token bucket per address holding `perHour` and refilling `perHour` an
// hour. A bucket that has filled up again is forgotten, so memory holds only the addresses that
// made a player within the last hour, and never more than `maxAddresses` of them.
import { addressKey } from '../address.ts';

const HOUR_MS = 3_600_000;

interface Bucket {
  tokens: number;
  at: number;
}

export class GuestLimit {
  private readonly buckets = new Map<string, Bucket>();

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
    const bucket = this.buckets.get(key);
    const tokens = bucket ? this.level(bucket, now) : this.perHour;
    if (tokens < 1) return Math.ceil(((1 - tokens) * HOUR_MS) / this.perHour);
    if (!bucket && this.buckets.size >= this.maxAddresses) {
      this.sweep(now);
      // Still full: the oldest address is forgotten (a flood of addresses, not of guests from one).
      if (this.buckets.size >= this.maxAddresses) this.buckets.delete(this.buckets.keys().next().value!);
    }
    this.buckets.set(key, { tokens: tokens - 1, at: now });
    return 0;
  }

  /** Forgets the addresses whose buckets are full again. */
  sweep(now: number): void {
    for (const [key, bucket] of this.buckets) if (this.level(bucket, now) >= this.perHour) this.buckets.delete(key);
  }

  private level(bucket: Bucket, now: number): number {
    return Math.min(this.perHour, bucket.tokens + ((now - bucket.at) * this.perHour) / HOUR_MS);
  }
}
