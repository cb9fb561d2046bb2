// Small helpers to lay out scenes and aim shots, deterministic like the rest of shared/.
import { detAtan2 } from '../physics/det-math.ts';
import { tableSpec, type SceneBall, type Shot, type TableName } from '../physics/index.ts';

export interface Point {
  readonly x: number;
  readonly y: number;
}

/** Heading from a to b (radians from +x). */
export function aim(a: Point, b: Point): number {
  return detAtan2(b.y - a.y, b.x - a.x);
}

/** Where the cue ball's centre must be at contact to send `object` toward `target` (the ghost ball). */
export function ghost(object: Point, target: Point, R: number): Point {
  const dx = target.x - object.x;
  const dy = target.y - object.y;
  const d = Math.sqrt(dx * dx + dy * dy);
  return { x: object.x - (2 * R * dx) / d, y: object.y - (2 * R * dy) / d };
}

export function shot(ball: string, heading: number, speed: number, side = 0, top = 0): Shot {
  return { ball, heading, speed, side, top };
}

/** The centre of a ball resting against a rail: `side` is 'top' (+y), 'bottom', 'left' (-x) or 'right'. */
export function onRail(table: TableName, side: 'top' | 'bottom' | 'left' | 'right', along: number): Point {
  const t = tableSpec(table);
  const hx = t.length / 2 - t.ballRadius;
  const hy = t.width / 2 - t.ballRadius;
  switch (side) {
    case 'top':
      return { x: along, y: hy };
    case 'bottom':
      return { x: along, y: -hy };
    case 'left':
      return { x: -hx, y: along };
    default:
      return { x: hx, y: along };
  }
}

/** A line of `count` touching balls from `start` along `heading` components (ux, uy), ids given. */
export function frozenLine(ids: readonly string[], start: Point, ux: number, uy: number, R: number): SceneBall[] {
  return ids.map((id, i) => ({ id, x: start.x + 2 * R * i * ux, y: start.y + 2 * R * i * uy }));
}

/** A 32-bit generator (mulberry32), for random scenes that are the same everywhere. */
export function generator(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let z = s;
    z = Math.imul(z ^ (z >>> 15), z | 1);
    z ^= z + Math.imul(z ^ (z >>> 7), z | 61);
    return ((z ^ (z >>> 14)) >>> 0) / 4294967296;
  };
}

/** `count` balls placed at random on a table, none overlapping, ids b0, b1, ... */
export function randomBalls(table: TableName, count: number, next: () => number): SceneBall[] {
  const t = tableSpec(table);
  const R = t.ballRadius;
  const hx = t.length / 2 - R;
  const hy = t.width / 2 - R;
  const balls: SceneBall[] = [];
  while (balls.length < count) {
    const x = (2 * next() - 1) * hx;
    const y = (2 * next() - 1) * hy;
    if (balls.every((b) => (b.x - x) * (b.x - x) + (b.y - y) * (b.y - y) >= 4 * R * R * 1.0001)) balls.push({ id: `b${balls.length}`, x, y });
  }
  return balls;
}
