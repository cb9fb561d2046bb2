// chooseShot is deterministic and always legal: over games reached from seeded racks by random
// strokes, the same game, level and seed give the same decision, and the referee accepts it.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { chooseShot, type Level } from '../../../shared/ai/index.ts';
import type { GameKind } from '../../../shared/rules/index.ts';
import { apply, reachable } from './support.ts';

const stroke = fc.record({
  heading: fc.double({ min: -3.14, max: 3.14, noNaN: true }),
  speed: fc.double({ min: 0.3, max: 6, noNaN: true }),
  side: fc.double({ min: -0.4, max: 0.4, noNaN: true }),
  top: fc.double({ min: -0.4, max: 0.4, noNaN: true }),
});

describe.each(['nineball', 'eightball', 'snooker'] as GameKind[])('chooseShot in %s', (kind) => {
  it('is deterministic and legal in reachable games', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 1e6 }),
        fc.array(stroke, { minLength: 0, maxLength: 10 }),
        fc.constantFrom<Level>(1, 2, 3, 4, 5),
        fc.integer({ min: 0, max: 0xffffffff }),
        (rack, strokes, level, seed) => {
          const game = reachable(kind, rack, strokes);
          if (game.winner !== null) return;
          const a = chooseShot(game, { level, seed });
          const b = chooseShot(game, { level, seed });
          expect(b).toEqual(a);
          expect(() => apply(game, a)).not.toThrow();
        },
      ),
      { numRuns: 15, seed: 38 },
    );
  }, 240_000);
});
