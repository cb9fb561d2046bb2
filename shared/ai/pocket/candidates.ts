// Candidate strokes, generated from geometry: pots (ghost-ball aim into each pocket, and one-
// cushion banks aiming the object ball at a pocket's image in a rail), each with a few speeds and
// spins for position; safeties (a fan of contacts on each legal ball at several speeds); kicks
// (the cue ball at a ball's image in a rail, for when nothing is in sight).
import { detAtan2, tableSpec, type TableSpec } from '../../physics/index.ts';
import { cueBallId, legalTargets, type Ball, type Game, type Point, type Shot } from '../../rules/index.ts';
import { declare } from './declare.ts';
import { dist, pocketAims, potGeometry, railImages, type PocketAim, type PotGeometry } from './geometry.ts';

export interface Candidate {
  shot: Shot;
  /** The ball in hand's place, when in hand. */
  cueBall?: Point;
  /** A pot's object ball and the direction it should leave in (for the aim's correction). */
  pot?: { target: string; ux: number; uy: number };
  /** Geometric pot chance (0 for safeties and kicks): the first, cheap ranking. */
  prior: number;
}

export interface Pot {
  readonly target: Ball;
  readonly pocket: PocketAim;
  readonly geo: PotGeometry;
  readonly bank: boolean;
}

/** Rolling resistance (m/s^2, muRoll g) and the share of speed a centre-ball hit keeps once rolling. */
const DECEL = 0.1;
const ROLLING = 5 / 7;

/** Every pot for the cue ball at `cue`, best geometric chance first (ties in a fixed order). */
export function pots(game: Game, cue: Point, sigma: number, banks: boolean): Pot[] {
  const spec = tableSpec(game.table);
  const cueId = cueBallId(game);
  const balls = game.balls.map((b) => (b.id === cueId ? { id: cueId, x: cue.x, y: cue.y } : b));
  const out: Pot[] = [];
  for (const id of legalTargets(game)) {
    const target = balls.find((b) => b.id === id);
    if (!target) continue;
    for (const pocket of pocketAims(spec)) {
      const geo = potGeometry(spec, balls, cue, cueId, target, pocket.aim, pocket, sigma);
      if (geo && geo.p > 0.01) out.push({ target, pocket, geo, bank: false });
      if (!banks) continue;
      for (const image of railImages(spec, pocket.aim)) {
        const bank = bankGeometry(spec, balls, cue, cueId, target, pocket, image, sigma);
        if (bank && bank.p > 0.01) out.push({ target, pocket, geo: bank, bank: true });
      }
    }
  }
  return out.sort((a, b) => b.geo.p - a.geo.p);
}

/** A one-cushion bank: aimed at the pocket's image; both legs must be clear; judged as harder. */
function bankGeometry(spec: TableSpec, balls: readonly Ball[], cue: Point, cueId: string, obj: Ball, pocket: PocketAim, image: Point, sigma: number): PotGeometry | null {
  // The entry angle after the rail is not known here: the mouth is taken as seen at 45 degrees.
  const d = dist(obj, image) || 1;
  const normal = { ...pocket, nx: (0.7071 * (image.x - obj.x)) / d, ny: (0.7071 * (image.y - obj.y)) / d };
  const geo = potGeometry(spec, balls, cue, cueId, obj, image, normal, sigma, 0.6);
  if (!geo) return null;
  // The pocket must be met after the rail: the image's leg must cross the rail line first.
  const X = spec.length / 2 - spec.ballRadius;
  const Y = spec.width / 2 - spec.ballRadius;
  const tx = geo.ux !== 0 ? ((geo.ux > 0 ? X : -X) - obj.x) / geo.ux : Infinity;
  const ty = geo.uy !== 0 ? ((geo.uy > 0 ? Y : -Y) - obj.y) / geo.uy : Infinity;
  const t = Math.min(tx, ty);
  if (!(t > 0) || t >= geo.d2 - 0.05) return null;
  const bounce = { x: obj.x + geo.ux * t, y: obj.y + geo.uy * t };
  if (dist(bounce, pocket.aim) < 0.15) return null;
  return { ...geo, p: geo.p * 0.8 };
}

/** The speed that takes the object ball to the pocket with a little to spare. */
function baseSpeed(geo: PotGeometry): number {
  const need = Math.sqrt(2 * DECEL * (geo.d2 + 0.25)) / (ROLLING * ROLLING) / Math.max(0.3, geo.cosCut);
  return Math.min(6, 0.5 + need + 0.2 * geo.d1);
}

