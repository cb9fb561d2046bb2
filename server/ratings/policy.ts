// When a match is rated and how far a result may move each rating (docs/api.md, "Ratings"): the
// rules that keep farmed wins over throwaway guests and a colluding partner off the leaderboard.
import { PROVISIONAL_RD, rateMatch, type Rating } from './glicko2.ts';

/** Shots each player must have taken for a match to be rated. */
export const RATED_MIN_SHOTS = 3;
/** Server time from a match's start to its result below which it is not rated (ms; BAIZE_RATED_MIN_PLAY_S). */
export const RATED_MIN_PLAY_MS = 60_000;
/** Rated results of one kind between the same two players (either order) in any 24 hours. */
export const RATED_PER_PAIR_PER_DAY = 3;
export const DAY_MS = 86_400_000;
/**
 * Once a kind's leaderboard holds this many players, only results against players on it can
 * bring anyone onto it (below): before that, on a young server, every rated result counts in full.
 */
export const ANCHOR_BOARD_SIZE = 10;

/** Why a finished match was not rated. */
export type UnratedReason = 'few-shots' | 'too-short' | 'pair-limit' | 'computer';

/** A rating is provisional (off the leaderboard) while its RD is PROVISIONAL_RD or more. */
export function provisional(r: Rating): boolean {
  return r.rd >= PROVISIONAL_RD;
}

/** The reason in words, for the room's "Not rated: ..." sentence. */
export function unratedSentence(reason: UnratedReason, minPlayMs: number): string {
  switch (reason) {
    case 'few-shots':
      return `each player must take at least ${RATED_MIN_SHOTS} shots`;
    case 'too-short':
      return `a rated match lasts at least ${Math.ceil(minPlayMs / 1000)} s`;
    case 'pair-limit':
      return `at most ${RATED_PER_PAIR_PER_DAY} rated matches of a kind between the same two players in 24 hours`;
    case 'computer':
      return 'matches against the computer are never rated';
  }
}

/**
 * Both ratings after a rated match won by the first player. Glicko-2 as it is, except once the
 * board is anchored (it holds ANCHOR_BOARD_SIZE players): a provisional opponent is a player the
 * system knows little about, perhaps a guest made to lose, so a result against one never moves an
 * established rating, and moves a provisional rating but not its RD. Only results against
 * established players then bring a player onto the board.
 */
export function rateResult(winner: Rating, loser: Rating, anchored: boolean): { winner: Rating; loser: Rating } {
  const next = rateMatch(winner, loser);
  if (!anchored) return next;
  return { winner: against(winner, loser, next.winner), loser: against(loser, winner, next.loser) };
}

function against(before: Rating, opponent: Rating, after: Rating): Rating {
  if (!provisional(opponent)) return after;
  if (!provisional(before)) return before;
  return { ...after, rd: Math.max(after.rd, before.rd) };
}
