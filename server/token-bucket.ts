// A token bucket: `rate` tokens a second up to `burst`; each message, guest or request takes one.
// Shared by every rate limit: socket frames, chat, new guests per address, the HTTP API.
export class TokenBucket {
  private tokens: number;
  private last: number;

  constructor(
    private readonly rate: number,
    private readonly burst: number,
    now: number,
  ) {
    this.tokens = burst;
    this.last = now;
  }

  /**
   * Takes a token; false when there is none left (the sender is over the limit). `extra` raises
   * the bucket's cap for this call, so that time the server itself lost (a stall) still counts
   * as time the sender waited.
   */
  take(now: number, extra = 0): boolean {
    this.refill(now, extra);
    if (this.tokens < 1) return false;
    this.tokens -= 1;
    return true;
  }

  /** Milliseconds until a token is there: 0 when one is. */
  waitMs(now: number): number {
    this.refill(now, 0);
    return this.tokens >= 1 ? 0 : Math.ceil(((1 - this.tokens) / this.rate) * 1000);
  }

  /** Whether the bucket is full again: it then holds nothing worth keeping. */
  full(now: number): boolean {
    this.refill(now, 0);
    return this.tokens >= this.burst;
  }

  private refill(now: number, extra: number): void {
    this.tokens = Math.min(this.burst + extra, this.tokens + (Math.max(0, now - this.last) / 1000) * this.rate);
    this.last = Math.max(this.last, now);
  }
}