/** Stroke variants by level: speed factors and (top, side) tip offsets, most natural first. */
const VARIANTS: readonly [number, number, number][] = [
  [1.3, 0, 0],
  [2, 0.4, 0],
  [2, -0.45, 0],
  [1, 0.3, 0],
  [3, -0.5, 0],
  [3, 0.45, 0],
  [1.4, -0.3, 0],
  [2, 0, 0.35],
  [2, 0, -0.35],
  [4.5, 0, 0],
  [2.5, 0.2, 0.3],
  [2.5, 0.2, -0.3],
  [2.5, -0.3, 0.3],
  [2.5, -0.3, -0.3],
];

export function potStrokes(game: Game, pot: Pot, cue: Point, variants: number, cueBall?: Point): Candidate[] {
  const cueId = cueBallId(game);
  const heading = detAtan2(pot.geo.ghost.y - cue.y, pot.geo.ghost.x - cue.x);
  const base = baseSpeed(pot.geo);
  const out: Candidate[] = [];
  for (let i = 0; i < Math.min(variants, VARIANTS.length); i++) {
    const [k, top, side] = VARIANTS[i]!;
    const speed = Math.min(7, Math.max(0.4, base * k));
    const shot = declare(game, pot.target.id, pot.pocket.id, { player: game.turn, ball: cueId, heading, speed, side, top });
    out.push({ shot, cueBall, pot: { target: pot.target.id, ux: pot.geo.ux, uy: pot.geo.uy }, prior: pot.geo.p });
  }
  return out;
}

const FAN = [0, -0.5, 0.5, -1.1, 1.1, -1.6, 1.6, -1.85, 1.85];
const SAFE_SPEEDS = [1.2, 2.2, 0.7, 3.4, 5];

/** Safeties: contacts across each legal ball (nearest first) at several speeds, and kicks. */
export function safetyStrokes(game: Game, cue: Point, count: number, cueBall?: Point): Candidate[] {
  const spec = tableSpec(game.table);
  const R = spec.ballRadius;
  const cueId = cueBallId(game);
  const targets = legalTargets(game)
    .map((id) => game.balls.find((b) => b.id === id))
    .filter((b): b is Ball => b !== undefined)
    .sort((a, b) => dist(cue, a) - dist(cue, b) || (a.id < b.id ? -1 : 1))
    .slice(0, 3);
  const out: Candidate[] = [];
  const per = Math.max(1, Math.floor(count / Math.max(1, targets.length)));
  for (const t of targets) {
    const d = dist(cue, t);
    const px = -(t.y - cue.y) / d;
    const py = (t.x - cue.x) / d;
    let n = 0;
    for (let s = 0; s < SAFE_SPEEDS.length && n < per; s++) {
      for (let f = 0; f < FAN.length && n < per; f++) {
        const o = FAN[f]! * R;
        const heading = detAtan2(t.y + py * o - cue.y, t.x + px * o - cue.x);
        out.push({ shot: declare(game, t.id, undefined, { player: game.turn, ball: cueId, heading, speed: SAFE_SPEEDS[s]!, side: 0, top: 0 }), cueBall, prior: 0 });
        n++;
      }
    }
    // One-cushion kicks at the ball's images.
    for (const image of railImages(spec, t)) {
      const heading = detAtan2(image.y - cue.y, image.x - cue.x);
      for (const speed of [1.8, 3.2]) out.push({ shot: declare(game, t.id, undefined, { player: game.turn, ball: cueId, heading, speed, side: 0, top: 0 }), cueBall, prior: 0 });
    }
  }
  return out;
}

/** Headings of a push-out's roll, in eighths of a turn from each legal ball's line. */
const PUSH_TURNS = [0, 0.25, -0.25, 0.5, -0.5, 1, -1, 1.5, -1.5, 2];
const PUSH_SPEEDS = [0.6, 1.1];

/**
 * Nine-ball push-outs (WPA 2.4), on the shot right after the break: soft rolls that need hit
 * nothing, fanned about the line to the lowest ball, for a position the opponent must take or
 * hand back (value.ts weighs both answers).
 */
export function pushOutStrokes(game: Game, cue: Point, count: number, cueBall?: Point): Candidate[] {
  if (game.kind !== 'nineball' || game.phase !== 'push-out' || count === 0) return [];
  const lowest = legalTargets(game)
    .map((id) => game.balls.find((b) => b.id === id))
    .find((b): b is Ball => b !== undefined);
  const base = lowest ? detAtan2(lowest.y - cue.y, lowest.x - cue.x) : 0;
  const out: Candidate[] = [];
  for (const speed of PUSH_SPEEDS) {
    for (const turn of PUSH_TURNS) {
      if (out.length >= count) return out;
      const heading = base + (turn * Math.PI) / 4;
      out.push({ shot: { player: game.turn, ball: cueBallId(game), heading, speed, side: 0, top: 0, pushOut: true }, cueBall, prior: 0 });
    }
  }
  return out;
}
