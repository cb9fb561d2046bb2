// The computer opponent's one entry point. chooseShot(game, { level, seed }) says what the player
// on turn does, by the rules of shared/rules and the physics of shared/physics: pure and
// deterministic (the same game, level and seed give the same decision in Node and every browser).
import type { Game } from '../rules/index.ts';
import { choosePocketShot } from './pocket/index.ts';
import { chooseCaromShot } from './carom/index.ts';
import { isLevel, LEVELS } from './levels.ts';
import { Random } from './random.ts';
import { noisy } from './noise.ts';
import type { Context } from './context.ts';
import type { AiOptions, Decision, DecisionStats } from './types.ts';

export type { AiOptions, Decision, DecisionStats, Level } from './types.ts';
export { LEVELS, isLevel } from './levels.ts';
export type { LevelSpec } from './levels.ts';

/** The decision for the player on turn. Throws a RangeError for a finished game or a bad level. */
export function chooseShot(game: Game, options: AiOptions, stats?: DecisionStats): Decision {
  if (!isLevel(options.level)) throw new RangeError(`level must be 1 to 5, got ${String(options.level)}`);
  if (!Number.isFinite(options.seed)) throw new RangeError(`seed must be a finite number, got ${options.seed}`);
  if (game.winner !== null) throw new RangeError('the game is over');
  const random = new Random(options.seed);
  // The hand's own draws, so that the search's draws do not change the noise of the stroke played.
  const hand = new Random(Math.floor(random.uniform() * 0x100000000));
  const context = { level: LEVELS[options.level], random, stats: stats ?? { simulations: 0, candidates: 0 } };
  const aimed = think(game, context);
  // The stroke as the computer's hand plays it: the levels differ in the hand as well as the head.
  return 'shot' in aimed ? { ...aimed, shot: noisy(aimed.shot, context.level, hand) } : aimed;
}

function think(game: Game, context: Context): Decision {
  switch (game.kind) {
    case 'nineball':
    case 'eightball':
    case 'snooker':
      return choosePocketShot(game, context);
    case 'threecushion':
      return chooseCaromShot(game, context);
    default:
      throw new RangeError(`the computer does not play ${game.kind}`);
  }
}
