// How good a table is for the player about to shoot: the best geometric pot chance among the balls
// they may legally hit first (the lookahead of position play, and the opponent's chance when
// judging a safety or a miss).
import { tableSpec } from '../../physics/index.ts';
import { ballValue, cueBallId, legalTargets, type Ball, type Game } from '../../rules/index.ts';
import { pocketAims, potGeometry } from './geometry.ts';

/** Chance credited to a ball in hand, by area: the placement search almost always finds a pot. */
const IN_HAND = { anywhere: 0.92, kitchen: 0.6, D: 0.55 } as const;

/** Weight of a pot for the player on turn: snooker values the ball; pool balls count alike. */
export function potWorth(game: Game, id: string): number {
  return game.kind === 'snooker' ? (ballValue(id) + 4) / 11 : 1;
}

/** The best geometric pot chance (times the ball's worth) of the player on turn in `game`. */
export function bestChance(game: Game, sigma: number): number {
  if (game.winner !== null) return 0;
  if (game.ballInHand !== false) return IN_HAND[game.ballInHand];
  const spec = tableSpec(game.table);
  const cueId = cueBallId(game);
  const cue = game.balls.find((b) => b.id === cueId);
  if (!cue) return 0;
  let best = 0;
  for (const id of legalTargets(game)) {
    const obj = game.balls.find((b) => b.id === id);
    if (!obj) continue;
    const w = potWorth(game, id);
    if (w <= best) continue;
    for (const pk of pocketAims(spec)) {
      const g = potGeometry(spec, game.balls, cue, cueId, obj, pk.aim, pk, sigma);
      if (g && g.p * w > best) best = g.p * w;
    }
  }
  return best;
}

/** Best chance from a given cue ball place (placement search). */
export function chanceFrom(game: Game, cue: Ball, sigma: number): number {
  const balls = game.balls.map((b) => (b.id === cue.id ? cue : b));
  return bestChance({ ...game, balls, ballInHand: false } as Game, sigma);
}
