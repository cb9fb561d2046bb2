// How far a rated result moves each rating (server/ratings/policy.ts): Glicko-2 as it is on a young
// board; once the board is anchored, a provisional opponent moves no established rating and
// lowers no RD.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { NEW_RATING, PROVISIONAL_RD, rateMatch, type Rating } from '../../../server/ratings/glicko2.ts';
import { provisional, rateResult } from '../../../server/ratings/policy.ts';

const established: Rating = { rating: 1600, rd: 70, vol: 0.06 };
const ratingArb = fc.record({ rating: fc.double({ min: 800, max: 2800, noNaN: true }), rd: fc.double({ min: 40, max: 350, noNaN: true }), vol: fc.double({ min: 0.04, max: 0.08, noNaN: true }) });

describe('the rating policy', () => {
  it('is Glicko-2 as it is while the board is not anchored', () => {
    expect(rateResult(NEW_RATING, established, false)).toEqual(rateMatch(NEW_RATING, established));
  });

  it('once anchored: an established player against a provisional one moves only the provisional rating', () => {
    const plain = rateMatch(NEW_RATING, established);
    expect(rateResult(NEW_RATING, established, true)).toEqual({ winner: plain.winner, loser: established });
    expect(rateResult(established, established, true)).toEqual(rateMatch(established, established));
  });

  it('once anchored: two provisional players move each other\'s ratings but not their RDs', () => {
    const next = rateResult(NEW_RATING, NEW_RATING, true);
    expect(next.winner.rating).toBeGreaterThan(1500);
    expect(next.loser.rating).toBeLessThan(1500);
    expect([next.winner.rd, next.loser.rd]).toEqual([350, 350]);
  });

  it('once anchored, for any two ratings: a provisional opponent never lowers an RD nor moves an established rating', () => {
    fc.assert(
      fc.property(ratingArb, ratingArb, (w, l) => {
        const next = rateResult(w, l, true);
        for (const [before, opponent, after] of [
          [w, l, next.winner],
          [l, w, next.loser],
        ] as const) {
          if (!provisional(opponent)) continue;
          expect(after.rd).toBeGreaterThanOrEqual(before.rd);
          if (!provisional(before)) expect(after).toEqual(before);
          // So nobody crosses onto the board by it.
          if (provisional(before)) expect(after.rd).toBeGreaterThanOrEqual(PROVISIONAL_RD);
        }
      }),
    );
  });
});
