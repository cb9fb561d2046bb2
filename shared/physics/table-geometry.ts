// The cushion outline of a table as collision primitives, built from its pocket specification.
//
// The ball's centre meets a straight cushion when it is R from the cushion's nose line, and a
// rounded jaw (an arc of radius r) when it is R + r from the arc's centre. Rails end where the
// pocket jaws begin; each jaw is a rounded nose (an arc tangent to the rail and to the jaw face,
// "the curved jaw") followed by a straight jaw face that leads into the pocket, ending at a point.
// Together they bound the ball's centre without gaps. A ball is captured when its centre enters
// the pocket's drop circle, which spans the throat between the ends of the two jaw faces, so a
// ball can strike the jaws, rattle between them, and still fall or stay out.

export interface Segment {
  readonly kind: 'segment';
  /** Start and end of the cushion nose line (m). */
  readonly ax: number;
  readonly ay: number;
  readonly bx: number;
  readonly by: number;
  /** Unit normal pointing into the cushion, away from the side the ball is on. */
  readonly nx: number;
  readonly ny: number;
  /** Names the cushion in events: a rail ("top") or a jaw ("TL-jaw"). */
  readonly name: string;
}

export interface Arc {
  readonly kind: 'arc';
  /** Centre and radius of the convex arc (radius 0 is a point). */
  readonly cx: number;
  readonly cy: number;
  readonly r: number;
  /**
   * The arc spans the directions (from its centre) between these two unit vectors, turning
   * counter-clockwise from the first to the second; a full circle when `full`.
   */
  readonly ux: number;
  readonly uy: number;
  readonly wx: number;
  readonly wy: number;
  readonly full: boolean;
  readonly name: string;
}

export type Cushion = Segment | Arc;

export interface Pocket {
  readonly id: string;
  /** Centre and radius of the drop circle: a ball whose centre enters it falls. */
  readonly x: number;
  readonly y: number;
  readonly r: number;
  /**
   * Where a ball's centre may be in the pocket's mouth, outside the rectangle the rails leave it:
   * a quadrilateral from the two jaw noses' virtual corners, moved a ball radius onto the table,
   * to the two ends of the jaw faces (x0, y0, x1, y1, ...).
   */
  readonly mouth: readonly number[];
}

/** One pocket's shape: mouth width between the jaw noses, jaw angle, nose radius, face length. */
export interface PocketShape {
  /** Distance between the two jaw noses (the virtual corners where rail and jaw face meet), m. */
  readonly mouth: number;
  /** Cosine and sine of the angle between the rail and the jaw face (WPA: 142° corner, 104° side). */
  readonly cosJaw: number;
  readonly sinJaw: number;
  /** Radius of the rounded nose joining rail and jaw face (m). */
  readonly noseRadius: number;
  /** Length of the jaw face from the virtual corner into the pocket (m). */
  readonly faceLength: number;
}

export interface TableOutline {
  readonly cushions: readonly Cushion[];
  readonly pockets: readonly Pocket[];
}

interface Jaw {
  /** The virtual corner where the rail's nose line meets the jaw face. */
  px: number;
  py: number;
  /** Unit vector along the rail, pointing away from the pocket. */
  rx: number;
  ry: number;
  /** Unit normal of the rail, pointing into the cushion. */
  nx: number;
  ny: number;
}

function segment(ax: number, ay: number, bx: number, by: number, nx: number, ny: number, name: string): Segment {
  return { kind: 'segment', ax, ay, bx, by, nx, ny, name };
}

function point(x: number, y: number, name: string): Arc {
  return { kind: 'arc', cx: x, cy: y, r: 0, ux: 1, uy: 0, wx: 1, wy: 0, full: true, name };
}

/**
 * The jaw at one side of a pocket: the rounded nose and the face. Returns the cushions and the end
 * of the face (where the drop circle begins) and the point where the rail stops.
 */
