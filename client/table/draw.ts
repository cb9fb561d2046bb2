// Draws a table from its spec: wooden rails, cloth, cushions with the pockets' rounded jaws, pocket
// holes with depth, diamonds or the baulk line and D; and the balls, shaded, with a shadow, their
// stripes, numbers and spots turned as each ball is (orientation.ts). World metres, y up; the
// caller sets the transform.
import type { TableSpec } from '../../shared/physics/index.ts';
import { poolMarks, snookerMarks } from '../../shared/rules/index.ts';
import type { BallInHand } from '../../shared/rules/index.ts';
import { ballLook, capView, IVORY, STRIPE_HALF, type CapView } from './ball-look.ts';
import { IDENTITY, markFrame, rotate, type Quat, type Vec3 } from './orientation.ts';

export { ballColour } from './ball-look.ts';

export interface DrawnBall {
  readonly id: string;
  readonly x: number;
  readonly y: number;
  /** How the ball is turned (body to world); upright when absent. */
  readonly q?: Quat;
  /** 0 to 1 of its drop into a pocket: smaller and darker as it goes. */
  readonly sink?: number;
}

/** Drawn rail width in metres, from the cushion nose to the table's edge: looks only. */
export const RAIL = 0.09;
/** The cushion's width from its nose to the wood (m). */
const CUSHION = 0.04;

const CLOTH = { 'pool-9ft': '#1d6fa3', 'snooker-12ft': '#1d7a45', 'carom-match': '#2f6fb3' } as Record<string, string>;

/** A colour #rrggbb scaled by f (below 1 darker). */
function shade(hex: string, f: number): string {
  const n = parseInt(hex.slice(1), 16);
  const c = (v: number) => Math.max(0, Math.min(255, Math.round(v * f)));
  return `rgb(${c(n >> 16)},${c((n >> 8) & 255)},${c(n & 255)})`;
}

/** Device pixels per unit of the current transform. */
function pixelsPerUnit(ctx: CanvasRenderingContext2D): number {
  const m = ctx.getTransform();
  return Math.hypot(m.a, m.b) || 1;
}

