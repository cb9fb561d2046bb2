// Contract tests of the cluster pieces, run on the in-memory implementations (unit) and on the
// Redis ones (integration). `two()` gives two views of one shared backend: two processes over
// Redis, the same object in memory. `pass(ms)` lets that much time go by (a fake or real clock).
import fc from 'fast-check';
import { expect, it } from 'vitest';
import type { ChatLimit, ConnIds, RoomLeases } from '../../server/cluster/index.ts';

export interface Pair<T> {
  readonly a: T;
  readonly b: T;
}

export function leaseContract(two: () => Promise<Pair<RoomLeases>>, pass: (ms: number) => Promise<void>): void {
  it('a lease is exclusive: the second process is refused while the first holds it', async () => {
    const { a, b } = await two();
    expect(await a.acquire('r1', 'p1', 5000)).toBe(true);
    expect(await b.acquire('r1', 'p2', 5000)).toBe(false);
    expect(await b.owner('r1')).toBe('p1');
    expect(await a.acquire('r1', 'p1', 5000)).toBe(true); // the owner again: renewed
  });

  it('of many processes racing for a room exactly one wins', async () => {
    const { a, b } = await two();
    const wins = await Promise.all(Array.from({ length: 10 }, (_, i) => (i % 2 ? a : b).acquire('race', `p${i}`, 5000)));
    expect(wins.filter(Boolean)).toHaveLength(1);
    expect(await a.owner('race')).toBe(`p${wins.indexOf(true)}`);
  });

  it('a non-owner can neither renew nor release; the owner can', async () => {
    const { a, b } = await two();
    await a.acquire('r2', 'p1', 5000);
    expect(await b.renew('r2', 'p2', 5000)).toBe(false);
    expect(await b.release('r2', 'p2')).toBe(false);
    expect(await b.owner('r2')).toBe('p1');
    expect(await a.renew('r2', 'p1', 5000)).toBe(true);
    expect(await a.release('r2', 'p1')).toBe(true);
    expect(await a.owner('r2')).toBe(null);
    expect(await b.acquire('r2', 'p2', 5000)).toBe(true);
  });

  it('an expired lease lets another process take over, and the old owner cannot renew it', async () => {
    const { a, b } = await two();
    await a.acquire('r3', 'p1', 100);
    expect(await b.acquire('r3', 'p2', 5000)).toBe(false);
    await pass(250);
    expect(await a.owner('r3')).toBe(null);
    expect(await b.acquire('r3', 'p2', 5000)).toBe(true);
    expect(await a.renew('r3', 'p1', 5000)).toBe(false);
    expect(await a.release('r3', 'p1')).toBe(false);
    expect(await a.owner('r3')).toBe('p2');
  });

  it('bad input gets a clear error', async () => {
    const { a } = await two();
    await expect(a.acquire('', 'p1', 100)).rejects.toThrow(/roomId/);
    await expect(a.acquire('r', '', 100)).rejects.toThrow(/processId/);
    await expect(a.acquire('r', 'p1', Number.NaN)).rejects.toThrow(/ttlMs/);
    await expect(a.renew('r', 'p1', -1)).rejects.toThrow(/ttlMs/);
    expect(await a.owner('r')).toBe(null);
  });
}

export function connIdsContract(two: () => Promise<Pair<ConnIds>>): void {
  it('connection ids are unique across processes under concurrency', async () => {
    const { a, b } = await two();
    const ids = await Promise.all(Array.from({ length: 600 }, (_, i) => (i % 3 ? a : b).next()));
    expect(new Set(ids).size).toBe(ids.length);
    for (const id of ids) expect(Number.isSafeInteger(id) && id > 0).toBe(true);
  });
}

export function chatLimitContract(two: () => Promise<Pair<ChatLimit>>, lines: number, windowMs: number): void {
  it('the chat limit is one allowance across processes, refilled over time', async () => {
    const { a, b } = await two();
    const t = 1_000_000;
    for (let i = 0; i < lines; i++) expect(await (i % 2 ? a : b).take('alice', t)).toBe(0);
    const wait = await a.take('alice', t);
    expect(wait).toBeGreaterThan(0);
    expect(await b.take('alice', t)).toBeGreaterThan(0);
    expect(await b.take('bob', t)).toBe(0); // another player is not limited
    expect(await b.take('alice', t + wait)).toBe(0);
    expect(await a.take('alice', t + windowMs * 2)).toBe(0);
  });

  it('never lets more than the limit through in a window (property)', async () => {
    let n = 0;
    await fc.assert(
      fc.asyncProperty(fc.array(fc.tuple(fc.boolean(), fc.integer({ min: 0, max: 500 })), { minLength: 1, maxLength: 40 }), async (steps) => {
        const { a, b } = await two();
        const player = `prop${n++}`;
        let t = 5_000_000;
        const passed: number[] = [];
        for (const [which, dt] of steps) {
          t += dt;
          if ((await (which ? a : b).take(player, t)) === 0) passed.push(t);
        }
        // Any window holds at most `lines` lines plus what refilled within it.
        for (let i = 0; i < passed.length; i++) {
          const inWindow = passed.filter((x) => x >= passed[i]! && x < passed[i]! + windowMs).length;
          expect(inWindow).toBeLessThanOrEqual(lines + lines);
        }
      }),
      { numRuns: 30 },
    );
  });

  it('bad input gets a clear error', async () => {
    const { a } = await two();
    await expect(a.take('', 1)).rejects.toThrow(/player/);
    await expect(a.take('x', Number.NaN)).rejects.toThrow(/now/);
  });
}
