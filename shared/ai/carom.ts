// Three-cushion: the first version. A fan of headings at two speeds with running side, each tried
// under the level's noise and judged by the referee.
import { cueBallId, type Game, type Shot } from '../rules/index.ts';
import type { Context } from './context.ts';
import { tryShot } from './try-shot.ts';
import type { Decision } from './types.ts';
import { worth } from './worth.ts';

const TAU = 6.283185307179586;

export function chooseCaromShot(game: Game, ctx: Context): Decision {
  const base = { player: game.turn, ball: cueBallId(game), top: 0 };
  let best: { shot: Shot; value: number } | undefined;
  for (let i = 0; i < 48; i++) {
    const shot: Shot = { ...base, heading: (TAU * i) / 48, speed: i % 4 < 2 ? 3 : 4.5, side: i % 2 ? 0.3 : -0.3 };
    ctx.stats.candidates++;
    let value = 0;
    for (let k = 0; k < ctx.level.samples; k++) {
      const next = tryShot(game, shot, undefined, ctx);
      value += next === null ? -1e9 : worth(game, next);
    }
    if (!best || value > best.value) best = { shot, value };
  }
  return { shot: best!.shot };
}
