// The worth of a tried stroke to the player who played it: the referee's verdict (won, lost,
// points, the turn kept, a foul) plus the position left, scored by the geometric chance of the
// next pot for whoever shoots next (PickPocket's lookahead, flattened to one cheap ply).
import type { Game } from '../../rules/index.ts';
import { bestChance } from './position.ts';

export const WIN = 100;

/** Sigma used when judging positions: never below this, as the geometry ignores throw and rattles. */
export function positionSigma(heading: number): number {
  return Math.max(heading, 0.0025);
}

/** Without lookahead (the lowest levels) the next shot's chance is not weighed: they pot and hope. */
export function value(before: Game, after: Game, sigma: number, lookahead = true): number {
  const me = before.turn;
  if (after.winner !== null) return after.winner === me ? WIN : -WIN;
  const v = after.verdict;
  let points = 0;
  if (before.kind === 'snooker') {
    for (const p of before.players) {
      const d = (after.scores[p] ?? 0) - (before.scores[p] ?? 0);
      points += p === me ? d : -d;
    }
    points /= 4;
  } else if (before.kind === 'eightball' && v) {
    points = 0.15 * v.potted.length * (after.turn === me ? 1 : 0);
  }
  if (after.turn === me && after.choices.length === 0) return points + 1 + (lookahead ? 2 * bestChance(after, sigma) : 0);
  const opp = lookahead ? bestChance(after, sigma) : 0.5;
  return points - 0.3 - 2 * opp - (v?.foul ? 0.5 : 0);
}