export function drawTable(ctx: CanvasRenderingContext2D, table: TableSpec): void {
  const L = table.length / 2;
  const W = table.width / 2;
  const cloth = CLOTH[table.name] ?? '#1d7a45';
  // Wood, lit from the top left.
  const wood = ctx.createLinearGradient(-L, W + RAIL, L, -W - RAIL);
  wood.addColorStop(0, '#6e4325');
  wood.addColorStop(1, '#4a2a15');
  ctx.fillStyle = wood;
  roundRect(ctx, -L - RAIL, -W - RAIL, 2 * (L + RAIL), 2 * (W + RAIL), 0.04);
  ctx.fill();
  ctx.strokeStyle = 'rgba(0,0,0,0.45)';
  ctx.lineWidth = 1.5 / pixelsPerUnit(ctx);
  ctx.strokeRect(-L - CUSHION, -W - CUSHION, 2 * (L + CUSHION), 2 * (W + CUSHION));
  const holes = table.pockets.map((p) => pocketHole(p, L, W));
  // Leather round each pocket, under the cloth and the cushions, cut at the table's edge.
  ctx.save();
  roundRect(ctx, -L - RAIL, -W - RAIL, 2 * (L + RAIL), 2 * (W + RAIL), 0.04);
  ctx.clip();
  for (const h of holes) {
    ctx.fillStyle = '#3a2414';
    ctx.beginPath();
    ctx.ellipse(h.x, h.y, h.r + LEATHER, h.w + LEATHER, Math.atan2(h.by, h.bx), 0, 2 * Math.PI);
    ctx.fill();
    ctx.strokeStyle = 'rgba(255,225,180,0.35)';
    ctx.lineWidth = 1.5 / pixelsPerUnit(ctx);
    ctx.stroke();
  }
  ctx.restore();
  if (table.pockets.length === 0) {
    ctx.fillStyle = shade(cloth, 0.8);
    ctx.fillRect(-L - CUSHION, -W - CUSHION, 2 * (L + CUSHION), 2 * (W + CUSHION));
  }
  // The bed, lighter in the middle as under a lamp, and the shelves of cloth between the jaws.
  const bed = ctx.createRadialGradient(0, 0, 0, 0, 0, Math.hypot(L, W));
  bed.addColorStop(0, shade(cloth, 1.12));
  bed.addColorStop(1, shade(cloth, 0.9));
  ctx.fillStyle = bed;
  ctx.fillRect(-L, -W, 2 * L, 2 * W);
  const rails = railOutlines(table);
  const jaws = rails.flatMap((r) => [r.a, r.b]);
  const jawAt = (x: number, y: number) => jaws.find((j) => Math.abs(j.faceEnd[0] - x) < 1e-9 && Math.abs(j.faceEnd[1] - y) < 1e-9);
  for (const p of table.pockets) {
    const a = jawAt(p.mouth[2]!, p.mouth[3]!);
    const b = jawAt(p.mouth[4]!, p.mouth[5]!);
    if (!a || !b) continue;
    ctx.beginPath();
    for (const [x, y] of [a.corner, a.faceEnd, b.faceEnd, b.corner]) ctx.lineTo(x, y);
    ctx.fill();
  }
  // The holes, clipped at the table's edge: dark in the depth, the wall on the table's side lit.
  ctx.save();
  roundRect(ctx, -L - RAIL, -W - RAIL, 2 * (L + RAIL), 2 * (W + RAIL), 0.04);
  ctx.clip();
  for (const h of holes) {
    // In the hole's frame: x backwards (depth, radius r), y across the throat (half-width w).
    ctx.save();
    ctx.translate(h.x, h.y);
    ctx.rotate(Math.atan2(h.by, h.bx));
    ctx.scale(h.r, h.w);
    const g = ctx.createRadialGradient(0.3, 0, 0.45, 0, 0, 1);
    g.addColorStop(0, '#020202');
    g.addColorStop(0.55, '#0d0a08');
    g.addColorStop(1, '#3b2f26');
    ctx.fillStyle = g;
    ctx.beginPath();
    ctx.arc(0, 0, 1, 0, 2 * Math.PI);
    ctx.fill();
    ctx.restore();
  }
  ctx.restore();
  // The cushions: cloth on the rubber, darker, their noses and rounded jaws outlined.
  ctx.fillStyle = shade(cloth, 0.78);
  ctx.strokeStyle = 'rgba(0,0,0,0.35)';
  ctx.lineWidth = 1.5 / pixelsPerUnit(ctx);
  for (const r of rails) {
    ctx.beginPath();
    ctx.moveTo(r.a.back[0], r.a.back[1]);
    ctx.lineTo(r.a.faceEnd[0], r.a.faceEnd[1]);
    ctx.arcTo(r.a.corner[0], r.a.corner[1], r.b.corner[0], r.b.corner[1], r.a.nose);
    ctx.arcTo(r.b.corner[0], r.b.corner[1], r.b.faceEnd[0], r.b.faceEnd[1], r.b.nose);
    ctx.lineTo(r.b.faceEnd[0], r.b.faceEnd[1]);
    ctx.lineTo(r.b.back[0], r.b.back[1]);
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
  }
  if (table.name !== 'snooker-12ft') drawDiamonds(ctx, L, W, table.pockets.length > 0);
  else drawSnookerMarks(ctx, table);
  // The spots marked on the cloth: pool's head and foot spots, snooker's colour spots.
  ctx.fillStyle = 'rgba(255,255,255,0.55)';
  const spots = table.name === 'snooker-12ft' ? Object.values(snookerMarks(table).spots) : table.name === 'pool-9ft' ? [poolMarks(table).footSpot, poolMarks(table).headSpot] : [];
  for (const p of spots) dot(ctx, p.x, p.y, 0.004);
}

