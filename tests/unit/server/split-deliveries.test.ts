// Deliveries split by the process holding each socket: nothing lost, nothing doubled, order kept.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { splitDeliveries } from '../../../server/game/split-deliveries.ts';
import type { Delivery } from '../../../server/game/service.ts';

const chat = (n: number) => ({ type: 'chat', room: 'r', from: { id: '1', name: 'x' }, text: String(n), at: n }) as const;

describe('splitDeliveries', () => {
  it('keeps local sockets here and groups the others by process, in order', () => {
    const where: Record<number, string> = { 3: 'p2', 4: 'p2', 5: 'p3' };
    const out: Delivery[] = [
      { to: [1, 3, 5], message: chat(1) },
      { to: [4], message: chat(2) },
      { to: [2], message: chat(3) },
    ];
    const { here, there } = splitDeliveries(out, (c) => where[c]);
    expect(here).toEqual([{ to: [1], message: chat(1) }, { to: [2], message: chat(3) }]);
    expect(there.get('p2')).toEqual([{ to: [3], message: chat(1) }, { to: [4], message: chat(2) }]);
    expect(there.get('p3')).toEqual([{ to: [5], message: chat(1) }]);
  });

  it('delivers every (socket, message) pair exactly once', () => {
    fc.assert(
      fc.property(fc.array(fc.uniqueArray(fc.nat(20), { maxLength: 8 }), { maxLength: 10 }), fc.func(fc.constantFrom(undefined, 'a', 'b')), (tos, procOf) => {
        const out: Delivery[] = tos.map((to, i) => ({ to, message: chat(i) }));
        const { here, there } = splitDeliveries(out, (c) => procOf(c));
        const pairs = (ds: readonly Delivery[], tag: string) => ds.flatMap((d) => d.to.map((c) => `${tag}:${c}:${(d.message as { at: number }).at}`));
        const got = [...pairs(here, 'here'), ...[...there].flatMap(([p, ds]) => pairs(ds, p))].sort();
        const want = out.flatMap((d) => d.to.map((c) => `${procOf(c) ?? 'here'}:${c}:${(d.message as { at: number }).at}`)).sort();
        expect(got).toEqual(want);
      }),
    );
  });
});
