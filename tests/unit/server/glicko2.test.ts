// Glicko-2 against the worked example of Glickman's paper ("Example of the Glicko-2 system",
// section "Example calculation"): a player at 1500, RD 200, volatility 0.06 beats a 1400 (RD 30)
// and loses to a 1550 (RD 100) and a 1700 (RD 300); with τ = 0.5 the new rating is 1464.06,
// RD 151.52, volatility 0.05999.
import { describe, expect, it } from 'vitest';
import { NEW_RATING, rateMatch, ratePeriod } from '../../../server/ratings/glicko2.ts';

describe('Glicko-2', () => {
  it('reproduces Glickman\'s worked example', () => {
    const r = ratePeriod({ rating: 1500, rd: 200, vol: 0.06 }, [
      { opponent: { rating: 1400, rd: 30, vol: 0.06 }, score: 1 },
      { opponent: { rating: 1550, rd: 100, vol: 0.06 }, score: 0 },
      { opponent: { rating: 1700, rd: 300, vol: 0.06 }, score: 0 },
    ]);
    expect(r.rating).toBeCloseTo(1464.06, 1);
    expect(r.rd).toBeCloseTo(151.52, 1);
    expect(r.vol).toBeCloseTo(0.05999, 4);
  });

  it('moves the winner up and the loser down, less as the RD shrinks', () => {
    const first = rateMatch(NEW_RATING, NEW_RATING);
    expect(first.winner.rating).toBeGreaterThan(1500);
    expect(first.loser.rating).toBeLessThan(1500);
    expect(first.winner.rating - 1500).toBeCloseTo(1500 - first.loser.rating, 6);
    expect(first.winner.rd).toBeLessThan(350);
    const second = rateMatch(first.winner, first.loser);
    expect(second.winner.rating - first.winner.rating).toBeLessThan(first.winner.rating - 1500);
  });
});
