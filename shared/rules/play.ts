// A shot played end to end, as the server plays it: the ball in hand placed, the stroke simulated
// by shared/physics, the outcome judged. The server never takes an outcome from anywhere else.
import { simulate, type Outcome as SimOutcome } from '../physics/index.ts';
import { applyShot, placeCueBall, sceneOf, strikeOf } from './index.ts';
import { cueBallId } from './common.ts';
import type { Game, Point, Shot } from './types.ts';

export interface PlayedShot {
  /** The game the shot was played from: after the placement of the ball in hand, if any. */
  readonly from: Game;
  /** The simulation's outcome of sceneOf(from) and strikeOf(shot). */
  readonly outcome: SimOutcome;
  /** The next game, judged by the rules. */
  readonly game: Game;
}

/**
 * Place the ball in hand at `cueBall` (when given), simulate the stroke, judge it. Throws a
 * RuleError (illegal placement or shot) or the physics' SimulationInputError or MiscueError, and
 * then nothing has changed.
 */
export function playShot(game: Game, shot: Shot, cueBall?: Point): PlayedShot {
  const from = cueBall === undefined ? game : placeCueBall(game, shot.player, cueBall);
  const outcome = simulate(sceneOf(from), strikeOf(shot));
  return { from, outcome, game: applyShot(from, shot, outcome) };
}

/**
 * The player on turn ran out of time: judged as a stroke that meets nothing (the cue ball not
 * struck, nothing moved), which each game's rules already penalise as their foul for it (pool:
 * no contact, ball in hand to the opponent; snooker: a foul of at least four; three-cushion: the
 * inning ends). The verdict says it was the clock.
 */
export function shotClockExpired(game: Game): Game {
  const ball = cueBallId(game);
  const shot: Shot = { player: game.turn, ball, heading: 0, speed: 0, side: 0, top: 0 };
  const still = { balls: game.balls.map((b) => ({ id: b.id, x: b.x, y: b.y, pocketed: false })), events: [] };
  const next = applyShot(game, shot, still);
  const v = next.verdict!;
  return { ...next, verdict: { ...v, message: `${game.turn} ran out of time: ${v.message}` } };
}
