// The worth of a tried stroke to the player who played it: the referee's verdict plus the position
// left, scored by the geometric chance of the next pot for whoever shoots next (PickPocket's
// lookahead, flattened to one cheap ply). Pool: an estimate of the chance of winning the rack,
// the shooter running out with the next pot's chance p and then q per ball; snooker: points.
import { cueBallId, groupOf, type Game } from '../../rules/index.ts';
import { bestChance } from './position.ts';

export const WIN = 100;

/** Sigma used when judging positions: never below this, as the geometry ignores throw and rattles. */
export function positionSigma(heading: number): number {
  return Math.max(heading, 0.0025);
}

/** Per-ball success the player expects of itself after the next pot (its level's hand). */
function perBall(heading: number): number {
  return Math.max(0.5, 0.97 - 15 * heading);
}

/** Balls the player on turn must still pot to win the rack. */
function ballsLeft(game: Game): number {
  const objects = game.balls.filter((b) => b.id !== cueBallId(game));
  if (game.kind === 'eightball') {
    const g = game.groups;
    if (g === null) return Math.ceil((objects.length - 1) / 2) + 1;
    const mine = g[game.turn];
    return objects.filter((b) => groupOf(b.id) === mine).length + 1;
  }
  return objects.length;
}

/** Chance that the player on turn in `game` wins the rack, if it runs out or else fares evenly. */
function winChance(game: Game, p: number, q: number): number {
  let run = p;
  for (let i = 1; i < ballsLeft(game); i++) run *= q;
  return run + (1 - run) * 0.4;
}

/** The chance that the player on turn wins the rack from here (nine-ball's push-out answer). */
export function shooterWinChance(game: Game, sigma: number, heading: number): number {
  return winChance(game, bestChance(game, sigma), perBall(heading));
}

/** Without lookahead (the lowest levels) the next shot's chance is not weighed: they pot and hope. */
export function value(before: Game, after: Game, sigma: number, lookahead = true, heading = sigma): number {
  const me = before.turn;
  if (after.winner !== null) return after.winner === me ? WIN : -WIN;
  const v = after.verdict;
  const mine = after.turn === me && after.choices.length === 0;
  const p = lookahead || !mine ? bestChance(after, sigma) : 0.5;
  if (before.kind !== 'snooker') {
    const w = winChance(after, p, perBall(heading));
    // After a push-out the opponent shoots or hands the shot back, whichever is worse for me.
    if (after.choices.includes('pass')) return WIN * Math.min(w, 1 - w);
    return WIN * (mine ? w : 1 - w) - (v?.foul ? 1 : 0);
  }
  let points = 0;
  for (const pl of before.players) {
    const d = (after.scores[pl] ?? 0) - (before.scores[pl] ?? 0);
    points += pl === me ? d : -d;
  }
  points /= 4;
  if (mine) return points + 1 + (lookahead ? 2 * p : 0);
  return points - 0.3 - 2 * (lookahead ? p : 0.5) - (v?.foul ? 0.5 : 0);
}
