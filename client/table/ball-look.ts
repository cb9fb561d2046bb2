// What a ball looks like, as plain data (pure, unit-tested): its colour, a stripe or not, its
// number, spots on a cue ball, and the cap of a stripe ball's white ends as the camera above sees it.
import type { Vec3 } from './orientation.ts';

const SOLID: Readonly<Record<string, string>> = {
  cue: '#f4f1e8',
  white: '#f4f1e8',
  yellow: '#f2c511',
  red: '#c0392b',
  green: '#1e8449',
  brown: '#7b4a24',
  blue: '#2e5cb8',
  pink: '#f19cbb',
  black: '#111111',
};
/** Pool balls 1-8; 9-15 are the same colours as stripes. */
const POOL = ['#f2c511', '#2e5cb8', '#c0392b', '#6c3483', '#e67e22', '#1e8449', '#7b241c', '#111111'];

export const IVORY = '#f4f1e8';

export function ballColour(id: string): string {
  if (SOLID[id]) return SOLID[id]!;
  if (id.startsWith('red')) return SOLID.red!;
  const n = Number(id);
  if (Number.isInteger(n) && n >= 1 && n <= 15) return POOL[(n - 1) % 8]!;
  return '#bbbbbb';
}

export interface BallLook {
  readonly colour: string;
  readonly stripe: boolean;
  /** A pool ball's number, printed on two opposite discs. */
  readonly number: number | null;
  /** Spots on a cue ball (so its spin shows), their colour; null for none. */
  readonly spots: string | null;
}

/** `table`: on a carom table the yellow is a cue ball too, and carries spots. */
export function ballLook(id: string, table?: string): BallLook {
  const n = Number(id);
  const numbered = Number.isInteger(n) && n >= 1 && n <= 15;
  return {
    colour: ballColour(id),
    stripe: numbered && n >= 9,
    number: numbered ? n : null,
    spots: id === 'cue' || id === 'white' || (id === 'yellow' && table === 'carom-match') ? '#c0392b' : null,
  };
}

/** Half the width of a stripe's band, as the height of its edge above the ball's equator (in radii). */
export const STRIPE_HALF = 0.55;

/** An ellipse in canvas terms: centre, radii, rotation, and the arc's parameter range. */
export interface EllipseArc {
  readonly cx: number;
  readonly cy: number;
  readonly rx: number;
  readonly ry: number;
  readonly rotation: number;
  readonly start: number;
  readonly end: number;
  readonly anticlockwise: boolean;
}

/**
 * The cap {p : p·a >= h} of the unit sphere as seen from above (+z), for a unit world vector a and
 * 0 < h < 1: nothing when it is on the far side; the whole ellipse its rim projects to when it is
 * all on the near side; otherwise the near arc of that ellipse closed by an arc of the ball's
 * outline (`rim`: from angle `from` to `to`, the short way round).
 */
export type CapView =
  | { readonly kind: 'hidden' }
  | { readonly kind: 'whole'; readonly ellipse: EllipseArc }
  | { readonly kind: 'part'; readonly ellipse: EllipseArc; readonly rim: { readonly from: number; readonly to: number; readonly anticlockwise: boolean } };

export function capView(a: Vec3, h: number): CapView {
  const [ax, ay, az] = a;
  const r = Math.sqrt(1 - h * h);
  const s = Math.hypot(ax, ay);
  if (s < 1e-9) {
    const whole = { cx: 0, cy: 0, rx: r, ry: r, rotation: 0, start: 0, end: 2 * Math.PI, anticlockwise: false };
    return az > 0 ? { kind: 'whole', ellipse: whole } : { kind: 'hidden' };
  }
  // The rim circle: centre h·a, radius r, c(θ) = h a + r (cos θ e1 + sin θ v) with e1 level and
  // v = a × e1; its height is h az + r s sin θ.
  const e1x = -ay / s;
  const e1y = ax / s;
  const rotation = Math.atan2(e1y, e1x);
  const base = { cx: h * ax, cy: h * ay, rx: r, ry: r * Math.abs(az), rotation };
  if (h * az - r * s >= 0) return { kind: 'whole', ellipse: { ...base, start: 0, end: 2 * Math.PI, anticlockwise: false } };
  if (h * az + r * s <= 0) return { kind: 'hidden' };
  const k = (-h * az) / (r * s);
  const t1 = Math.asin(k);
  const t2 = Math.PI - t1;
  // The canvas ellipse's parameter runs with θ when az >= 0 and against it otherwise (its minor
  // axis is the projection of v, which points along -(ax, ay)·az).
  const flip = az < 0;
  const ellipse: EllipseArc = { ...base, start: flip ? -t1 : t1, end: flip ? -t2 : t2, anticlockwise: flip };
  const at = (t: number): number => {
    const x = h * ax + r * Math.cos(t) * e1x + r * Math.sin(t) * (-az * ax) / s;
    const y = h * ay + r * Math.cos(t) * e1y + r * Math.sin(t) * (-az * ay) / s;
    return Math.atan2(y, x);
  };
  const from = at(t2);
  const to = at(t1);
  let d = to - from;
  while (d <= -Math.PI) d += 2 * Math.PI;
  while (d > Math.PI) d -= 2 * Math.PI;
  return { kind: 'part', ellipse, rim: { from, to, anticlockwise: d < 0 } };
}
