// Connection ids unique across processes: each process takes a block of ids from one Redis
// counter (INCRBY) and hands them out locally, so a connection costs a round trip only once per
// block. Ids stay numbers, as the game service's ConnId is.
import type { RedisClientType } from '@redis/client';
import { CONN_ID_KEY } from './keys.ts';

export interface ConnIds {
  /** A fresh id, never handed out before by any process sharing the source. */
  next(): Promise<number>;
}

/** One process's ids: a counter. */
export class MemoryConnIds implements ConnIds {
  private last = 0;

  async next(): Promise<number> {
    return ++this.last;
  }
}

/** Ids from a Redis counter, `block` at a time. */
export class RedisConnIds implements ConnIds {
  private nextId = 0;
  private end = 0;
  private refill: Promise<void> | null = null;

  constructor(
    private readonly redis: RedisClientType,
    private readonly block = 1000,
  ) {
    if (!Number.isInteger(block) || block < 1 || block > 1_000_000) throw new RangeError(`block must be a whole number from 1 to 1000000, got ${block}`);
  }

  async next(): Promise<number> {
    while (this.nextId >= this.end) {
      // One refill at a time: callers waiting on it share the block.
      this.refill ??= this.take().finally(() => (this.refill = null));
      await this.refill;
    }
    return this.nextId++;
  }

  private async take(): Promise<void> {
    const top = Number(await this.redis.incrBy(CONN_ID_KEY, this.block));
    this.nextId = top - this.block + 1;
    this.end = top + 1;
  }
}
