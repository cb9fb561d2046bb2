// What every part of a decision shares: the level's spec, the decision's random draws, the tally.
import type { LevelSpec } from './levels.ts';
import type { Random } from './random.ts';
import type { DecisionStats } from './types.ts';

export interface Context {
  readonly level: LevelSpec;
  readonly random: Random;
  readonly stats: DecisionStats;
}
