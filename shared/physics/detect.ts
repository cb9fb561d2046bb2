// When: the time of the next contact of a moving ball with another ball, a cushion or a pocket.
// Every path between events is a parabola p(τ) = p0 + v τ + a τ²/2, so each gap below is a
// polynomial in τ: a quadratic for a straight cushion, a quartic for a ball, an arc or a pocket
// (the squared distance between two parabolas). Roots come from roots.ts, which cannot skip one.
import type { Arc, Pocket, Segment } from './table-geometry.ts';
import { firstEntry, rootsIn } from './roots.ts';

/** A path relative to now: position, velocity and constant acceleration. */
export interface Path {
  x: number;
  y: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
}

/** Relative normal speed below which touching bodies count as neither approaching nor parting (m/s). */
export const CONTACT_SPEED = 1e-6;
/** Relative normal acceleration below which touching bodies count as not pressed together (m/s^2). */
export const CONTACT_ACCEL = 1e-9;
/** Overlap that touching bodies may reach, through rounding, before it counts as a new contact (m). */
export const CONTACT_OVERLAP = 1e-10;

/**
 * The first τ in [0, H] at which the gap polynomial c (positive while apart) closes. `scale` turns
 * distances into the polynomial's units near contact: 1 for a gap, 2d for a squared distance
 * d² - D². When the bodies already touch (c[0] <= 0, within rounding of a contact just resolved)
 * it is a contact now if they approach or, not parting, are pressed together; otherwise the next
 * contact is when they close by CONTACT_OVERLAP more than they are now, so rounding can neither
 * hide a contact nor repeat one at the same instant.
 */
export function nextContact(c: Float64Array, H: number, tol: number, scale: number): number {
  if (c[0]! > 0) return firstEntry(c, 0, H, tol);
  const slope = c[1] ?? 0;
  const slopeEps = scale * CONTACT_SPEED;
  if (slope < -slopeEps) return 0;
  if (slope <= slopeEps && (c[2] ?? 0) < -0.5 * scale * CONTACT_ACCEL) return 0;
  // Measured from the present (possibly slightly overlapping) distance.
  c[0] = scale * CONTACT_OVERLAP;
  return firstEntry(c, 0, H, tol);
}

// The gap polynomial of the current prediction (no allocation per prediction).
const POLY = new Float64Array(5);

/** Squared distance between centres minus dist^2, as a quartic in τ, into POLY. */
function distanceQuartic(dx: number, dy: number, dvx: number, dvy: number, dax: number, day: number, dist: number): Float64Array {
  POLY[0] = dx * dx + dy * dy - dist * dist;
  POLY[1] = 2 * (dx * dvx + dy * dvy);
  POLY[2] = dvx * dvx + dvy * dvy + dx * dax + dy * day;
  POLY[3] = dvx * dax + dvy * day;
  POLY[4] = 0.25 * (dax * dax + day * day);
  return POLY;
}

function xAt(p: Path, t: number): number {
  return p.x + (p.vx + 0.5 * p.ax * t) * t;
}

function yAt(p: Path, t: number): number {
  return p.y + (p.vy + 0.5 * p.ay * t) * t;
}

/** Two balls of radius R meet when their centres are 2R apart. */
export function ballBallTime(a: Path, b: Path, R: number, H: number, tol: number): number {
  const c = distanceQuartic(b.x - a.x, b.y - a.y, b.vx - a.vx, b.vy - a.vy, b.ax - a.ax, b.ay - a.ay, 2 * R);
  return nextContact(c, H, tol, 4 * R);
}

/** A ball meets a straight cushion when its centre is R from the nose line, within the segment. */
export function segmentTime(p: Path, s: Segment, R: number, H: number, tol: number): number {
  // gap = -(n · (p - A)) - R, positive on the table side.
  const c = POLY;
  c[0] = -(s.nx * (p.x - s.ax) + s.ny * (p.y - s.ay)) - R;
  c[1] = -(s.nx * p.vx + s.ny * p.vy);
  c[2] = -0.5 * (s.nx * p.ax + s.ny * p.ay);
  c[3] = 0;
  c[4] = 0;
  const c0 = c[0]!;
  const t = c0 > 0 || onSegment(p, s, 0) ? nextContact(c, H, tol, 1) : -1;
  if (t === Infinity || (t >= 0 && onSegment(p, s, t))) return t;
  c[0] = c0; // nextContact may have moved it
  // The line was crossed beside the segment (a ball in a pocket's mouth is behind the rail's line):
  // walk the crossings for the first that enters the gap within the segment.
  for (const r of rootsIn(c, 0, H)) if (entering(c, r) && onSegment(p, s, r)) return r;
  return Infinity;
}

