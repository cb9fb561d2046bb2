// A practice run, scored by playing its shots: from the game's own start (a full snooker table,
// a nine-ball rack to break, three-cushion's opening position), the player plays on while the rules
// keep them at the table. The score is what the run earned: snooker's break, the nine-ball balls
// potted (a break-and-run wins the rack), three-cushion's points. The server plays the shots
// itself, and so can anyone, so a score is never taken on a client's word.
import { RuleError } from './errors.ts';
import { newGame } from './index.ts';
import { achievements, type Achievement } from './match-record.ts';
import { playShot } from './play.ts';
import type { Game, PlayerId, Point, Shot, StrikeParams } from './types.ts';

export const PRACTICE_KINDS = ['snooker', 'nineball', 'threecushion'] as const;
export type PracticeKind = (typeof PRACTICE_KINDS)[number];

/** The table's other seat in a practice run: never at the table while the run lasts. */
export const PRACTICE_OPPONENT = 'practice-opponent';

/** Shots a practice run may have. */
export const PRACTICE_MAX_SHOTS = 500;

/**
 * The game a practice run starts from. Nine-ball is one rack (a run-out from the break); a snooker
 * frame has no race; three-cushion races to more points than a run has shots, so the run lasts
 * while the player scores, never ending at the first point.
 */
export function practiceStart(kind: PracticeKind, player: PlayerId, seed: number): Game {
  return newGame(kind, [player, PRACTICE_OPPONENT], { seed, raceTo: kind === 'threecushion' ? PRACTICE_MAX_SHOTS + 1 : 1 });
}

export interface PracticeShot {
  readonly shot: StrikeParams & Omit<Partial<Shot>, 'player'>;
  readonly cueBall?: Point;
}

export interface PracticeRun {
  readonly start: Game;
  readonly games: readonly Game[];
  readonly score: number;
  /** What the run achieved, as a match would record it (a break, a run, a break-and-run). */
  readonly achievements: readonly Achievement[];
}

/**
 * Plays a practice run's shots for `player` from the start of `kind` with `seed`. Throws a RuleError
 * naming the shot (by index) that the rules refuse or that comes after the run has ended, and the
 * physics' error for a shot it refuses.
 */
export function practiceRun(kind: PracticeKind, player: PlayerId, seed: number, shots: readonly PracticeShot[]): PracticeRun {
  const start = practiceStart(kind, player, seed);
  let game = start;
  const games: Game[] = [];
  let score = 0;
  shots.forEach((s, i) => {
    if (game.winner !== null || game.turn !== player) {
      throw new RuleError('game-over', `shots[${i}]: the run ended after shot ${i}`);
    }
    let next: Game;
    try {
      next = playShot(game, { ...s.shot, player }, s.cueBall).game;
    } catch (err) {
      if (err instanceof Error) err.message = `shots[${i}]: ${err.message}`;
      throw err;
    }
    const v = next.verdict!;
    if (!v.foul) score += kind === 'nineball' ? v.potted.length : (v.points[player] ?? 0);
    game = next;
    games.push(next);
  });
  return { start, games, score, achievements: achievements(start, games).filter((a) => a.player === player) };
}
