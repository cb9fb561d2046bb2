// The multi-process mode's Redis parts on a real redis-server started here: the lease contract
// across two clients (two processes), connection ids unique across them, and a Redis that dies.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { createClient, type RedisClientType } from '@redis/client';
import fc from 'fast-check';
import { RedisConnIds, RedisLeases } from '../../server/cluster/index.ts';
import { leaseContract } from '../contract/leases.contract.ts';
import { redisAvailable, startRedis, type RedisServer } from '../support/redis.ts';

const run = redisAvailable();

describe.skipIf(!run)('cluster parts on Redis', () => {
  let server: RedisServer;
  const clients: RedisClientType[] = [];

  const client = async (url = server.url): Promise<RedisClientType> => {
    const c = createClient({ url, socket: { reconnectStrategy: false } }) as RedisClientType;
    c.on('error', () => undefined);
    await c.connect();
    clients.push(c);
    return c;
  };

  beforeAll(async () => {
    server = await startRedis();
  }, 20_000);

  afterAll(async () => {
    for (const c of clients) if (c.isOpen) await c.quit().catch(() => undefined);
    await server?.stop();
  });

  describe('RedisLeases', () => {
    leaseContract(async () => {
      const [x, y] = await Promise.all([client(), client()]);
      await x.flushAll();
      return { a: new RedisLeases(x), b: new RedisLeases(y) };
    });
  });

  it('hands out connection ids unique across processes, however the calls interleave', async () => {
    const [x, y] = await Promise.all([client(), client()]);
    await fc.assert(
      fc.asyncProperty(fc.integer({ min: 1, max: 7 }), fc.integer({ min: 1, max: 7 }), fc.integer({ min: 1, max: 60 }), async (ba, bb, n) => {
        const a = new RedisConnIds(x, ba);
        const b = new RedisConnIds(y, bb);
        const ids = await Promise.all(Array.from({ length: n }, (_, i) => (i % 3 === 0 ? b : a).next()));
        expect(new Set(ids).size).toBe(ids.length);
        for (const id of ids) expect(Number.isSafeInteger(id) && id > 0).toBe(true);
      }),
      { numRuns: 50 },
    );
    expect(() => new RedisConnIds(x, 0)).toThrow(/block must be/);
  });

  it('gives clear errors, not a crash, when Redis dies', async () => {
    const own = await startRedis();
    const c = await client(own.url);
    const leases = new RedisLeases(c);
    expect(await leases.acquire('r9', 'p1', 5000)).toBe(true);
    own.kill();
    await new Promise((r) => setTimeout(r, 100));
    await expect(leases.owner('r9')).rejects.toThrow();
    await expect(new RedisConnIds(c, 10).next()).rejects.toThrow();
    await own.stop();
  });
});
