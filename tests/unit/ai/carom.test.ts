// The computer at three-cushion: deterministic, always legal, and it finds the point on easy
// positions (played as chosen, without noise, the referee counts it).
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { chooseShot, type Level } from '../../../shared/ai/index.ts';
import { newGame, playShot, type Ball, type Game } from '../../../shared/rules/index.ts';

function start(): Game {
  return newGame('threecushion', ['a', 'b'], { raceTo: 50 });
}

function at(balls: Ball[]): Game {
  return { ...start(), balls, shots: 1 };
}

function shotOf(g: Game, level: Level, seed: number) {
  const d = chooseShot(g, { level, seed });
  if (!('shot' in d)) throw new Error('three-cushion has no choices');
  return d.shot;
}

const stroke = fc.record({
  heading: fc.double({ min: 0, max: 6.28, noNaN: true }),
  speed: fc.double({ min: 0.5, max: 6, noNaN: true }),
  // Inside the miscue limit (0.5 R from the centre) whatever the pair: 0.35 * sqrt(2) < 0.5.
  side: fc.double({ min: -0.35, max: 0.35, noNaN: true }),
  top: fc.double({ min: -0.35, max: 0.35, noNaN: true }),
});

describe('chooseShot at three-cushion', () => {
  it('is deterministic and always legal over random reachable games', () => {
    fc.assert(
      fc.property(fc.array(stroke, { maxLength: 3 }), fc.integer({ min: 0, max: 0xffffffff }), fc.constantFrom<Level>(1, 2), (strokes, seed, level) => {
        let g = start();
        for (const s of strokes) {
          if (g.winner !== null) break;
          const ball = g.players[0] === g.turn ? 'white' : 'yellow';
          g = playShot(g, { player: g.turn, ball, ...s }).game;
        }
        const a = chooseShot(g, { level, seed });
        const b = chooseShot(g, { level, seed });
        expect(b).toEqual(a);
        if (!('shot' in a)) throw new Error('a choice at three-cushion');
        expect(a.shot.player).toBe(g.turn);
        expect(() => playShot(g, a.shot)).not.toThrow();
      }),
      { numRuns: 6 },
    );
  }, 120_000);

  const easy: [string, Game][] = [
    ['the opening position', start()],
    [
      'the object balls close together near a corner',
      at([
        { id: 'white', x: 0, y: 0 },
        { id: 'yellow', x: 1.2, y: 0.5 },
        { id: 'red', x: 1.1, y: 0.58 },
      ]),
    ],
    [
      'the red near the cue ball, the yellow in the far corner',
      at([
        { id: 'white', x: -0.6, y: -0.2 },
        { id: 'red', x: -0.3, y: -0.1 },
        { id: 'yellow', x: 1.25, y: 0.55 },
      ]),
    ],
  ];
  for (const [name, g] of easy) {
    it(`scores from ${name} (level 5, played without noise)`, () => {
      const shot = shotOf(g, 5, 11);
      const next = playShot(g, shot).game;
      expect(next.scores['a']).toBe(1);
    }, 60_000);
  }
});
