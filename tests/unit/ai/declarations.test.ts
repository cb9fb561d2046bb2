// The computer declares what the rules ask: eight-ball's called pocket for the 8, snooker's
// nominated colour after a red, nine-ball's push-out; and the referee accepts the stroke.
import { describe, expect, it } from 'vitest';
import { chooseShot } from '../../../shared/ai/index.ts';
import { newGame, type Game } from '../../../shared/rules/index.ts';
import { apply } from './support.ts';

describe('declarations', () => {
  it('eight-ball: calls a pocket for the 8 once the group is down', () => {
    const g0 = newGame('eightball', ['a', 'b'], { seed: 3 });
    const keep = new Set(['cue', '8', '9', '12', '15']);
    const balls = g0.balls
      .filter((b) => keep.has(b.id))
      .map((b) => (b.id === 'cue' ? { ...b, x: -0.6, y: 0.1 } : b.id === '8' ? { ...b, x: 0.4, y: 0.25 } : b));
    const game = { ...g0, balls, phase: 'play', ballInHand: false, groups: { a: 'solids', b: 'stripes' } } as Game;
    for (const level of [1, 3, 5] as const) {
      const d = chooseShot(game, { level, seed: 7 });
      if (!('shot' in d)) throw new Error('expected a stroke');
      expect(d.shot.calledPocket).toBeDefined();
      expect(() => apply(game, d)).not.toThrow();
    }
  });

  it('snooker: nominates a colour after a red', () => {
    const g0 = newGame('snooker', ['a', 'b'], { seed: 1 });
    const balls = g0.balls.filter((b) => b.id !== 'red1').map((b) => (b.id === 'cue' ? { ...b, x: 0.6, y: 0.3 } : b));
    const game = { ...g0, balls, on: 'colour', ballInHand: false, shots: 2, scores: { a: 1, b: 0 }, break: 1 } as Game;
    for (const level of [1, 3, 5] as const) {
      const d = chooseShot(game, { level, seed: 11 });
      if (!('shot' in d)) throw new Error('expected a stroke');
      expect(['yellow', 'green', 'brown', 'blue', 'pink', 'black']).toContain(d.shot.nominated);
      expect(() => apply(game, d)).not.toThrow();
    }
  });

  it('nine-ball: pushes out when the break leaves nothing on, and answers a push-out', () => {
    // After the break, the cue ball in a corner behind a wall of balls, the 1 at the far end.
    const g0 = newGame('nineball', ['a', 'b'], { seed: 5 });
    const wall = ['2', '3', '4', '5', '6', '7', '8'];
    const balls = g0.balls.map((b) => {
      if (b.id === 'cue') return { ...b, x: -1.15, y: -0.5 };
      if (b.id === '1') return { ...b, x: 1.1, y: 0.52 };
      if (b.id === '9') return { ...b, x: 0.9, y: -0.3 };
      const i = wall.indexOf(b.id);
      return { ...b, x: -1.0 + 0.062 * (i % 4), y: -0.42 + 0.062 * Math.floor(i / 4) + (i % 4 === 3 ? -0.06 : 0) };
    });
    const game = { ...g0, balls, turn: 'b', phase: 'push-out', ballInHand: false, choices: [], verdict: null } as Game;
    for (const level of [4, 5] as const) {
      const d = chooseShot(game, { level, seed: 3 });
      if (!('shot' in d)) throw new Error('expected a stroke');
      expect(d.shot.pushOut).toBe(true);
      const after = apply(game, d);
      expect(after.choices).toContain('pass');
      // The other side answers with the choice or a stroke; either is legal.
      const reply = chooseShot(after, { level, seed: 4 });
      if ('choice' in reply) expect(reply.choice).toBe('pass');
      else expect(() => apply(after, reply)).not.toThrow();
    }
  });
});