/** Whether the ball's centre at time t projects onto the segment. */
function onSegment(p: Path, s: Segment, t: number): boolean {
  const ex = s.bx - s.ax;
  const ey = s.by - s.ay;
  const along = ((xAt(p, t) - s.ax) * ex + (yAt(p, t) - s.ay) * ey) / (ex * ex + ey * ey);
  return along >= 0 && along <= 1;
}

/** Whether the gap polynomial closes at its root r (it falls through zero there). */
function entering(c: Float64Array, r: number): boolean {
  return c[1]! + r * (2 * c[2]! + r * (3 * c[3]! + r * 4 * c[4]!)) < 0;
}

/** Whether the direction (dx, dy) from an arc's centre lies within its span. */
export function inArcSpan(arc: Arc, dx: number, dy: number): boolean {
  if (arc.full) return true;
  return arc.ux * dy - arc.uy * dx >= 0 && dx * arc.wy - dy * arc.wx >= 0;
}

export function arcTime(p: Path, arc: Arc, R: number, H: number, tol: number): number {
  const c = distanceQuartic(p.x - arc.cx, p.y - arc.cy, p.vx, p.vy, p.ax, p.ay, R + arc.r);
  const c0 = c[0]!;
  const t = c0 > 0 || onArc(p, arc, 0) ? nextContact(c, H, tol, 2 * (R + arc.r)) : -1;
  if (t === Infinity || (t >= 0 && onArc(p, arc, t))) return t;
  // Inside the arc's circle but beside its span (that part of the circle is in a pocket's mouth or
  // inside the cushion): the first crossing that enters within the span counts.
  c[0] = c0; // nextContact may have moved it
  for (const r of rootsIn(c, 0, H)) if (entering(c, r) && onArc(p, arc, r)) return r;
  return Infinity;
}

function onArc(p: Path, arc: Arc, t: number): boolean {
  return inArcSpan(arc, xAt(p, t) - arc.cx, yAt(p, t) - arc.cy);
}

/** A ball drops when its centre enters the pocket's drop circle. */
export function pocketTime(p: Path, pocket: Pocket, H: number, tol: number): number {
  const c = distanceQuartic(p.x - pocket.x, p.y - pocket.y, p.vx, p.vy, p.ax, p.ay, pocket.r);
  return c[0]! <= 0 ? 0 : firstEntry(c, 0, H, tol);
}

/** The box a path sweeps over [0, H], grown by `pad`: [minX, minY, maxX, maxY]. */
export function sweptBox(p: Path, H: number, pad: number, out: Float64Array): Float64Array {
  let x0 = p.x;
  let x1 = p.x;
  let y0 = p.y;
  let y1 = p.y;
  const ex = p.x + (p.vx + 0.5 * p.ax * H) * H;
  const ey = p.y + (p.vy + 0.5 * p.ay * H) * H;
  x0 = Math.min(x0, ex);
  x1 = Math.max(x1, ex);
  y0 = Math.min(y0, ey);
  y1 = Math.max(y1, ey);
  // The extremum of each coordinate, where its velocity changes sign.
  if (p.ax !== 0) {
    const tx = -p.vx / p.ax;
    if (tx > 0 && tx < H) {
      const x = p.x + 0.5 * p.vx * tx;
      x0 = Math.min(x0, x);
      x1 = Math.max(x1, x);
    }
  }
  if (p.ay !== 0) {
    const ty = -p.vy / p.ay;
    if (ty > 0 && ty < H) {
      const y = p.y + 0.5 * p.vy * ty;
      y0 = Math.min(y0, y);
      y1 = Math.max(y1, y);
    }
  }
  out[0] = x0 - pad;
  out[1] = y0 - pad;
  out[2] = x1 + pad;
  out[3] = y1 + pad;
  return out;
}

export function boxesOverlap(a: Float64Array, b: Float64Array): boolean {
  return a[0]! <= b[2]! && b[0]! <= a[2]! && a[1]! <= b[3]! && b[1]! <= a[3]!;
}