/** Room left for the leather round a hole, inside the table's edge (m). */
const LEATHER = 0.012;

/**
 * A pocket's hole: from the drop circle's front edge (where a ball falls) back, a little wider than
 * the drop circle where the rail leaves room, else as deep as fits inside the table's edge and as
 * wide as the throat (an ellipse).
 */
function pocketHole(p: TableSpec['pockets'][number], L: number, W: number): { x: number; y: number; r: number; w: number; bx: number; by: number } {
  const m = p.mouth;
  // The throat's middle (between the ends of the jaw faces) to the drop circle's centre: backwards.
  const tx = (m[2]! + m[4]!) / 2;
  const ty = (m[3]! + m[5]!) / 2;
  const d = Math.hypot(p.x - tx, p.y - ty) || 1;
  const bx = (p.x - tx) / d;
  const by = (p.y - ty) / d;
  const fx = Math.abs(p.x - p.r * bx);
  const fy = Math.abs(p.y - p.r * by);
  let r = p.r * 1.08;
  r = Math.min(r, (L + RAIL - LEATHER - fx) / (1 + Math.abs(bx)), (W + RAIL - LEATHER - fy) / (1 + Math.abs(by)));
  // Where the rail leaves less depth than the throat is wide (a middle pocket), as wide as the throat.
  const w = Math.max(r, 0.95 * Math.hypot(m[4]! - m[2]!, m[5]! - m[3]!) / 2);
  return { x: p.x - p.r * bx + r * bx, y: p.y - p.r * by + r * by, r, w, bx, by };
}

interface JawEnd {
  /** Where the rail's nose line and the jaw face meet (the rounded nose is cut from this corner). */
  corner: [number, number];
  faceEnd: [number, number];
  /** The face carried on to the back of the cushion. */
  back: [number, number];
  nose: number;
}

/**
 * Each rail's cushion from jaw to jaw, from the collision outline: the rail segment, and at each
 * end the jaw whose rounded nose starts there (its face to the face's end). Without pockets, the
 * four rails end at the corners.
 */
function railOutlines(table: TableSpec): { a: JawEnd; b: JawEnd }[] {
  const out: { a: JawEnd; b: JawEnd }[] = [];
  if (table.pockets.length === 0) return out;
  const arcs = table.cushions.filter((c) => c.kind === 'arc' && c.r > 0);
  for (const s of table.cushions) {
    if (s.kind !== 'segment' || s.name.includes('-face')) continue;
    const jawAt = (px: number, py: number, other: [number, number]): JawEnd | null => {
      const arc = arcs.find((a) => a.kind === 'arc' && Math.abs(a.cx - (px + a.r * s.nx)) < 1e-9 && Math.abs(a.cy - (py + a.r * s.ny)) < 1e-9);
      if (!arc || arc.kind !== 'arc') return null;
      const face = table.cushions.find((c) => c.name === arc.name.replace(/-nose$/, '-face'));
      if (!face || face.kind !== 'segment') return null;
      const dx = face.bx - face.ax;
      const dy = face.by - face.ay;
      const len = Math.hypot(dx, dy);
      const ux = dx / len;
      const uy = dy / len;
      // The rail line p + t e meets the face line a + u d.
      const ex = other[0] - px;
      const ey = other[1] - py;
      const el = Math.hypot(ex, ey);
      const den = (ex / el) * uy - (ey / el) * ux;
      const t = ((face.ax - px) * uy - (face.ay - py) * ux) / den;
      const corner: [number, number] = [px + (t * ex) / el, py + (t * ey) / el];
      // Carried on past the face's end to the back of the cushion.
      const depth = CUSHION - ((face.bx - px) * s.nx + (face.by - py) * s.ny);
      const along = depth / (ux * s.nx + uy * s.ny);
      return { corner, faceEnd: [face.bx, face.by], back: [face.bx + along * ux, face.by + along * uy], nose: arc.r };
    };
    const a = jawAt(s.ax, s.ay, [s.bx, s.by]);
    const b = jawAt(s.bx, s.by, [s.ax, s.ay]);
    if (a && b) out.push({ a, b });
  }
  return out;
}

