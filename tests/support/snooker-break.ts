// A scoring snooker break from the D for practice runs, shared by the practice API's tests and the
// practice flood of bench:attacks.
import { chooseShot } from '../../bots/strategy.ts';
import { simulate } from '../../shared/physics/index.ts';
import { playShot, practiceStart, type Game, type PracticeShot } from '../../shared/rules/index.ts';

/**
 * A snooker break of up to `max` shots: a first red found by a fan of headings from the D, then
 * the sound bot. Snooker's layout does not depend on the seed: the same shots play alike with any.
 */
export function snookerBreak(playerId: string, max: number): PracticeShot[] {
  let game: Game = practiceStart('snooker', playerId, 0);
  const shots: PracticeShot[] = [];
  const cue = game.balls.find((b) => b.id === 'cue')!;
  search: for (const cueBall of [undefined, { x: cue.x, y: cue.y + 0.1 }, { x: cue.x, y: cue.y - 0.1 }]) {
    for (const speed of [3, 5, 7]) {
      for (let i = 0; i < 360; i++) {
        const shot: PracticeShot = { shot: { ball: 'cue', heading: (i * Math.PI) / 180, speed, side: 0, top: 0 }, ...(cueBall ? { cueBall } : {}) };
        try {
          const next = playShot(game, { ...shot.shot, player: playerId }, shot.cueBall).game;
          if (!next.verdict!.foul && next.verdict!.potted.length > 0) {
            shots.push(shot);
            game = next;
            break search;
          }
        } catch {
          // a place the cue ball cannot go: the next
        }
      }
    }
  }
  while (shots.length > 0 && shots.length < max && game.winner === null && game.turn === playerId) {
    const { player: _p, ...shot } = chooseShot(game, 'sound', (scene, s) => simulate(scene, s));
    shots.push({ shot });
    game = playShot(game, { ...shot, player: playerId }).game;
  }
  return shots;
}
