// Room leases: a room has one owner process at a time. A lease lasts ttlMs unless renewed; a
// process that dies stops renewing and another takes the room over once it expires. Renewing and
// releasing compare the owner first, atomically (a Lua script in Redis), so a process whose lease
// expired and was taken can never extend or drop the new owner's.
import type { RedisClientType } from '@redis/client';
import { checkId, roomOwnerKey } from './keys.ts';

export interface RoomLeases {
  /** Takes the room for `process` for ttlMs if nobody holds it (or `process` already does); true when it holds it now. */
  acquire(roomId: string, process: string, ttlMs: number): Promise<boolean>;
  /** Extends the lease by ttlMs from now, only while `process` holds it; false when it no longer does. */
  renew(roomId: string, process: string, ttlMs: number): Promise<boolean>;
  /** Gives the room up, only if `process` holds it; false otherwise. */
  release(roomId: string, process: string): Promise<boolean>;
  /** The process holding the room, if any. */
  owner(roomId: string): Promise<string | undefined>;
}

function checkTtl(ttlMs: unknown): number {
  if (typeof ttlMs !== 'number' || !Number.isInteger(ttlMs) || ttlMs < 1 || ttlMs > 3_600_000) {
    throw new RangeError(`ttlMs must be a whole number of milliseconds from 1 to 3600000, got ${String(ttlMs)}`);
  }
  return ttlMs;
}

/** One process's leases (the embedded mode, and the contract's reference). */
export class MemoryLeases implements RoomLeases {
  private readonly held = new Map<string, { process: string; until: number }>();

  constructor(private readonly now: () => number = Date.now) {}

  private current(roomId: string): { process: string; until: number } | undefined {
    const l = this.held.get(roomId);
    if (l && l.until <= this.now()) {
      this.held.delete(roomId);
      return undefined;
    }
    return l;
  }

  async acquire(roomId: string, process: string, ttlMs: number): Promise<boolean> {
    checkId('roomId', roomId);
    checkId('process', process);
    checkTtl(ttlMs);
    const l = this.current(roomId);
    if (l && l.process !== process) return false;
    this.held.set(roomId, { process, until: this.now() + ttlMs });
    return true;
  }

  async renew(roomId: string, process: string, ttlMs: number): Promise<boolean> {
    checkId('roomId', roomId);
    checkId('process', process);
    checkTtl(ttlMs);
    const l = this.current(roomId);
    if (!l || l.process !== process) return false;
    l.until = this.now() + ttlMs;
    return true;
  }

  async release(roomId: string, process: string): Promise<boolean> {
    checkId('roomId', roomId);
    checkId('process', process);
    const l = this.current(roomId);
    if (!l || l.process !== process) return false;
    this.held.delete(roomId);
    return true;
  }

  async owner(roomId: string): Promise<string | undefined> {
    checkId('roomId', roomId);
    return this.current(roomId)?.process;
  }
}

// KEYS[1] the owner key, ARGV[1] the process, ARGV[2] the TTL (ms).
const ACQUIRE = `local v = redis.call('GET', KEYS[1])
if v == false or v == ARGV[1] then redis.call('SET', KEYS[1], ARGV[1], 'PX', ARGV[2]) return 1 end
return 0`;
const RENEW = `if redis.call('GET', KEYS[1]) == ARGV[1] then redis.call('PEXPIRE', KEYS[1], ARGV[2]) return 1 end
return 0`;
const RELEASE = `if redis.call('GET', KEYS[1]) == ARGV[1] then redis.call('DEL', KEYS[1]) return 1 end
return 0`;

/** Leases shared by every process, in Redis: the key's value is the owner, its TTL the lease. */
export class RedisLeases implements RoomLeases {
  constructor(private readonly redis: RedisClientType) {}

  private async run(script: string, roomId: string, args: string[]): Promise<boolean> {
    const reply = await this.redis.eval(script, { keys: [roomOwnerKey(roomId)], arguments: args });
    return reply === 1;
  }

  async acquire(roomId: string, process: string, ttlMs: number): Promise<boolean> {
    checkId('roomId', roomId);
    checkId('process', process);
    return this.run(ACQUIRE, roomId, [process, String(checkTtl(ttlMs))]);
  }

  async renew(roomId: string, process: string, ttlMs: number): Promise<boolean> {
    checkId('roomId', roomId);
    checkId('process', process);
    return this.run(RENEW, roomId, [process, String(checkTtl(ttlMs))]);
  }

  async release(roomId: string, process: string): Promise<boolean> {
    checkId('roomId', roomId);
    checkId('process', process);
    return this.run(RELEASE, roomId, [process]);
  }

  async owner(roomId: string): Promise<string | undefined> {
    checkId('roomId', roomId);
    const v = await this.redis.get(roomOwnerKey(roomId));
    return v === null ? undefined : String(v);
  }
}