/** Sights at eighths of the long rails and quarters of the short ones; a pool table's side pockets take the middle ones' place. */
function drawDiamonds(ctx: CanvasRenderingContext2D, L: number, W: number, pockets: boolean): void {
  ctx.fillStyle = '#efe6cf';
  const d = (RAIL + CUSHION) / 2;
  for (let i = 1; i < 8; i++) {
    if (i === 4 && pockets) continue;
    const x = -L + (i * L) / 4;
    dot(ctx, x, W + d, 0.007);
    dot(ctx, x, -W - d, 0.007);
  }
  for (let i = 1; i < 4; i++) {
    const y = -W + (i * W) / 2;
    dot(ctx, L + d, y, 0.007);
    dot(ctx, -L - d, y, 0.007);
  }
}

/** The baulk line and the D (WPBSA: 737 mm from the bottom cushion, radius 292 mm). */
function drawSnookerMarks(ctx: CanvasRenderingContext2D, table: TableSpec): void {
  const m = snookerMarks(table);
  ctx.strokeStyle = 'rgba(255,255,255,0.6)';
  ctx.lineWidth = 0.004;
  ctx.beginPath();
  ctx.moveTo(m.baulkX, -table.width / 2);
  ctx.lineTo(m.baulkX, table.width / 2);
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(m.baulkX, 0, m.dRadius, Math.PI / 2, (3 * Math.PI) / 2);
  ctx.stroke();
}

/** The region a ball in hand's centre may take: a rectangle, or the D (a half disc behind x = cx). */
export type LegalShape =
  | { readonly kind: 'rect'; readonly x0: number; readonly y0: number; readonly x1: number; readonly y1: number }
  | { readonly kind: 'D'; readonly cx: number; readonly r: number };

/** The area of shared/rules/placement.ts (inArea) as a shape: the kitchen, the D or the whole bed. */
export function legalShape(table: TableSpec, area: Exclude<BallInHand, false>): LegalShape {
  const L = table.length / 2 - table.ballRadius;
  const W = table.width / 2 - table.ballRadius;
  if (area === 'kitchen') return { kind: 'rect', x0: -L, y0: -W, x1: poolMarks(table).headStringX, y1: W };
  if (area === 'D') {
    const m = snookerMarks(table);
    return { kind: 'D', cx: m.baulkX, r: m.dRadius };
  }
  return { kind: 'rect', x0: -L, y0: -W, x1: L, y1: W };
}

/** Where a ball in hand may go (legalShape), shaded and outlined. */
export function drawLegalArea(ctx: CanvasRenderingContext2D, table: TableSpec, area: Exclude<BallInHand, false>): void {
  const s = legalShape(table, area);
  ctx.save();
  ctx.beginPath();
  if (s.kind === 'rect') ctx.rect(s.x0, s.y0, s.x1 - s.x0, s.y1 - s.y0);
  else {
    ctx.moveTo(s.cx, s.r);
    ctx.arc(s.cx, 0, s.r, Math.PI / 2, (3 * Math.PI) / 2);
    ctx.closePath();
  }
  ctx.fillStyle = 'rgba(255,255,255,0.09)';
  ctx.fill();
  ctx.strokeStyle = 'rgba(255,255,255,0.75)';
  const px = pixelsPerUnit(ctx);
  ctx.lineWidth = 1.5 / px;
  ctx.setLineDash([6 / px, 4 / px]);
  ctx.stroke();
  ctx.restore();
}

