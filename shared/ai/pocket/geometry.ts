// Plane geometry of pocket games: the ghost-ball aim (the cue ball's centre must arrive two radii
// behind the object ball on the line to the pocket), clear paths, one-cushion mirror images, and
// a cheap pot probability under the level's aiming noise (in the spirit of the geometric shot
// filters of PickPocket, Smith 2006/2007, and CueCard, Archibald et al. 2009: rank many strokes
// by geometry, simulate only the best).
import type { Pocket, TableSpec } from '../../physics/index.ts';
import type { Ball, Point } from '../../rules/index.ts';

export interface PocketAim {
  readonly id: string;
  /** The point the object ball is sent at: the middle of the mouth, half a radius in. */
  readonly aim: Point;
  /** Unit vector from the table into the pocket, normal to the mouth. */
  readonly nx: number;
  readonly ny: number;
  /** Half the distance between the jaw noses. */
  readonly half: number;
}

const cache = new Map<TableSpec, PocketAim[]>();

/** The pockets as aiming targets (the mouth's first and last corners are the jaw noses). */
export function pocketAims(spec: TableSpec): PocketAim[] {
  const hit = cache.get(spec);
  if (hit) return hit;
  const out = spec.pockets.map((p: Pocket) => {
    const m = p.mouth;
    const n = m.length;
    const ax = m[0]!;
    const ay = m[1]!;
    const bx = m[n - 2]!;
    const by = m[n - 1]!;
    const mx = (ax + bx) / 2;
    const my = (ay + by) / 2;
    const dx = p.x - mx;
    const dy = p.y - my;
    const d = Math.sqrt(dx * dx + dy * dy) || 1;
    const half = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay)) / 2;
    const R = spec.ballRadius;
    return { id: p.id, aim: { x: mx + (dx / d) * 0.5 * R, y: my + (dy / d) * 0.5 * R }, nx: dx / d, ny: dy / d, half };
  });
  cache.set(spec, out);
  return out;
}

export function dist(a: Point, b: Point): number {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  return Math.sqrt(dx * dx + dy * dy);
}

/** Whether a ball can roll from a to b without touching any ball but those in `ignore`. */
export function clearPath(balls: readonly Ball[], a: Point, b: Point, R: number, ignore: readonly string[]): boolean {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const L2 = dx * dx + dy * dy;
  const lim = 2 * R - 1e-6;
  for (const o of balls) {
    if (ignore.includes(o.id)) continue;
    let t = L2 > 0 ? ((o.x - a.x) * dx + (o.y - a.y) * dy) / L2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const ex = a.x + t * dx - o.x;
    const ey = a.y + t * dy - o.y;
    if (ex * ex + ey * ey < lim * lim) return false;
  }
  return true;
}

/**
 * Whether a ball rolling from a to b passes across the mouth of a pocket (other than `except`):
 * along a rail past a side pocket, say, where it would drop or catch the jaw.
 */
export function crossesPocket(spec: TableSpec, a: Point, b: Point, except: string): boolean {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const L2 = dx * dx + dy * dy;
  for (const p of pocketAims(spec)) {
    if (p.id === except) continue;
    let t = L2 > 0 ? ((p.aim.x - a.x) * dx + (p.aim.y - a.y) * dy) / L2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    const ex = a.x + t * dx - p.aim.x;
    const ey = a.y + t * dy - p.aim.y;
    if (ex * ex + ey * ey < p.half * p.half) return true;
  }
  return false;
}

/** erf by Abramowitz and Stegun 7.1.27 (error below 5e-4): arithmetic only, so exact everywhere. */
export function erf(x: number): number {
  const s = x < 0 ? -1 : 1;
  const a = Math.abs(x);
  const d = 1 + a * (0.278393 + a * (0.230389 + a * (0.000972 + a * 0.078108)));
  const d2 = d * d;
  return s * (1 - 1 / (d2 * d2));
}

export interface PotGeometry {
  /** Where the cue ball's centre must be at contact. */
  readonly ghost: Point;
  /** Cut angle's cosine (1: full ball). */
  readonly cosCut: number;
  /** Cue ball to ghost, object ball to its aim point (m). */
  readonly d1: number;
  readonly d2: number;
  /** Unit direction the object ball must leave in. */
  readonly ux: number;
  readonly uy: number;
  /** Probability of the pot under a heading error of sigma (radians), from geometry alone. */
  readonly p: number;
}

/** Steepest cut tried: thinner contacts hardly pot and throw unpredictably. */
const MAX_CUT_COS = 0.2;

/**
 * The ghost-ball pot of `obj` sent at `aim` (a pocket, or its mirror image for a bank), or null if
 * it is blocked, too thin or would enter the mouth from behind. The object ball's direction error
 * is the heading error magnified by d1 / (2R cos cut) (the contact point moves across the object
 * ball); it must stay within the mouth's half-width, seen from d2 away, less the ball's margin.
 */
export function potGeometry(
  spec: TableSpec,
  balls: readonly Ball[],
  cue: Point,
  cueId: string,
  obj: Ball,
  aim: Point,
  pocket: PocketAim,
  sigma: number,
  slack = 1,
): PotGeometry | null {
  const R = spec.ballRadius;
  const d2 = dist(obj, aim);
  if (d2 < 1e-6) return null;
  const ux = (aim.x - obj.x) / d2;
  const uy = (aim.y - obj.y) / d2;
  const ghost = { x: obj.x - 2 * R * ux, y: obj.y - 2 * R * uy };
  // The cue ball cannot reach a ghost inside a cushion (a ball frozen on a rail is not cut off it).
  if (Math.abs(ghost.x) > spec.length / 2 - R + 1e-4 || Math.abs(ghost.y) > spec.width / 2 - R + 1e-4) return null;
  const d1 = dist(cue, ghost);
  if (d1 < 1e-6) return null;
  const cosCut = ((ghost.x - cue.x) * ux + (ghost.y - cue.y) * uy) / d1;
  if (cosCut < MAX_CUT_COS) return null;
  if (!clearPath(balls, cue, ghost, R, [cueId, obj.id])) return null;
  if (!clearPath(balls, obj, aim, R, [cueId, obj.id])) return null;
  if (crossesPocket(spec, cue, ghost, '') || crossesPocket(spec, obj, aim, pocket.id)) return null;
  const cosIn = ux * pocket.nx + uy * pocket.ny;
  if (cosIn < 0.1) return null;
  const tol = Math.max(0.002, pocket.half * cosIn - 0.35 * R) * slack;
  const spread = (sigma * d1) / (2 * R * cosCut) + sigma;
  const p = erf(tol / d2 / (spread * 1.4142135623730951));
  // Very short cue-ball runs are awkward (no room to stroke, double hits): trusted less.
  const near = d1 < 0.12 ? 0.5 + d1 / 0.24 : 1;
  return { ghost, cosCut, d1, d2, ux, uy, p: p * (1 - 0.05 * d2) * near };
}

/**
 * The mirror image of p in each rail (the cushion noses' lines pulled in a radius, where a ball's
 * centre turns): a one-cushion bank or kick aims at the image.
 */
export function railImages(spec: TableSpec, p: Point): Point[] {
  const X = spec.length / 2 - spec.ballRadius;
  const Y = spec.width / 2 - spec.ballRadius;
  return [
    { x: 2 * X - p.x, y: p.y },
    { x: -2 * X - p.x, y: p.y },
    { x: p.x, y: 2 * Y - p.y },
    { x: p.x, y: -2 * Y - p.y },
  ];
}
