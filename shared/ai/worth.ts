// The referee's verdict on a tried shot as one number, for the player who shot: winning, points,
// keeping the table, no foul.
import type { Game } from '../rules/index.ts';

export function worth(before: Game, after: Game): number {
  const me = before.turn;
  if (after.winner !== null) return after.winner === me ? 1e6 : -1e6;
  const gained = (after.scores[me] ?? 0) - (before.scores[me] ?? 0);
  let lost = 0;
  for (const p of before.players) if (p !== me) lost += (after.scores[p] ?? 0) - (before.scores[p] ?? 0);
  const foul = after.verdict?.foul ? 1 : 0;
  return 100 * gained - 100 * lost + (after.turn === me ? 10 : 0) - 20 * foul;
}