// Gradients in ball radii about the ball's centre, made once per canvas.
interface BallPaints {
  shadow: CanvasGradient;
  light: CanvasGradient;
}
const paints = new WeakMap<CanvasRenderingContext2D, BallPaints>();
function paintsOf(ctx: CanvasRenderingContext2D): BallPaints {
  let p = paints.get(ctx);
  if (!p) {
    const shadow = ctx.createRadialGradient(0, 0, 0.2, 0, 0, 1.3);
    shadow.addColorStop(0, 'rgba(0,0,0,0.5)');
    shadow.addColorStop(1, 'rgba(0,0,0,0)');
    // Light from the top left: a highlight there, the far side in shade.
    const light = ctx.createRadialGradient(-0.38, 0.42, 0, 0, 0, 1);
    light.addColorStop(0, 'rgba(255,255,255,0.75)');
    light.addColorStop(0.12, 'rgba(255,255,255,0.3)');
    light.addColorStop(0.4, 'rgba(255,255,255,0)');
    light.addColorStop(0.75, 'rgba(0,0,0,0.1)');
    light.addColorStop(1, 'rgba(0,0,0,0.5)');
    p = { shadow, light };
    paints.set(ctx, p);
  }
  return p;
}

/** A ball's soft shadow on the cloth, cast down and to the right; drawn under every ball. */
export function drawShadow(ctx: CanvasRenderingContext2D, b: DrawnBall, R: number): void {
  if (b.sink) return;
  ctx.save();
  ctx.translate(b.x + 0.22 * R, b.y - 0.28 * R);
  ctx.scale(R, R);
  ctx.fillStyle = paintsOf(ctx).shadow;
  ctx.beginPath();
  ctx.arc(0, 0, 1.3, 0, 2 * Math.PI);
  ctx.fill();
  ctx.restore();
}

