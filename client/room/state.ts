// The room page's state that is not the server's: what made the verdict shown (read from the games
// before and after it), and the players' ratings around the match.
import type { Game } from '../../shared/rules/index.ts';
import type { VerdictHow } from '../verdict.ts';
import type { RatingChange } from './result.ts';

export type RoomRatings = Record<string, RatingChange>;

/**
 * What made `after`'s verdict, from the game before it: a broadcast stroke (with its
 * declarations); else a concession or claim; a verdict that counted a shot without a stroke is
 * the shot clock; one that did not is a choice (a pass, or an eight-ball re-rack). null: the
 * verdict is the one `before` had.
 */
export function howOf(before: Game | null, after: Game, shot?: { readonly pushOut?: boolean; readonly calledPocket?: string }, claimed = false): VerdictHow | null {
  const v = after.verdict;
  if (!v) return {};
  // The same verdict (a placement, a reconnection): what made it is unchanged.
  if (!shot && before?.verdict && before.verdict.shot === v.shot && before.verdict.message === v.message && before.verdict.player === v.player) return null;
  const known = before ?? undefined;
  if (shot) return { action: 'shot', shot, ...(known ? { before: known } : {}) };
  if (v.loss === 'concession') return { action: claimed ? 'claim' : 'concede' };
  if (!before) return {};
  if (after.shots > before.shots) return { action: 'clock', before };
  return { action: 'decide', choice: after.kind === 'eightball' ? 'rerack' : 'pass' };
}
