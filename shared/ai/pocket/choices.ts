// The game's offered choices, taken by a simple rule: eight-ball re-racks and breaks itself (a
// break is worth more than the offender's table); 'pass' (nine-ball after a push-out, snooker
// after a foul) hands the table back when the shot on offer is poor.
import type { Choice, Game } from '../../rules/index.ts';
import { bestChance } from './position.ts';

/** Below this geometric chance the offered table is handed back. */
const PASS_BELOW = { nineball: 0.5, snooker: 0.3 } as const;

export function takeChoice(game: Game, sigma: number): Choice | null {
  if (game.choices.includes('rerack')) return 'rerack';
  if (game.choices.includes('pass')) {
    const limit = game.kind === 'nineball' ? PASS_BELOW.nineball : PASS_BELOW.snooker;
    if (bestChance(game, sigma) < limit) return 'pass';
  }
  return null;
}
