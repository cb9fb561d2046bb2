import { describe, expect, it } from 'vitest';
import { energyAt, sampleOutcome, simulate } from '../../../shared/physics/index.ts';
import { corpusCase } from '../../support/corpus.ts';

describe('sampling an outcome for animation', () => {
  const c = corpusCase('nineball break 8 m/s from y=0.1');
  const o = simulate(c.scene, c.shot);

  it('starts at the scene and ends at the final positions', () => {
    const start = sampleOutcome(o, 0);
    c.scene.balls.forEach((b, i) => {
      expect(start[i]!.x).toBe(b.x);
      expect(start[i]!.y).toBe(b.y);
    });
    const end = sampleOutcome(o, o.duration + 1);
    o.balls.forEach((b, i) => {
      expect(end[i]!.x).toBeCloseTo(b.x, 12);
      expect(end[i]!.y).toBeCloseTo(b.y, 12);
      expect(end[i]!.motion).toBe(b.pocketed ? 'pocketed' : 'rest');
    });
  });

  it('moves every ball continuously: no jump in position across any event', () => {
    for (const e of o.events) {
      const before = sampleOutcome(o, e.t - 1e-9);
      const after = sampleOutcome(o, e.t + 1e-9);
      before.forEach((b, i) => {
        if (after[i]!.motion === 'pocketed') return;
        expect(Math.hypot(after[i]!.x - b.x, after[i]!.y - b.y)).toBeLessThan(1e-7); // 2e-9 s at ≤ 10 m/s, plus the event
      });
    }
  });

  it('the cue ball leaves with the struck speed and spin, and energy only falls', () => {
    const cue = sampleOutcome(o, 0).find((b) => b.id === 'cue')!;
    expect(Math.hypot(cue.vx, cue.vy)).toBeCloseTo(c.shot.speed, 12);
    let last = Infinity;
    for (let t = 0; t <= o.duration; t += o.duration / 200) {
      const e = energyAt(o, t);
      expect(e).toBeLessThanOrEqual(last * (1 + 1e-12));
      last = e;
    }
    expect(energyAt(o, o.duration + 1)).toBe(0);
  });
});
