// Placing balls: on the bed, clear of other balls, inside the area of a ball in hand; finding a
// free spot for a ball in hand; spotting a ball as near as possible to a point along the long string.
import type { TableSpec } from '../physics/tables.ts';
import { poolMarks, snookerMarks } from './marks.ts';
import type { Ball, BallInHand, Point } from './types.ts';

/** Slack for positions computed in floating point (metres): far below anything a player sees. */
export const EPS = 1e-9;

/** The ball's centre lies where the ball fits on the bed between the cushion noses. */
export function onBed(spec: TableSpec, p: Point): boolean {
  const R = spec.ballRadius;
  return (
    Number.isFinite(p.x) &&
    Number.isFinite(p.y) &&
    Math.abs(p.x) <= spec.length / 2 - R + EPS &&
    Math.abs(p.y) <= spec.width / 2 - R + EPS
  );
}

/** The first ball (other than `except`) that a ball at p would overlap; touching is allowed. */
export function overlapping(spec: TableSpec, balls: readonly Ball[], p: Point, except?: string): Ball | null {
  const d = 2 * spec.ballRadius - EPS;
  for (const b of balls) {
    if (b.id === except) continue;
    const dx = b.x - p.x;
    const dy = b.y - p.y;
    if (dx * dx + dy * dy < d * d) return b;
  }
  return null;
}

/**
 * Whether p lies in the area of a ball in hand. Kitchen (WPA Definitions, "behind the head
 * string"): the centre strictly behind the head string. D (WPBSA Section 1 Rule 1(e), the D, and
 * Section 3, play from in-hand): the centre on or within the lines of the D.
 */
export function inArea(spec: TableSpec, area: Exclude<BallInHand, false>, p: Point): boolean {
  if (!onBed(spec, p)) return false;
  if (area === 'anywhere') return true;
  if (area === 'kitchen') return p.x < poolMarks(spec).headStringX;
  const m = snookerMarks(spec);
  const dx = p.x - m.baulkX;
  return dx <= EPS && dx * dx + p.y * p.y <= (m.dRadius + EPS) * (m.dRadius + EPS);
}

/** Why p is not a legal place for ball `id` in `area`, or null if it is. */
export function placementProblem(
  spec: TableSpec,
  balls: readonly Ball[],
  id: string,
  p: Point,
  area: Exclude<BallInHand, false>,
): string | null {
  if (!Number.isFinite(p.x) || !Number.isFinite(p.y)) return `position (${p.x}, ${p.y}) is not a pair of finite numbers`;
  if (!onBed(spec, p)) return `(${p.x}, ${p.y}) is off the bed of the ${spec.name} table`;
  if (!inArea(spec, area, p)) {
    const where = area === 'kitchen' ? 'behind the head string (the kitchen)' : 'in the D';
    return `(${p.x}, ${p.y}) is not ${where}`;
  }
  const hit = overlapping(spec, balls, p, id);
  if (hit) return `a ball at (${p.x}, ${p.y}) would overlap ball ${hit.id}`;
  return null;
}

/** The preferred place of a cue ball in hand, before any search. */
export function preferredSpot(spec: TableSpec, area: Exclude<BallInHand, false>): Point {
  if (area === 'D') {
    // On the baulk line midway between brown and yellow: the usual break-off position.
    const m = snookerMarks(spec);
    return { x: m.baulkX, y: -m.dRadius / 2 };
  }
  if (area === 'kitchen') return { x: -(3 * spec.length) / 8, y: 0 };
  return { x: -spec.length / 4, y: 0 };
}

/**
 * A free place in `area` for ball `id`, as near as the search finds to the preferred spot: rings of
 * candidates two ball radii apart around it, in a fixed order. Throws if the area is full.
 */
export function freeSpot(
  spec: TableSpec,
  balls: readonly Ball[],
  id: string,
  area: Exclude<BallInHand, false>,
  preferred: Point = preferredSpot(spec, area),
): Point {
  const step = 2 * spec.ballRadius + 0.001;
  const rings = Math.ceil(spec.length / step) + 1;
  for (let k = 0; k <= rings; k++) {
    for (let i = -k; i <= k; i++) {
      for (let j = -k; j <= k; j++) {
        if (Math.max(Math.abs(i), Math.abs(j)) !== k) continue;
        const p = { x: preferred.x + i * step, y: preferred.y + j * step };
        if (placementProblem(spec, balls, id, p, area) === null) return p;
      }
    }
  }
  throw new Error(`no free place for ball ${id} (${area})`);
}

/**
 * The x nearest to x0 along the line y = y0, going in direction dir (+1 or -1) and not beyond
 * `limit`, where a ball can stand without overlapping `balls` (touching is allowed unless `clear`,
 * in which case it must not touch either). Each ball forbids an interval of x; the answer is found
 * by pushing x past the intervals until none contains it. Null if there is no room.
 */
export function freeAlongX(
  spec: TableSpec,
  balls: readonly Ball[],
  y0: number,
  x0: number,
  dir: 1 | -1,
  limit: number,
  clear = false,
): number | null {
  const d = 2 * spec.ballRadius + (clear ? EPS : 0);
  const intervals: Array<[number, number]> = [];
  for (const b of balls) {
    const dy = b.y - y0;
    if (Math.abs(dy) >= d) continue;
    const w = Math.sqrt(d * d - dy * dy);
    intervals.push([b.x - w, b.x + w]);
  }
  let x = x0;
  for (let guard = 0; guard <= intervals.length + 1; guard++) {
    let moved = false;
    for (const [lo, hi] of intervals) {
      if (x > lo && x < hi) {
        x = dir > 0 ? hi : lo;
        moved = true;
      }
    }
    if (!moved) break;
  }
  if (dir > 0 ? x > limit + EPS : x < limit - EPS) return null;
  for (const [lo, hi] of intervals) if (x > lo && x < hi) return null;
  return x;
}

/**
 * Spot a pool ball (WPA 1.4 Spotting Balls): on the long string as near as possible to the foot
 * spot behind it (towards the foot rail); if there is no room there, as near as possible in front
 * of it (towards the head string).
 */
export function spotPoolBall(spec: TableSpec, balls: readonly Ball[], id: string): Ball {
  const foot = poolMarks(spec).footSpot;
  const edge = spec.length / 2 - spec.ballRadius;
  const others = balls.filter((b) => b.id !== id);
  const behind = freeAlongX(spec, others, 0, foot.x, 1, edge);
  if (behind !== null) return { id, x: behind, y: 0 };
  const front = freeAlongX(spec, others, 0, foot.x, -1, -edge);
  if (front !== null) return { id, x: front, y: 0 };
  return { id, ...freeSpot(spec, others, id, 'anywhere', foot) };
}
