// The per-player chat limit held across processes: a token bucket (CHAT_PER_PLAYER lines per
// CHAT_WINDOW_S seconds) in one Redis hash, taken atomically in Lua so that two processes serving
// the same player's tabs share one allowance. Time comes from the caller (ms) for testability.
import { CHAT_PER_PLAYER, CHAT_WINDOW_S } from '../../shared/protocol/index.ts';
import { TokenBucket } from '../token-bucket.ts';
import { KEYS, requireId } from './keys.ts';
import { command, type RedisClient } from './redis.ts';

export interface ChatLimit {
  /** 0 when the line is let through (and counted), else how many ms to wait (nothing counted). */
  take(player: string, now: number): Promise<number>;
  /** Forgets the players whose allowance has filled up again (Redis lets its keys expire instead). */
  prune?(now: number): void;
}

export class MemoryChatLimit implements ChatLimit {
  private readonly buckets = new Map<string, TokenBucket>();
  constructor(private readonly lines = CHAT_PER_PLAYER, private readonly windowS = CHAT_WINDOW_S) {}
  async take(player: string, now: number): Promise<number> {
    requireId('player', player);
    if (!Number.isFinite(now)) throw new Error(`now must be a finite number (got ${now})`);
    let b = this.buckets.get(player);
    if (!b) this.buckets.set(player, (b = new TokenBucket(this.lines / this.windowS, this.lines, now)));
    const wait = b.waitMs(now);
    if (wait > 0) return wait;
    b.take(now);
    return 0;
  }
  prune(now: number): void {
    for (const [player, b] of this.buckets) if (b.full(now)) this.buckets.delete(player);
  }
}

// KEYS[1] bucket; ARGV: capacity, refill per ms, now ms. Returns 0 or the wait in ms.
const TAKE = `
local cap = tonumber(ARGV[1]); local rate = tonumber(ARGV[2]); local now = tonumber(ARGV[3])
local s = redis.call('HMGET', KEYS[1], 't', 'at')
local tokens = tonumber(s[1]) or cap; local at = tonumber(s[2]) or now
if now > at then tokens = math.min(cap, tokens + (now - at) * rate); at = now end
if tokens < 1 then return math.ceil((1 - tokens) / rate) end
redis.call('HSET', KEYS[1], 't', tostring(tokens - 1), 'at', tostring(at))
redis.call('PEXPIRE', KEYS[1], math.ceil(cap / rate) + 1000)
return 0`;

export class RedisChatLimit implements ChatLimit {
  constructor(private readonly client: RedisClient, private readonly lines = CHAT_PER_PLAYER, private readonly windowS = CHAT_WINDOW_S) {}
  async take(player: string, now: number): Promise<number> {
    const key = KEYS.chat(requireId('player', player));
    if (!Number.isFinite(now)) throw new Error(`now must be a finite number (got ${now})`);
    const rate = this.lines / (this.windowS * 1000);
    return Number(await command(this.client, ['EVAL', TAKE, '1', key, String(this.lines), String(rate), String(Math.floor(now))]));
  }
}
