// The cluster pieces over a real redis-server (tests/support/redis.ts): two clients stand for two
// processes. Skips with a message without redis-server, unless BAIZE_REQUIRE_REDIS=1.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CHAT_PER_PLAYER, CHAT_WINDOW_S } from '../../shared/protocol/index.ts';
import { ClusterNode, connectRedis, RedisBus, RedisChatLimit, RedisConnIds, RedisRegistry, RedisRoomLeases, KEYS, type RedisClient } from '../../server/cluster/index.ts';
import { chatLimitContract, connIdsContract, leaseContract } from '../contract/cluster.contract.ts';
import { redisAvailable, startRedis, type RedisServer } from '../support/redis.ts';

const until = async (check: () => boolean, ms = 3000) => {
  const end = Date.now() + ms;
  while (!check()) {
    if (Date.now() > end) throw new Error('timed out waiting');
    await new Promise((r) => setTimeout(r, 10));
  }
};

describe.runIf(redisAvailable())('cluster pieces over Redis', () => {
  let server: RedisServer;
  let c1: RedisClient;
  let c2: RedisClient;
  const closers: (() => Promise<unknown> | unknown)[] = [];

  beforeAll(async () => {
    server = await startRedis();
    c1 = await connectRedis(server.url, 'p1');
    c2 = await connectRedis(server.url, 'p2');
  }, 20_000);
  afterAll(async () => {
    for (const close of closers) await close();
    c1?.destroy();
    c2?.destroy();
    await server?.stop();
  });

  describe('RedisRoomLeases', () => {
    leaseContract(async () => {
      await c1.sendCommand(['FLUSHALL']); // each test from an empty server
      return { a: new RedisRoomLeases(c1), b: new RedisRoomLeases(c2) };
    }, (ms) => new Promise((r) => setTimeout(r, ms)));
  });

  describe('RedisConnIds', () => {
    connIdsContract(async () => ({ a: new RedisConnIds(c1, 7), b: new RedisConnIds(c2, 7) }));
  });

  describe('RedisChatLimit', () => {
    let n = 0;
    chatLimitContract(async () => {
      // A fresh key space each time, so that the property's runs do not share buckets.
      if (n++ === 0) await c1.sendCommand(['FLUSHALL']);
      return { a: new RedisChatLimit(c1), b: new RedisChatLimit(c2) };
    }, CHAT_PER_PLAYER, CHAT_WINDOW_S * 1000);
  });

  describe('RedisBus', () => {
    it('a command reaches its process only; a delivery reaches every process', async () => {
      const b1 = await RedisBus.open(server.url, c1, 'p1');
      const b2 = await RedisBus.open(server.url, c2, 'p2');
      closers.push(() => b1.close(), () => b2.close());
      const got: string[] = [];
      b1.onCommand((m) => got.push(`p1 cmd ${m.from} ${JSON.stringify(m.body)}`));
      b2.onCommand((m) => got.push(`p2 cmd ${m.from} ${JSON.stringify(m.body)}`));
      b1.onDelivery((m) => got.push(`p1 del ${m.from} ${JSON.stringify(m.body)}`));
      b2.onDelivery((m) => got.push(`p2 del ${m.from} ${JSON.stringify(m.body)}`));
      expect(await b1.command('p2', { move: 1 })).toBe(1);
      expect(await b1.command('gone', { move: 2 })).toBe(0);
      await b2.deliver({ shot: 3 });
      await until(() => got.length === 3);
      expect(got.sort()).toEqual(['p1 del p2 {"shot":3}', 'p2 cmd p1 {"move":1}', 'p2 del p2 {"shot":3}']);
    });

    it('malformed messages are dropped, and the bus goes on', async () => {
      const b = await RedisBus.open(server.url, c1, 'p3');
      closers.push(() => b.close());
      const got: unknown[] = [];
      b.onCommand((m) => got.push(m.body));
      b.onCommand(() => {
        throw new Error('a failing handler does not stop the others');
      });
      for (const raw of ['not json', '{"body":1}', '{"from":5,"body":1}', 'null']) await c2.sendCommand(['PUBLISH', KEYS.proc('p3'), raw]);
      await c2.sendCommand(['PUBLISH', KEYS.proc('p3'), JSON.stringify({ from: 'p2', body: 'ok' })]);
      await until(() => got.length === 1);
      await new Promise((r) => setTimeout(r, 50));
      expect(got).toEqual(['ok']);
    });
  });

  describe('ClusterNode', () => {
    const fast = { beatMs: 50, deadMs: 300, leaseMs: 300 };

    it('passes messages, sees the others alive, and finds a silent process dead with its sockets gone', async () => {
      await c1.sendCommand(['FLUSHALL']);
      const a = await ClusterNode.start(server.url, { processId: 'na', timing: fast });
      const b = await ClusterNode.start(server.url, { processId: 'nb', timing: fast });
      closers.push(() => a.close(), () => b.close());
      const heard: string[] = [];
      b.onMessage((from, body) => heard.push(`${from}:${JSON.stringify(body)}`));
      expect(await a.send('nb', { x: 1 })).toBe(true);
      a.publish({ y: 2 });
      expect(await a.send('nobody', { z: 3 })).toBe(false);
      await until(() => heard.length === 2);
      expect(heard).toEqual(['na:{"x":1}', 'na:{"y":2}']);
      await until(() => b.alive('na'));
      expect(a.nextConnId()).not.toBe(b.nextConnId());

      // A process that beat once, with a socket listed, then fell silent: each of the others reports
      // it dead once (whichever removes its entry first), and its entry and sockets are gone.
      const registry = new RedisRegistry(c2);
      await registry.beat('ghost', Date.now());
      await registry.joined('ghost', 7, { id: '1', name: 'Gone' });
      await until(() => a.alive('ghost') && b.alive('ghost'));
      expect((await b.presence()).filter((e) => e.proc === 'ghost')).toEqual([{ proc: 'ghost', conn: 7, player: { id: '1', name: 'Gone' } }]);
      const dead: string[] = [];
      const deadToA: string[] = [];
      b.onDead((p) => dead.push(p));
      a.onDead((p) => deadToA.push(p));
      await until(() => dead.includes('ghost') && deadToA.includes('ghost'));
      await new Promise((r) => setTimeout(r, 200));
      expect(dead.filter((p) => p === 'ghost')).toHaveLength(1);
      expect(b.alive('ghost')).toBe(false);
      expect(await registry.presence(['ghost'])).toEqual([]);
      expect((await registry.processes()).has('ghost')).toBe(false);

      // A process that leaves is gone for the others too, and its leases are free at once.
      expect(await a.acquire('room-1')).toBe(true);
      await a.close();
      await until(() => dead.includes('na'));
      expect(await b.acquire('room-1')).toBe(true);
    });

    it('renews its leases, and reports one another process took', async () => {
      await c1.sendCommand(['FLUSHALL']);
      const a = await ClusterNode.start(server.url, { processId: 'la', timing: fast });
      closers.push(() => a.close());
      const lost: string[] = [];
      a.onLost((room) => lost.push(room));
      expect(await a.acquire('kept')).toBe(true);
      expect(await a.acquire('taken')).toBe(true);
      await new Promise((r) => setTimeout(r, 700)); // past the lease's 300 ms: renewed meanwhile
      expect(await a.ownerOf('kept')).toBe('la');
      await c2.sendCommand(['SET', KEYS.lease('taken'), 'someone-else']);
      await until(() => lost.includes('taken'));
      expect(lost).toEqual(['taken']);
      expect(await a.ownerOf('kept')).toBe('la');
    });
  });

  describe('a lost redis-server', () => {
    it('gives clear errors while down, no crash, and works again after a restart', async () => {
      const c = await connectRedis(server.url, 'lost');
      const leases = new RedisRoomLeases(c);
      expect(await leases.acquire('lost-room', 'p1', 60_000)).toBe(true);
      await server.kill();
      await expect(leases.owner('lost-room')).rejects.toThrow();
      await server.start();
      let owner: string | null | undefined;
      const end = Date.now() + 10_000;
      for (;;) {
        try {
          owner = await leases.owner('lost-room');
          break;
        } catch (err) {
          if (Date.now() > end) throw err;
          await new Promise((r) => setTimeout(r, 100));
        }
      }
      expect(owner).toBe(null); // a fresh server without persistence: the lease is gone
      expect(await leases.acquire('lost-room', 'p2', 60_000)).toBe(true);
      c.destroy();
    }, 20_000);
  });
});
