// The game's offered choices, taken by a simple rule: eight-ball re-racks and breaks itself (a
// break is worth more than the offender's table); 'pass' hands the table back when the shot on
// offer is poor: nine-ball after a push-out when shooting wins the rack less than half the time
// (the same estimate the pusher aimed at, value.ts), snooker after a foul below a pot chance.
import type { Choice, Game } from '../../rules/index.ts';
import { bestChance } from './position.ts';
import { shooterWinChance } from './value.ts';

/** Snooker: below this geometric chance the offered table is handed back. */
const SNOOKER_PASS_BELOW = 0.3;

export function takeChoice(game: Game, sigma: number, heading: number): Choice | null {
  if (game.choices.includes('rerack')) return 'rerack';
  if (game.choices.includes('pass')) {
    if (game.kind === 'nineball' ? shooterWinChance(game, sigma, heading) < 0.5 : bestChance(game, sigma) < SNOOKER_PASS_BELOW) return 'pass';
  }
  return null;
}