function buildJaw(j: Jaw, shape: PocketShape, name: string): { cushions: Cushion[]; railEnd: [number, number]; faceEnd: [number, number]; corner: [number, number] } {
  // Face direction: the rail direction (away from the pocket) turned by the jaw angle into the
  // cushion: d = cos β r + sin β n.
  const dx = shape.cosJaw * j.rx + shape.sinJaw * j.nx;
  const dy = shape.cosJaw * j.ry + shape.sinJaw * j.ny;
  // The nose arc of radius ρ is tangent to both lines; its centre is on the bisector inside the
  // cushion body. With half-angle β/2: tangent points at ρ/tan(β/2) from the corner.
  // tan(β/2) = sin β / (1 + cos β).
  const rho = shape.noseRadius;
  const tanHalf = shape.sinJaw / (1 + shape.cosJaw);
  const along = rho / tanHalf;
  const t1x = j.px + along * j.rx; // on the rail
  const t1y = j.py + along * j.ry;
  const t2x = j.px + along * dx; // on the face
  const t2y = j.py + along * dy;
  // Face normal pointing into the cushion body: the perpendicular of d on the rail's side.
  let fnx = -dy;
  let fny = dx;
  if (fnx * j.rx + fny * j.ry < 0) {
    fnx = -fnx;
    fny = -fny;
  }
  // Arc centre: from the tangent point on the rail, ρ into the cushion.
  const cx = t1x + rho * j.nx;
  const cy = t1y + rho * j.ny;
  // The arc spans from the direction -n (the rail's outward normal at t1) to -fn (at t2).
  let ux = -j.nx;
  let uy = -j.ny;
  let wx = -fnx;
  let wy = -fny;
  if (ux * wy - uy * wx < 0) {
    [ux, uy, wx, wy] = [wx, wy, ux, uy]; // keep the span counter-clockwise from u to w
  }
  const ex = j.px + shape.faceLength * dx;
  const ey = j.py + shape.faceLength * dy;
  const cushions: Cushion[] = [];
  if (rho > 0) cushions.push({ kind: 'arc', cx, cy, r: rho, ux, uy, wx, wy, full: false, name: `${name}-nose` });
  else cushions.push(point(j.px, j.py, `${name}-nose`));
  cushions.push(segment(t2x, t2y, ex, ey, fnx, fny, `${name}-face`));
  cushions.push(point(ex, ey, `${name}-end`));
  return { cushions, railEnd: [t1x, t1y], faceEnd: [ex, ey], corner: [j.px, j.py] };
}

function onTable(corner: [number, number], j: Jaw, R: number): [number, number] {
  return [corner[0] - R * j.nx, corner[1] - R * j.ny];
}

/**
 * The outline of a rectangular table of playing area length x width with six pockets (corner and
 * middle shapes given) or none.
 */
