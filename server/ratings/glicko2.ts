// Glicko-2 ratings (Glickman, "Example of the Glicko-2 system", 2013) through glicko2-lite (MIT):
// each finished match is one rating period for both of its players.
import rate from 'glicko2-lite';

export interface Rating {
  readonly rating: number;
  readonly rd: number;
  readonly vol: number;
}

/** A new player's rating: 1500, RD 350, volatility 0.06 (Glickman's defaults). */
export const NEW_RATING: Rating = { rating: 1500, rd: 350, vol: 0.06 };
/**
 * RD at or above which a rating is provisional (as lichess does) and off the leaderboard. The
 * partial index ratings_board (migrations/008) spells the same bound: change both together.
 */
export const PROVISIONAL_RD = 110;
/** The system constant τ, which limits how fast the volatility moves (Glickman suggests 0.3-1.2). */
export const TAU = 0.5;

/** One player's rating after a period of games against the given opponents (score 1, 0.5 or 0). */
export function ratePeriod(player: Rating, games: readonly { opponent: Rating; score: number }[]): Rating {
  const r = rate(player.rating, player.rd, player.vol, games.map((g) => [g.opponent.rating, g.opponent.rd, g.score] as [number, number, number]), { tau: TAU });
  return { rating: r.rating, rd: r.rd, vol: r.vol };
}

/** Both players' ratings after one match won by the first. */
export function rateMatch(winner: Rating, loser: Rating): { winner: Rating; loser: Rating } {
  return { winner: ratePeriod(winner, [{ opponent: loser, score: 1 }]), loser: ratePeriod(loser, [{ opponent: winner, score: 0 }]) };
}
