// The chat limit one process uses, against the contract the Redis one meets; the bus's envelopes.
import { describe, expect, it } from 'vitest';
import { CHAT_PER_PLAYER, CHAT_WINDOW_S } from '../../../shared/protocol/index.ts';
import { MemoryChatLimit, parseEnvelope } from '../../../server/cluster/index.ts';
import { chatLimitContract } from '../../contract/cluster.contract.ts';

describe('MemoryChatLimit', () => {
  chatLimitContract(async () => {
    const c = new MemoryChatLimit();
    return { a: c, b: c };
  }, CHAT_PER_PLAYER, CHAT_WINDOW_S * 1000);
});

describe('the bus', () => {
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
