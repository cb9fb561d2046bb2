// Reachable games for the computer's tests: seeded racks played on by a few random strokes (and
// level-1 decisions where a random stroke cannot be played: ball in hand, choices).
import { chooseShot, type Decision } from '../../../shared/ai/index.ts';
import { cueBallId, decide, newGame, playShot, type Game, type GameKind } from '../../../shared/rules/index.ts';

export interface Stroke {
  heading: number;
  speed: number;
  side: number;
  top: number;
}

export function apply(game: Game, d: Decision): Game {
  if ('choice' in d) return decide(game, game.turn, d.choice);
  return playShot(game, d.shot, d.cueBall).game;
}

export function reachable(kind: GameKind, seed: number, strokes: readonly Stroke[]): Game {
  let g = newGame(kind, ['a', 'b'], { seed });
  strokes.forEach((s, i) => {
    if (g.winner !== null) return;
    if (g.ballInHand !== false || g.choices.length > 0 || ('phase' in g && g.phase === 'break')) {
      g = apply(g, chooseShot(g, { level: 1, seed: seed + i }));
      return;
    }
    try {
      g = playShot(g, { player: g.turn, ball: cueBallId(g), ...s }).game;
    } catch {
      // a miscue: the stroke is not played
    }
  });
  return g;
}
