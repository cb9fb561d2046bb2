// Connection ids unique across processes: each process takes a block from a Redis counter and
// hands its ids out locally, one round trip per block.
import { KEYS } from './keys.ts';
import { command, type RedisClient } from './redis.ts';

export interface ConnIds {
  next(): Promise<number>;
}

export class MemoryConnIds implements ConnIds {
  private last = 0;
  async next(): Promise<number> {
    return ++this.last;
  }
}

export class RedisConnIds implements ConnIds {
  private nextId = 0;
  private end = 0; // exclusive
  private pending: Promise<void> | null = null;
  constructor(private readonly client: RedisClient, private readonly block = 1000) {
    if (!Number.isInteger(block) || block < 1) throw new Error(`block must be a positive integer (got ${block})`);
  }

  async next(): Promise<number> {
    while (this.nextId >= this.end) {
      this.pending ??= this.refill().finally(() => (this.pending = null));
      await this.pending;
    }
    return this.nextId++;
  }

  private async refill(): Promise<void> {
    const top = Number(await command(this.client, ['INCRBY', KEYS.connIds, String(this.block)]));
    this.nextId = top - this.block + 1;
    this.end = top + 1;
  }
}
