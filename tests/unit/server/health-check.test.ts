// The health check over an asynchronous store: one write a second while it succeeds, every check
// tries again while it fails, and checks that arrive during a write share its answer.
import { describe, expect, it } from 'vitest';
import { healthCheck } from '../../../server/health.ts';

function source() {
  const clock = { now: 0 };
  const probe = { calls: 0, fail: undefined as string | undefined, release: undefined as (() => void) | undefined, hold: false };
  const check = healthCheck({
    version: 'v',
    schema: async () => 10,
    probeWrite: async () => {
      probe.calls++;
      if (probe.hold) await new Promise<void>((r) => (probe.release = r));
      if (probe.fail !== undefined) throw new Error(probe.fail);
    },
    now: () => clock.now,
  });
  return { clock, probe, check };
}

describe('the health check', () => {
  it('writes at most once a second while writes succeed', async () => {
    const { clock, probe, check } = source();
    expect(await check()).toEqual({ ok: true, version: 'v', schema: 10 });
    clock.now = 999;
    await check();
    expect(probe.calls).toBe(1);
    clock.now = 1000;
    await check();
    expect(probe.calls).toBe(2);
  });

  it('tries every check while writes fail, and says why', async () => {
    const { probe, check } = source();
    probe.fail = 'disk full';
    expect(await check()).toEqual({ ok: false, version: 'v', schema: 10, error: 'the database cannot be written: disk full' });
    await check();
    expect(probe.calls).toBe(2);
    probe.fail = undefined;
    expect((await check()).ok).toBe(true);
  });

  it('shares one write among the checks that arrive while it is under way', async () => {
    const { probe, check } = source();
    probe.hold = true;
    const answers = [check(), check(), check()];
    await new Promise((r) => setTimeout(r, 10));
    expect(probe.calls).toBe(1);
    probe.release!();
    expect((await Promise.all(answers)).map((a) => a.ok)).toEqual([true, true, true]);
  });
});
