// A break the practice page's keys can aim exactly, shared by the table's browser test and the
// screenshots.
import { cueBallId, newGame, playShot } from '../../shared/rules/index.ts';

/**
 * The practice page's first table (nine-ball, seed 1) and a break the keys can aim exactly: power
 * up 30 presses (10 m/s), the heading turned by `turns` presses of 0.008 rad, as aim.ts does. The
 * first such break that pots two or more object balls and not the cue ball.
 */
export function pottingBreak(): { presses: string[]; hash: string; pots: string[] } {
  const g = newGame('practice', ['me'], { layout: 'nineball' });
  let speed = 2.5;
  for (let i = 0; i < 30; i++) speed = Math.min(10, speed + 0.25);
  for (let k = 0; k <= 40; k++) {
    for (const [key, sign] of [['ArrowLeft', 1], ['ArrowRight', -1]] as const) {
      let heading = 0;
      for (let i = 0; i < k; i++) heading += sign * 0.008;
      const played = playShot(g, { ball: cueBallId(g), heading, speed, side: 0, top: 0, player: 'me' });
      const pots = played.outcome.events.filter((e) => e.kind === 'pocket').map((e) => e.balls[0]!);
      if (pots.length >= 2 && !pots.includes('cue')) {
        return { presses: [...Array<string>(30).fill('ArrowUp'), ...Array<string>(k).fill(key)], hash: played.outcome.hash, pots };
      }
    }
  }
  throw new Error('no potting break found');
}
