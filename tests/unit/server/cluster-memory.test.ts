// The cluster pieces' in-memory implementations (one process) against their contracts.
import { describe, expect, it } from 'vitest';
import { CHAT_PER_PLAYER, CHAT_WINDOW_S } from '../../../shared/protocol/index.ts';
import { MemoryBus, MemoryChatLimit, MemoryConnIds, MemoryRoomLeases, parseEnvelope } from '../../../server/cluster/index.ts';
import { chatLimitContract, connIdsContract, leaseContract } from '../../contract/cluster.contract.ts';

describe('MemoryRoomLeases', () => {
  let now = 0;
  leaseContract(
    async () => {
      const l = new MemoryRoomLeases(() => now);
      return { a: l, b: l };
    },
    async (ms) => void (now += ms),
  );
});

describe('MemoryConnIds', () => {
  connIdsContract(async () => {
    const c = new MemoryConnIds();
    return { a: c, b: c };
  });
});

describe('MemoryChatLimit', () => {
  chatLimitContract(async () => {
    const c = new MemoryChatLimit();
    return { a: c, b: c };
  }, CHAT_PER_PLAYER, CHAT_WINDOW_S * 1000);
});

describe('MemoryBus', () => {
  it('delivers commands to itself only, deliveries to itself', async () => {
    const bus = new MemoryBus('p1');
    const got: unknown[] = [];
    bus.onCommand((m) => got.push(['cmd', m.from, m.body]));
    bus.onDelivery((m) => got.push(['del', m.from, m.body]));
    expect(await bus.command('p1', { x: 1 })).toBe(1);
    expect(await bus.command('p2', { x: 2 })).toBe(0);
    await bus.deliver({ y: 1 });
    await new Promise((r) => setTimeout(r, 0));
    expect(got).toEqual([['cmd', 'p1', { x: 1 }], ['del', 'p1', { y: 1 }]]);
  });

  it('parseEnvelope drops what is not a well-formed envelope, with a log line', () => {
    const logs: string[] = [];
    const log = (w: string) => logs.push(w);
    expect(parseEnvelope('{nope', log)).toBe(null);
    expect(parseEnvelope('{"body":1}', log)).toBe(null);
    expect(parseEnvelope('{"from":"","body":1}', log)).toBe(null);
    expect(parseEnvelope('[]', log)).toBe(null);
    expect(logs).toHaveLength(4);
    expect(parseEnvelope('{"from":"p","body":{"a":1}}', log)).toEqual({ from: 'p', body: { a: 1 } });
  });
});
