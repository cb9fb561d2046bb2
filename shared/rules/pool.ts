// What nine-ball and eight-ball share: the rack as a race, the alternating break, the cue ball in
// hand after a foul.
import { opponent, putInHand, specOfGame } from './common.ts';
import { eightBallRack, nineBallRack, POOL_CUE } from './racks.ts';
import type { BallInHand, EightBallGame, NineBallGame, PlayerId, Verdict } from './types.ts';

type PoolGame = NineBallGame | EightBallGame;

/** Rack the balls afresh (seeded) and give the break to `breaker`, cue ball in hand in the kitchen. */
export function rerack(g: PoolGame, breaker: PlayerId): void {
  const spec = specOfGame(g);
  const r = g.kind === 'nineball' ? nineBallRack(spec, g.rng) : eightBallRack(spec, g.rng);
  g.rng = r.rng;
  g.balls = r.balls;
  g.breaker = breaker;
  g.turn = breaker;
  g.ballInHand = 'kitchen';
  g.phase = 'break';
  g.choices = [];
  if (g.kind === 'nineball') g.fouls = Object.fromEntries(g.players.map((p) => [p, 0]));
  else g.groups = null;
}

/**
 * The rack is over: score it; the match is over at raceTo racks, otherwise the next rack is
 * racked and broken by the other player (WPA Regulation 15, alternate break being the standard).
 */
export function endRack(g: PoolGame, rackWinner: PlayerId, v: Verdict): void {
  g.scores[rackWinner] = (g.scores[rackWinner] ?? 0) + 1;
  v.points[rackWinner] = (v.points[rackWinner] ?? 0) + 1;
  v.rackWinner = rackWinner;
  if ((g.scores[rackWinner] ?? 0) >= g.raceTo) {
    g.winner = rackWinner;
    g.choices = [];
    g.ballInHand = false;
    v.next = rackWinner;
    v.continues = false;
    return;
  }
  rerack(g, opponent(g, g.breaker));
  v.next = g.turn;
  v.continues = g.turn === v.player;
}

/** Pass the turn to the opponent with the cue ball in hand in `area`. */
export function giveBallInHand(g: PoolGame, shooter: PlayerId, area: Exclude<BallInHand, false>): void {
  g.balls = putInHand(specOfGame(g), g.balls, POOL_CUE, area);
  g.ballInHand = area;
  g.turn = opponent(g, shooter);
}
