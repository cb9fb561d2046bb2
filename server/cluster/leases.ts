// Room leases: one owner process per room. Acquired with SET NX PX; renewed and released only by
// the owner, atomically (Lua), so that a process whose lease expired cannot undo its successor's.
import { KEYS, requireId, requireMs } from './keys.ts';
import { command, type RedisClient } from './redis.ts';

export interface RoomLeases {
  /** True when `processId` now owns the room (also when it already did: the expiry is renewed). */
  acquire(roomId: string, processId: string, ttlMs: number): Promise<boolean>;
  /** True when still the owner, with the expiry pushed back. */
  renew(roomId: string, processId: string, ttlMs: number): Promise<boolean>;
  /** True when the owner gave the room up; false (and nothing changed) for anyone else. */
  release(roomId: string, processId: string): Promise<boolean>;
  owner(roomId: string): Promise<string | null>;
}

const RENEW = "if redis.call('GET', KEYS[1]) == ARGV[1] then return redis.call('PEXPIRE', KEYS[1], ARGV[2]) else return 0 end";
const RELEASE = "if redis.call('GET', KEYS[1]) == ARGV[1] then return redis.call('DEL', KEYS[1]) else return 0 end";

export class RedisRoomLeases implements RoomLeases {
  constructor(private readonly client: RedisClient) {}

  async acquire(roomId: string, processId: string, ttlMs: number): Promise<boolean> {
    const key = KEYS.lease(requireId('roomId', roomId));
    const ms = requireMs('ttlMs', ttlMs);
    requireId('processId', processId);
    if ((await command(this.client, ['SET', key, processId, 'NX', 'PX', String(ms)])) === 'OK') return true;
    return this.renew(roomId, processId, ms);
  }

  async renew(roomId: string, processId: string, ttlMs: number): Promise<boolean> {
    const key = KEYS.lease(requireId('roomId', roomId));
    const ms = requireMs('ttlMs', ttlMs);
    return Number(await command(this.client, ['EVAL', RENEW, '1', key, requireId('processId', processId), String(ms)])) === 1;
  }

  async release(roomId: string, processId: string): Promise<boolean> {
    const key = KEYS.lease(requireId('roomId', roomId));
    return Number(await command(this.client, ['EVAL', RELEASE, '1', key, requireId('processId', processId)])) === 1;
  }

  async owner(roomId: string): Promise<string | null> {
    const v = await command(this.client, ['GET', KEYS.lease(requireId('roomId', roomId))]);
    return typeof v === 'string' ? v : v == null ? null : String(v);
  }
}
