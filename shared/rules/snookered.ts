// A geometric test of "snookered", on ball positions alone.
//
// WPBSA Rules, Section 2, Definitions, "Snookered": the cue ball is snookered when a direct stroke
// in a straight line to every ball on is wholly or partially obstructed by a ball or balls not on.
// Read as referees apply it for the free ball: the striker is NOT snookered as soon as one ball on
// can be hit on both its extreme edges by a straight stroke. A straight stroke that grazes an
// edge sends the cue ball's centre along a tangent from the cue ball's centre to the circle of
// radius 2R around the object ball; the stroke is obstructed when, on the way to the contact
// point, the cue ball would meet another ball (its centre passes closer than 2R to that ball's
// centre). Cushions and pocket jaws are not modelled ("angled" is not judged), and balls are
// assumed to lie on the bed. Only + - * / and Math.sqrt are used.
import type { Ball, Point } from './types.ts';

/** Squared distance from point p to the segment [a, b]. */
function dist2ToSegment(p: Point, a: Point, b: Point): number {
  const abx = b.x - a.x;
  const aby = b.y - a.y;
  const len2 = abx * abx + aby * aby;
  let t = len2 > 0 ? ((p.x - a.x) * abx + (p.y - a.y) * aby) / len2 : 0;
  if (t < 0) t = 0;
  else if (t > 1) t = 1;
  const dx = a.x + t * abx - p.x;
  const dy = a.y + t * aby - p.y;
  return dx * dx + dy * dy;
}

/** The two positions of the cue ball's centre when it grazes `target` on either edge, from `cue`. */
export function edgeContacts(cue: Point, target: Point, R: number): [Point, Point] | null {
  const dx = target.x - cue.x;
  const dy = target.y - cue.y;
  const d2 = dx * dx + dy * dy;
  const r = 2 * R;
  if (d2 <= r * r) return null; // touching (or overlapping): no straight stroke to speak of
  const d = Math.sqrt(d2);
  const ux = dx / d;
  const uy = dy / d;
  const L = Math.sqrt(d2 - r * r); // length of the tangent
  const c = L / d; // cosine of the angle between the tangent and the line of centres
  const s = r / d; // its sine
  const left = { x: cue.x + L * (c * ux - s * uy), y: cue.y + L * (c * uy + s * ux) };
  const right = { x: cue.x + L * (c * ux + s * uy), y: cue.y + L * (c * uy - s * ux) };
  return [left, right];
}

/** Whether the cue ball, travelling from `from` to `to`, would meet any of `obstacles`. */
export function pathBlocked(from: Point, to: Point, obstacles: readonly Ball[], R: number): boolean {
  const r2 = 4 * R * R * (1 - 1e-12);
  return obstacles.some((o) => dist2ToSegment(o, from, to) < r2);
}

/** Whether both extreme edges of `target` can be hit directly from `cue`. */
export function bothEdgesVisible(cue: Point, target: Point, obstacles: readonly Ball[], R: number): boolean {
  const edges = edgeContacts(cue, target, R);
  if (edges === null) return true;
  return !pathBlocked(cue, edges[0], obstacles, R) && !pathBlocked(cue, edges[1], obstacles, R);
}

/**
 * Whether the cue ball is snookered on `ballsOn` by `obstacles` (normally: every ball that is
 * neither on nor the cue ball). No ball on at all counts as not snookered.
 */
export function isSnookered(cue: Point, ballsOn: readonly Ball[], obstacles: readonly Ball[], R: number): boolean {
  if (ballsOn.length === 0) return false;
  return !ballsOn.some((b) => bothEdgesVisible(cue, b, obstacles, R));
}