export function buildOutline(length: number, width: number, R: number, corner?: PocketShape, middle?: PocketShape): TableOutline {
  const hx = length / 2;
  const hy = width / 2;
  if (!corner || !middle) {
    return {
      cushions: [
        segment(-hx, -hy, hx, -hy, 0, -1, 'bottom-long'),
        segment(-hx, hy, hx, hy, 0, 1, 'top-long'),
        segment(-hx, -hy, -hx, hy, -1, 0, 'left-short'),
        segment(hx, -hy, hx, hy, 1, 0, 'right-short'),
      ],
      pockets: [],
    };
  }
  const cushions: Cushion[] = [];
  const pockets: Pocket[] = [];
  const d = corner.mouth / Math.SQRT2; // mouth measured across the diagonal: d·√2 = mouth
  const m = middle.mouth / 2;
  // Rail end points, collected per rail in order along it, then joined into segments.
  const longRail: Record<number, number[]> = { 1: [], [-1]: [] }; // x coordinates where the rail at y = sy·hy stops
  const shortRail: Record<number, number[]> = { 1: [], [-1]: [] };
  const drop = (id: string, a: [number, number], b: [number, number], ca: [number, number], cb: [number, number]) => {
    const dx = b[0] - a[0];
    const dy = b[1] - a[1];
    const r = 0.5 * Math.sqrt(dx * dx + dy * dy);
    const mx = 0.5 * (a[0] + b[0]);
    const my = 0.5 * (a[1] + b[1]);
    // Half a radius behind the throat, away from the table: the circle still spans every path a
    // ball's centre can take through the throat (its chord there is 0.87 of the throat, the
    // centre's channel is the throat less a diameter), but jaw hits stay outside it.
    let ox = -dy / (2 * r);
    let oy = dx / (2 * r);
    if (ox * mx + oy * my < 0) {
      ox = -ox;
      oy = -oy;
    }
    pockets.push({ id, x: mx + 0.5 * r * ox, y: my + 0.5 * r * oy, r, mouth: [ca[0], ca[1], a[0], a[1], b[0], b[1], cb[0], cb[1]] });
  };
  // Pocket ids as the referees name them (shared/rules/pockets.ts): B/M/T along x, L = +y, R = -y.
  for (const sx of [-1, 1]) {
    for (const sy of [1, -1]) {
      const id = `${sx < 0 ? 'B' : 'T'}${sy > 0 ? 'L' : 'R'}`;
      const longJaw: Jaw = { px: sx * (hx - d), py: sy * hy, rx: -sx, ry: 0, nx: 0, ny: sy };
      const shortJaw: Jaw = { px: sx * hx, py: sy * (hy - d), rx: 0, ry: -sy, nx: sx, ny: 0 };
      const onLong = buildJaw(longJaw, corner, `${id}-long`);
      const onShort = buildJaw(shortJaw, corner, `${id}-short`);
      cushions.push(...onLong.cushions, ...onShort.cushions);
      longRail[sy]!.push(onLong.railEnd[0]);
      shortRail[sx]!.push(onShort.railEnd[1]);
      drop(id, onLong.faceEnd, onShort.faceEnd, onTable(onLong.corner, longJaw, R), onTable(onShort.corner, shortJaw, R));
    }
  }
  for (const sy of [1, -1]) {
    const id = `M${sy > 0 ? 'L' : 'R'}`;
    const rightJaw: Jaw = { px: m, py: sy * hy, rx: 1, ry: 0, nx: 0, ny: sy };
    const leftJaw: Jaw = { px: -m, py: sy * hy, rx: -1, ry: 0, nx: 0, ny: sy };
    const right = buildJaw(rightJaw, middle, `${id}-right`);
    const left = buildJaw(leftJaw, middle, `${id}-left`);
    cushions.push(...right.cushions, ...left.cushions);
    longRail[sy]!.push(right.railEnd[0], left.railEnd[0]);
    drop(id, right.faceEnd, left.faceEnd, onTable(right.corner, rightJaw, R), onTable(left.corner, leftJaw, R));
  }
  for (const sy of [1, -1]) {
    const xs = longRail[sy]!.slice().sort((a, b) => a - b); // [-corner, -middle, +middle, +corner]
    const name = sy > 0 ? 'top-long' : 'bottom-long';
    cushions.push(segment(xs[0]!, sy * hy, xs[1]!, sy * hy, 0, sy, `${name}-left`));
    cushions.push(segment(xs[2]!, sy * hy, xs[3]!, sy * hy, 0, sy, `${name}-right`));
  }
  for (const sx of [-1, 1]) {
    const ys = shortRail[sx]!.slice().sort((a, b) => a - b);
    cushions.push(segment(sx * hx, ys[0]!, sx * hx, ys[1]!, sx, 0, sx < 0 ? 'left-short' : 'right-short'));
  }
  return { cushions, pockets };
}

/** Whether (x, y) lies inside the convex polygon of flat coordinates (either winding). */
export function inConvexPolygon(poly: readonly number[], x: number, y: number): boolean {
  let sign = 0;
  const n = poly.length / 2;
  for (let i = 0; i < n; i++) {
    const ax = poly[2 * i]!;
    const ay = poly[2 * i + 1]!;
    const bx = poly[(2 * i + 2) % poly.length]!;
    const by = poly[(2 * i + 3) % poly.length]!;
    const cross = (bx - ax) * (y - ay) - (by - ay) * (x - ax);
    if (cross === 0) continue;
    const s = cross > 0 ? 1 : -1;
    if (sign === 0) sign = s;
    else if (s !== sign) return false;
  }
  return true;
}

/** The cushion a ball of radius R at (x, y) sinks into by more than tol, if any. */
export function penetratedCushion(cushions: readonly Cushion[], x: number, y: number, R: number, tol: number): Cushion | undefined {
  for (const c of cushions) {
    if (c.kind === 'segment') {
      const ex = c.bx - c.ax;
      const ey = c.by - c.ay;
      const along = ((x - c.ax) * ex + (y - c.ay) * ey) / (ex * ex + ey * ey);
      const gap = -(c.nx * (x - c.ax) + c.ny * (y - c.ay)) - R;
      if (along >= 0 && along <= 1 && gap < -tol && gap > -2 * R) return c;
    } else {
      const dx = x - c.cx;
      const dy = y - c.cy;
      const inSpan = c.full || (c.ux * dy - c.uy * dx >= 0 && dx * c.wy - dy * c.wx >= 0);
      if (inSpan && dx * dx + dy * dy < (R + c.r - tol) * (R + c.r - tol)) return c;
    }
  }
  return undefined;
}
