// What every RoomLeases implementation must do; `make` gives two handles on one shared lease
// table (two processes).
import { expect, it } from 'vitest';
import type { RoomLeases } from '../../server/cluster/index.ts';

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

export function leaseContract(make: () => Promise<{ a: RoomLeases; b: RoomLeases }>): void {
  it('gives a room to one process at a time', async () => {
    const { a, b } = await make();
    const [x, y] = await Promise.all([a.acquire('r1', 'p1', 5000), b.acquire('r1', 'p2', 5000)]);
    expect([x, y].filter(Boolean)).toHaveLength(1);
    const owner = await b.owner('r1');
    expect(owner).toBe(x ? 'p1' : 'p2');
    // The owner may take it again (a renewal); the other may not.
    expect(await a.acquire('r1', owner!, 5000)).toBe(true);
    expect(await b.acquire('r1', owner === 'p1' ? 'p2' : 'p1', 5000)).toBe(false);
  });

  it('lets another process take a room once its lease expires unrenewed', async () => {
    const { a, b } = await make();
    expect(await a.acquire('r2', 'p1', 150)).toBe(true);
    expect(await b.acquire('r2', 'p2', 150)).toBe(false);
    await sleep(250);
    expect(await a.owner('r2')).toBeUndefined();
    expect(await b.acquire('r2', 'p2', 5000)).toBe(true);
    // The old owner can neither extend nor drop the new owner's lease.
    expect(await a.renew('r2', 'p1', 5000)).toBe(false);
    expect(await a.release('r2', 'p1')).toBe(false);
    expect(await a.owner('r2')).toBe('p2');
  });

  it('keeps a renewed lease past its first term', async () => {
    const { a, b } = await make();
    expect(await a.acquire('r3', 'p1', 200)).toBe(true);
    await sleep(120);
    expect(await a.renew('r3', 'p1', 200)).toBe(true);
    await sleep(120);
    expect(await b.acquire('r3', 'p2', 200)).toBe(false);
    expect(await b.owner('r3')).toBe('p1');
  });

  it('releases only for its owner', async () => {
    const { a, b } = await make();
    expect(await a.acquire('r4', 'p1', 5000)).toBe(true);
    expect(await b.release('r4', 'p2')).toBe(false);
    expect(await b.release('r4', 'p1')).toBe(true);
    expect(await a.owner('r4')).toBeUndefined();
    expect(await b.acquire('r4', 'p2', 5000)).toBe(true);
  });

  it('refuses bad ids and lease times with a clear error', async () => {
    const { a } = await make();
    await expect(a.acquire('', 'p1', 1000)).rejects.toThrow(/roomId must be/);
    await expect(a.acquire('r5', 'p 1', 1000)).rejects.toThrow(/process must be/);
    await expect(a.acquire('r5', 'p1', Number.NaN)).rejects.toThrow(/ttlMs must be/);
    await expect(a.renew('r5', 'p1', 0)).rejects.toThrow(/ttlMs must be/);
    await expect(a.owner('x'.repeat(33))).rejects.toThrow(/roomId must be/);
    expect(await a.owner('r5')).toBeUndefined();
  });
}
