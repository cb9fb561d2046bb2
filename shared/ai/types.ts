// Types of the computer opponent: what it is asked (the game, a level, a seed) and what it answers
// (a stroke with its declarations and the ball in hand's place, or one of the game's choices).
import type { Choice, Point, Shot } from '../rules/index.ts';

/** Levels 1 (a beginner) to 5 (the strongest the simulation allows). */
export type Level = 1 | 2 | 3 | 4 | 5;

export interface AiOptions {
  readonly level: Level;
  /** Any uint32-ish number: the same game, level and seed give the same decision everywhere. */
  readonly seed: number;
}

/** What the player on turn does: a stroke (placing the ball in hand first, when in hand) or a choice. */
export type Decision =
  | { readonly shot: Shot; readonly cueBall?: Point }
  | { readonly choice: Choice };

/** How a decision was reached, for benchmarks and logs. */
export interface DecisionStats {
  /** simulate() calls spent on the decision. */
  simulations: number;
  /** Candidate strokes considered. */
  candidates: number;
}
