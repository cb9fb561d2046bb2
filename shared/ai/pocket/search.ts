// The search: every candidate is first played once without noise (a pot's aim corrected for throw
// and deflection by what the simulation says the object ball did), the best `breadth` are then
// played `samples` times under the level's noise, each result judged by the referee and the
// position it leaves (value.ts); the best mean wins. The noisy samples share their random draws
// across candidates (common random numbers), so candidates are compared on the same luck.
import { detAtan2, tableSpec, type Outcome } from '../../physics/index.ts';
import { playShot, type Game, type Shot } from '../../rules/index.ts';
import type { Context } from '../context.ts';
import { noisy } from '../noise.ts';
import { Random } from '../random.ts';
import type { Candidate } from './candidates.ts';
import { positionSigma, value, WIN } from './value.ts';

interface Tried {
  readonly game: Game;
  readonly outcome: Outcome;
}

function attempt(game: Game, c: Candidate, shot: Shot, ctx: Context): Tried | null {
  ctx.stats.simulations++;
  try {
    const r = playShot(game, shot, c.cueBall);
    return { game: r.game, outcome: r.outcome };
  } catch {
    return null; // a miscue, or a stroke the referee refuses
  }
}

/** The direction the object ball first moved in, or null if it never moved. */
function departure(outcome: Outcome, id: string): { x: number; y: number } | null {
  const path = outcome.paths.find((p) => p.id === id);
  if (!path) return null;
  for (const s of path.segments) {
    const v2 = s.vx * s.vx + s.vy * s.vy;
    if (v2 > 1e-12) {
      const v = Math.sqrt(v2);
      return { x: s.vx / v, y: s.vy / v };
    }
  }
  return null;
}

/**
 * The pot's stroke with its heading corrected: the object ball left at an angle off the line to
 * the pocket (throw, the cue ball's swerve); turn the ghost ball about the object ball by that error.
 */
function corrected(game: Game, c: Candidate, tried: Tried): Shot {
  if (!c.pot) return c.shot;
  const d = departure(tried.outcome, c.pot.target);
  if (!d) return c.shot;
  const cross = d.x * c.pot.uy - d.y * c.pot.ux;
  const dot = d.x * c.pot.ux + d.y * c.pot.uy;
  if (dot < 0.7) return c.shot; // it hit something else first: no use correcting
  const err = detAtan2(cross, dot);
  const from = tried.outcome.paths.find((p) => p.id === c.shot.ball);
  const obj = game.balls.find((b) => b.id === c.pot!.target);
  if (!from || !obj) return c.shot;
  const cue = c.cueBall ?? from.segments[0]!;
  // Rotate the wanted direction by the error and aim at the new ghost ball.
  const ca = 1 - (err * err) / 2;
  const ux = c.pot.ux * ca - c.pot.uy * err;
  const uy = c.pot.ux * err + c.pot.uy * ca;
  const R = 2 * tableSpec(game.table).ballRadius;
  const heading = detAtan2(obj.y - R * uy - cue.y, obj.x - R * ux - cue.x);
  return { ...c.shot, heading };
}

export interface Choice {
  readonly candidate: Candidate;
  readonly shot: Shot;
  readonly value: number;
}

export function search(game: Game, candidates: readonly Candidate[], ctx: Context): Choice | null {
  const sigma = positionSigma(ctx.level.heading);
  const look = ctx.level.lookahead;
  const staged: Choice[] = [];
  for (const c of candidates) {
    ctx.stats.candidates++;
    const first = attempt(game, c, c.shot, ctx);
    if (!first) continue;
    let shot = c.shot;
    let after = first.game;
    if (c.pot) {
      const fixed = corrected(game, c, first);
      if (fixed !== c.shot) {
        const second = attempt(game, c, fixed, ctx);
        if (second && value(game, second.game, sigma, look, ctx.level.heading) >= value(game, first.game, sigma, look, ctx.level.heading) - 0.5) {
          shot = fixed;
          after = second.game;
        }
      }
    }
    staged.push({ candidate: c, shot, value: value(game, after, sigma, look, ctx.level.heading) });
  }
  if (staged.length === 0) return null;
  // Stable: equal values keep the candidates' order.
  const order = staged.map((s, i) => i).sort((a, b) => staged[b]!.value - staged[a]!.value || a - b);
  const seed = Math.floor(ctx.random.uniform() * 0x100000000);
  const runs = (s: Choice, seedOf: number, n: number): number => {
    const random = new Random(seedOf);
    let total = 0;
    for (let i = 0; i < n; i++) {
      const r = attempt(game, s.candidate, noisy(s.shot, ctx.level, random), ctx);
      total += r === null ? -WIN / 2 : value(game, r.game, sigma, look, ctx.level.heading);
    }
    return total;
  };
  const n = ctx.level.samples;
  const sampled = order.slice(0, ctx.level.breadth).map((i) => {
    const s = staged[i]!;
    return { s, total: runs(s, seed, n), n };
  });
  // The best of many noisy means is flattered by its luck (the winner's curse): the leaders are
  // sampled again, twice as long, before one is chosen.
  const ranked = sampled.map((x, i) => i).sort((a, b) => sampled[b]!.total / sampled[b]!.n - sampled[a]!.total / sampled[a]!.n || a - b);
  const finalists = ranked.slice(0, Math.max(1, Math.ceil(sampled.length / 4)));
  if (n > 1 && finalists.length > 1) {
    const seed2 = seed ^ 0x5bd1e995;
    for (const i of finalists) {
      const x = sampled[i]!;
      x.total += runs(x.s, seed2, 2 * n);
      x.n += 2 * n;
    }
  }
  let best: Choice | null = null;
  for (const i of finalists) {
    const x = sampled[i]!;
    const mean = x.total / x.n;
    if (!best || mean > best.value) best = { candidate: x.s.candidate, shot: x.s.shot, value: mean };
  }
  return best;
}
