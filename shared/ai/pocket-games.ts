// Nine-ball, eight-ball and snooker: the first version. Ghost-ball pots of each legal target into
// each pocket at two speeds, each tried under the level's noise and judged by the referee.
import { detAtan2, tableSpec } from '../physics/index.ts';
import { cueBallId, legalTargets, placementProblem, type Game, type PocketId, type Point, type Shot } from '../rules/index.ts';
import type { Context } from './context.ts';
import { tryShot } from './try-shot.ts';
import type { Decision } from './types.ts';
import { worth } from './worth.ts';

export function choosePocketShot(game: Game, ctx: Context): Decision {
  if (game.choices.includes('rerack')) return { choice: 'rerack' };
  const cueBall = game.ballInHand === false ? undefined : placeInHand(game);
  const from = cueBall ? { ...game, balls: game.balls.map((b) => (b.id === cueBallId(game) ? { ...b, ...cueBall } : b)) } : game;
  let best: { shot: Shot; value: number } | undefined;
  for (const shot of candidates(from)) {
    ctx.stats.candidates++;
    let value = 0;
    for (let i = 0; i < ctx.level.samples; i++) {
      const next = tryShot(game, shot, cueBall, ctx);
      value += next === null ? -1e9 : worth(game, next);
    }
    if (!best || value > best.value) best = { shot, value };
  }
  if (!best) throw new Error('no candidate shot');
  return cueBall ? { shot: best.shot, cueBall } : { shot: best.shot };
}

function candidates(g: Game): Shot[] {
  const t = tableSpec(g.table);
  const R = t.ballRadius;
  const cueId = cueBallId(g);
  const cue = g.balls.find((b) => b.id === cueId)!;
  const base = { player: g.turn, ball: cueId, side: 0, top: 0 };
  const out: Shot[] = [];
  const breaking = 'phase' in g && g.phase === 'break';
  for (const id of legalTargets(g)) {
    const b = g.balls.find((x) => x.id === id);
    if (!b) continue;
    if (breaking) {
      out.push({ ...base, heading: detAtan2(b.y - cue.y, b.x - cue.x), speed: 8 });
      continue;
    }
    for (const p of t.pockets) {
      const d = Math.sqrt((p.x - b.x) ** 2 + (p.y - b.y) ** 2);
      const gx = b.x - (2 * R * (p.x - b.x)) / d;
      const gy = b.y - (2 * R * (p.y - b.y)) / d;
      const heading = detAtan2(gy - cue.y, gx - cue.x);
      for (const speed of [1.5, 3]) out.push(declare(g, id, p.id as PocketId, { ...base, heading, speed }));
    }
  }
  if (out.length === 0) out.push({ ...base, heading: 0, speed: 2 });
  return out;
}

function declare(g: Game, target: string, pocket: PocketId, shot: Shot): Shot {
  if (g.kind === 'eightball' && target === '8' && g.groups !== null) return { ...shot, calledPocket: pocket };
  if (g.kind === 'snooker' && (g.on === 'colour' || (g.freeBall && !(g.on === 'red' ? target.startsWith('red') : g.on === target)))) return { ...shot, nominated: target };
  return shot;
}

/** A legal place for the ball in hand: where it lies if legal, else the first free point of a grid. */
function placeInHand(g: Game): Point {
  const spec = tableSpec(g.table);
  const id = cueBallId(g);
  const area = g.ballInHand as Exclude<typeof g.ballInHand, false>;
  const cue = g.balls.find((b) => b.id === id)!;
  if (!placementProblem(spec, g.balls, id, cue, area)) return { x: cue.x, y: cue.y };
  for (let i = 0; i <= 40; i++)
    for (let j = 0; j <= 20; j++) {
      const p = { x: -spec.length / 2 + ((i + 0.5) * spec.length) / 41, y: -spec.width / 2 + ((j + 0.5) * spec.width) / 21 };
      if (!placementProblem(spec, g.balls, id, p, area)) return p;
    }
  throw new Error('no free place for the ball in hand');
}
