// A shot's sounds: from its events, as loud as their impacts, on the animation's clock.
import { describe, expect, it } from 'vitest';
import { sampleOutcome, simulate } from '../../../shared/physics/index.ts';
import { cueTimes, impactGain, soundSchedule } from '../../../client/table/sound.ts';

/** A straight shot on the pool table: the cue ball into the 1, the 1 into the right-hand cushion. */
const shot = (speed: number) =>
  simulate({ table: 'pool-9ft', balls: [{ id: 'cue', x: -0.6, y: 0.1 }, { id: '1', x: 0, y: 0.1 }] }, { ball: 'cue', heading: 0, speed, side: 0, top: 0 });

describe('soundSchedule', () => {
  it('has the cue tap at 0, then a click, a thud and so on at their events, louder when harder', () => {
    const soft = soundSchedule(shot(2));
    const hard = soundSchedule(shot(6));
    for (const s of [soft, hard]) {
      expect(s[0]).toMatchObject({ t: 0, kind: 'cue' });
      expect(s.find((c) => c.kind === 'ball')).toBeDefined();
      expect(s.find((c) => c.kind === 'cushion')).toBeDefined();
      expect(s.every((c, i) => i === 0 || c.t >= s[i - 1]!.t)).toBe(true);
    }
    const first = (s: typeof soft, kind: string) => s.find((c) => c.kind === kind)!.gain;
    for (const kind of ['cue', 'ball', 'cushion']) expect(first(hard, kind)).toBeGreaterThan(first(soft, kind));
  });

  it('takes each gain from its event\'s speed, and the cue\'s from the struck ball', () => {
    const o = shot(3);
    const s = soundSchedule(o);
    expect(s[0]!.gain).toBeCloseTo(impactGain('cue', 3), 9);
    const hit = o.events.find((e) => e.kind === 'ball')!;
    expect(s.find((c) => c.kind === 'ball')!).toEqual({ t: hit.t, kind: 'ball', gain: impactGain('ball', hit.speed!) });
    // No sound for the balls' changes of motion.
    expect(s.length).toBe(1 + o.events.filter((e) => (e.kind === 'ball' || e.kind === 'cushion') && Math.abs(e.speed!) >= 0.03).length + o.events.filter((e) => e.kind === 'pocket').length);
  });

  it('drops a pocketed ball with a sound as loud as its speed into the pocket', () => {
    // The 1 sent along the top cushion's line into the top right corner.
    const spec = { table: 'pool-9ft', balls: [{ id: 'cue', x: 0.6, y: 0.5 }, { id: '1', x: 1.0, y: 0.55 }] };
    const heading = Math.atan2(0.05, 0.4);
    const o = simulate(spec, { ball: 'cue', heading, speed: 4, side: 0, top: 0 });
    const drop = o.events.find((e) => e.kind === 'pocket');
    expect(drop).toBeDefined();
    const before = sampleOutcome(o, drop!.t - 1e-4).find((b) => b.id === drop!.balls[0])!;
    expect(soundSchedule(o).find((c) => c.kind === 'pocket')).toEqual({ t: drop!.t, kind: 'pocket', gain: impactGain('pocket', Math.hypot(before.vx, before.vy)) });
  });

  it('keeps gains within 0..1 and grows with speed', () => {
    for (const kind of ['cue', 'ball', 'cushion', 'pocket'] as const) {
      let last = -1;
      for (const v of [0, 0.1, 0.5, 1, 2, 4, 8, 20]) {
        const g = impactGain(kind, v);
        expect(g).toBeGreaterThanOrEqual(0);
        expect(g).toBeLessThanOrEqual(1);
        expect(g).toBeGreaterThanOrEqual(last);
        last = g;
      }
    }
  });
});

describe('cueTimes', () => {
  const cues = [
    { t: 0, kind: 'cue' as const, gain: 0.5 },
    { t: 1, kind: 'ball' as const, gain: 0.5 },
    { t: 3, kind: 'cushion' as const, gain: 0.5 },
  ];
  it('places the sounds on the animation\'s clock: twice as fast at x2, only those to come after a jump', () => {
    expect(cueTimes(cues, 0, 1).map((c) => c.at)).toEqual([0, 1, 3]);
    expect(cueTimes(cues, 0, 2).map((c) => c.at)).toEqual([0, 0.5, 1.5]);
    expect(cueTimes(cues, 2, 4).map((c) => [c.cue.kind, c.at])).toEqual([['cushion', 0.25]]);
    expect(cueTimes(cues, 3.5, 1)).toEqual([]);
  });
});
