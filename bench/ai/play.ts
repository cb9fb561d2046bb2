// Playing games for the benchmarks: a player is a computer level or the bots' "sound" strategy;
// a decision is applied through the same calls the server uses (decide, playShot).
import { chooseShot, type DecisionStats, type Level } from '../../shared/ai/index.ts';
import { simulate } from '../../shared/physics/index.ts';
import { decide, newGame, playShot, type Game, type GameKind } from '../../shared/rules/index.ts';
import { chooseShot as botChoose } from '../../bots/strategy.ts';

export type Player = Level | 'sound';

export interface Timing {
  readonly level: Level;
  readonly ms: number;
  readonly simulations: number;
}

/** One decision by `who`, applied. Timings of the computer's decisions go to `timings`. */
export function step(game: Game, who: Player, seed: number, timings?: Timing[]): Game {
  if (who === 'sound') {
    const shot = botChoose(game, 'sound', simulate);
    try {
      return playShot(game, shot).game;
    } catch {
      return playShot(game, botChoose(game, 'quick', simulate, 1)).game;
    }
  }
  const stats: DecisionStats = { simulations: 0, candidates: 0 };
  const t0 = performance.now();
  const d = chooseShot(game, { level: who, seed }, stats);
  timings?.push({ level: who, ms: performance.now() - t0, simulations: stats.simulations });
  if ('choice' in d) return decide(game, game.turn, d.choice);
  return playShot(game, d.shot, d.cueBall).game;
}

/** A game between two players, the first breaking; returns the winner's index, or -1 if unfinished. */
export function playGame(kind: GameKind, a: Player, b: Player, seed: number, maxShots: number, timings?: Timing[]): number {
  let g = newGame(kind, ['a', 'b'], { seed });
  for (let i = 0; i < maxShots && g.winner === null; i++) g = step(g, g.turn === 'a' ? a : b, seed * 1000 + i, timings);
  return g.winner === null ? -1 : g.winner === 'a' ? 0 : 1;
}

/** Wilson's 95% interval half-width, for a share of n trials. */
export function margin(share: number, n: number): number {
  return n === 0 ? 0 : 1.96 * Math.sqrt((share * (1 - share)) / n);
}

export function pct(x: number): string {
  return `${(100 * x).toFixed(0)}%`;
}
