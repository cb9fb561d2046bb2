// Connection ids unique across processes: each process takes a block from a Redis counter and
// hands its ids out locally, one round trip per block.
import { KEYS } from './keys.ts';
import { command, type RedisClient } from './redis.ts';

export interface ConnIds {
  next(): Promise<number>;
}

export class RedisConnIds implements ConnIds {
  private nextId = 0;
  private end = 0; // exclusive
  private pending: Promise<void> | null = null;
  constructor(private readonly client: RedisClient, private readonly block = 1000) {
    if (!Number.isInteger(block) || block < 1) throw new Error(`block must be a positive integer (got ${block})`);
  }

  /** Fetches the first block, so that `take` has ids to give. */
  async ready(): Promise<void> {
    while (this.nextId >= this.end) {
      this.pending ??= this.refill().finally(() => (this.pending = null));
      await this.pending;
    }
  }

  /**
   * An id at once (a socket's id is needed as it opens), refilling in the background once half a
   * block is used (the rest of that block is skipped); undefined only when a whole block went before one round trip came back.
   */
  take(): number | undefined {
    if (this.end - this.nextId <= this.block / 2) this.pending ??= this.refill().catch(() => undefined).finally(() => (this.pending = null));
    return this.nextId < this.end ? this.nextId++ : undefined;
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