// The marks on a ball, in its body frame: the number's two discs (top and bottom), the stripe's
// axis (its band is the ball less the two caps round ±y), a cue ball's six spots.
const NUMBER_DISC = Math.asin(0.5);
const NUMBER_FACES: readonly (readonly [Vec3, Vec3, Vec3])[] = [
  [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
  [[0, 0, -1], [1, 0, 0], [0, -1, 0]],
];
/** The same discs with the number a quarter turn clockwise, for a table drawn turned (view.ts):
 * on a ball at rest the number then reads upright on the screen, not along the table. */
const NUMBER_FACES_TURNED: readonly (readonly [Vec3, Vec3, Vec3])[] = [
  [[0, 0, 1], [0, -1, 0], [1, 0, 0]],
  [[0, 0, -1], [0, 1, 0], [1, 0, 0]],
];
const SPOT = 0.2;
/** A mark centred on c, with some tangent frame (a spot is round: any will do). */
function frameAt(c: Vec3): readonly [Vec3, Vec3, Vec3] {
  const a: Vec3 = Math.abs(c[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0];
  const rx = a[1] * c[2] - a[2] * c[1];
  const ry = a[2] * c[0] - a[0] * c[2];
  const rz = a[0] * c[1] - a[1] * c[0];
  const n = Math.hypot(rx, ry, rz);
  const r: Vec3 = [rx / n, ry / n, rz / n];
  return [c, r, [c[1] * r[2] - c[2] * r[1], c[2] * r[0] - c[0] * r[2], c[0] * r[1] - c[1] * r[0]]];
}
// Six spots, on three axes at right angles, none of them on top of a ball not yet turned (so an
// upright cue ball is white in the middle).
const S = Math.SQRT1_2;
const SPOTS = ([[S, 0, S], [-S, 0, -S], [0, 1, 0], [0, -1, 0], [-S, 0, S], [S, 0, -S]] as const).map((c) => frameAt(c));

/** `turned`: the table is drawn turned a quarter (+x up the screen), so the numbers are turned back. */
export function drawBall(ctx: CanvasRenderingContext2D, b: DrawnBall, R: number, table?: string, turned = false): void {
  const look = ballLook(b.id, table);
  const q = b.q ?? IDENTITY;
  const sink = b.sink ?? 0;
  ctx.save();
  ctx.translate(b.x, b.y);
  const size = R * (1 - 0.45 * sink);
  ctx.scale(size, size);
  ctx.beginPath();
  ctx.arc(0, 0, 1, 0, 2 * Math.PI);
  ctx.fillStyle = look.colour;
  ctx.fill();
  const marked = look.stripe || look.number !== null || look.spots !== null;
  if (marked) {
    ctx.save();
    ctx.clip();
    if (look.stripe) {
      ctx.fillStyle = IVORY;
      // The number stands along the stripe's axis, as on a real ball: turned with it.
      const axis = rotate(q, turned ? [1, 0, 0] : [0, 1, 0]);
      fillCap(ctx, capView(axis, STRIPE_HALF));
      fillCap(ctx, capView([-axis[0], -axis[1], -axis[2]], STRIPE_HALF));
    }
    if (look.number !== null) for (const f of turned ? NUMBER_FACES_TURNED : NUMBER_FACES) drawNumber(ctx, q, f, look.number);
    if (look.spots !== null) {
      ctx.fillStyle = look.spots;
      for (const f of SPOTS) {
        const { m, facing } = markFrame(q, f[0], f[1], f[2], SPOT);
        if (facing < -Math.sin(SPOT)) continue;
        ctx.save();
        ctx.transform(...m);
        ctx.beginPath();
        ctx.arc(0, 0, Math.sin(SPOT), 0, 2 * Math.PI);
        ctx.fill();
        ctx.restore();
      }
    }
    ctx.restore();
  }
  // Shading over the markings, so the ball reads as a sphere lit from the top left.
  ctx.beginPath();
  ctx.arc(0, 0, 1, 0, 2 * Math.PI);
  ctx.fillStyle = paintsOf(ctx).light;
  ctx.fill();
  if (sink > 0) {
    ctx.fillStyle = `rgba(0,0,0,${(0.8 * sink).toFixed(3)})`;
    ctx.fill();
  }
  // A dark rim, so a ball the colour of the cloth (snooker's green) still stands out.
  ctx.strokeStyle = 'rgba(0,0,0,0.35)';
  ctx.lineWidth = 0.06;
  ctx.stroke();
  ctx.restore();
}

function drawNumber(ctx: CanvasRenderingContext2D, q: Quat, f: readonly [Vec3, Vec3, Vec3], n: number): void {
  const { m, facing } = markFrame(q, f[0], f[1], f[2], NUMBER_DISC);
  if (facing < -0.25) return;
  ctx.save();
  ctx.transform(...m);
  ctx.fillStyle = '#f8f6ef';
  ctx.beginPath();
  ctx.arc(0, 0, 0.5, 0, 2 * Math.PI);
  ctx.fill();
  if (facing > 0.2) {
    // Text at 35 units to a ball radius of 50, flipped to read in the y-up world: a font of a
    // fraction of a unit is clamped or dropped by some browsers (Firefox).
    ctx.scale(1 / 50, -1 / 50);
    ctx.fillStyle = '#111';
    ctx.font = 'bold 35px system-ui, sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(String(n), 0, 2.5);
  }
  ctx.restore();
}

function fillCap(ctx: CanvasRenderingContext2D, cap: CapView): void {
  if (cap.kind === 'hidden') return;
  const e = cap.ellipse;
  ctx.beginPath();
  ctx.ellipse(e.cx, e.cy, e.rx, e.ry, e.rotation, e.start, e.end, e.anticlockwise);
  if (cap.kind === 'part') ctx.arc(0, 0, 1, cap.rim.from, cap.rim.to, cap.rim.anticlockwise);
  ctx.closePath();
  ctx.fill();
}

function dot(ctx: CanvasRenderingContext2D, x: number, y: number, r: number): void {
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.fill();
}

function roundRect(ctx: CanvasRenderingContext2D, x: number, y: number, w: number, h: number, r: number): void {
  ctx.beginPath();
  ctx.moveTo(x + r, y);
  ctx.arcTo(x + w, y, x + w, y + h, r);
  ctx.arcTo(x + w, y + h, x, y + h, r);
  ctx.arcTo(x, y + h, x, y, r);
  ctx.arcTo(x, y, x + w, y, r);
  ctx.closePath();
}
