// Draws a table from its spec: rails, cloth, cushion noses, pockets, diamonds, and the balls with
// their colours, stripes and numbers. World metres, y up; the caller sets the transform.
import type { TableSpec } from '../../shared/physics/index.ts';

export interface DrawnBall {
  readonly id: string;
  readonly x: number;
  readonly y: number;
}

/** Drawn rail width in metres: looks only. */
export const RAIL = 0.09;

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

export function ballColour(id: string): string {
  if (SOLID[id]) return SOLID[id]!;
  if (id.startsWith('red')) return SOLID.red!;
  const n = Number(id);
  if (Number.isInteger(n) && n >= 1 && n <= 15) return POOL[(n - 1) % 8]!;
  return '#bbbbbb';
}

const CLOTH = { 'pool-9ft': '#1d6fa3', 'snooker-12ft': '#1d7a45', 'carom-match': '#2f6fb3' } as Record<string, string>;

export function drawTable(ctx: CanvasRenderingContext2D, table: TableSpec): void {
  const L = table.length / 2;
  const W = table.width / 2;
  ctx.fillStyle = '#5a341b';
  roundRect(ctx, -L - RAIL, -W - RAIL, 2 * (L + RAIL), 2 * (W + RAIL), 0.04);
  ctx.fillStyle = CLOTH[table.name] ?? '#1d7a45';
  ctx.fillRect(-L, -W, 2 * L, 2 * W);
  // Cushion noses, darker cloth on the rubber.
  ctx.strokeStyle = 'rgba(0,0,0,0.35)';
  ctx.lineWidth = 0.012;
  for (const c of table.cushions) {
    if (c.kind !== 'segment') continue;
    ctx.beginPath();
    ctx.moveTo(c.ax, c.ay);
    ctx.lineTo(c.bx, c.by);
    ctx.stroke();
  }
  ctx.fillStyle = '#0a0a0a';
  for (const p of table.pockets) {
    ctx.beginPath();
    ctx.arc(p.x, p.y, p.r * 1.15, 0, 2 * Math.PI);
    ctx.fill();
  }
  if (table.name !== 'snooker-12ft') drawDiamonds(ctx, L, W, table.pockets.length > 0);
  else drawSnookerMarks(ctx, table);
}

/** Sights at eighths of the long rails and quarters of the short ones; a pool table's side pockets take the middle ones' place. */
function drawDiamonds(ctx: CanvasRenderingContext2D, L: number, W: number, pockets: boolean): void {
  ctx.fillStyle = '#efe6cf';
  const d = RAIL / 2;
  for (let i = 1; i < 8; i++) {
    if (i === 4 && pockets) continue;
    const x = -L + (i * L) / 4;
    dot(ctx, x, W + d, 0.008);
    dot(ctx, x, -W - d, 0.008);
  }
  for (let i = 1; i < 4; i++) {
    const y = -W + (i * W) / 2;
    dot(ctx, L + d, y, 0.008);
    dot(ctx, -L - d, y, 0.008);
  }
}

/** The baulk line and the D (WPBSA: 737 mm from the bottom cushion, radius 292 mm). */
function drawSnookerMarks(ctx: CanvasRenderingContext2D, table: TableSpec): void {
  const baulk = -table.length / 2 + 0.737;
  ctx.strokeStyle = 'rgba(255,255,255,0.6)';
  ctx.lineWidth = 0.004;
  ctx.beginPath();
  ctx.moveTo(baulk, -table.width / 2);
  ctx.lineTo(baulk, table.width / 2);
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(baulk, 0, 0.292, Math.PI / 2, (3 * Math.PI) / 2);
  ctx.stroke();
}

export function drawBall(ctx: CanvasRenderingContext2D, b: DrawnBall, R: number): void {
  const colour = ballColour(b.id);
  const n = Number(b.id);
  const striped = Number.isInteger(n) && n >= 9 && n <= 15;
  ctx.save();
  ctx.beginPath();
  ctx.arc(b.x, b.y, R, 0, 2 * Math.PI);
  ctx.fillStyle = striped ? '#f4f1e8' : colour;
  ctx.fill();
  if (striped) {
    ctx.clip();
    ctx.fillStyle = colour;
    ctx.fillRect(b.x - R, b.y - R * 0.55, 2 * R, R * 1.1);
  }
  ctx.restore();
  // A dark rim, so a ball the colour of the cloth (snooker's green) still stands out.
  ctx.strokeStyle = 'rgba(0,0,0,0.5)';
  ctx.lineWidth = R * 0.08;
  ctx.beginPath();
  ctx.arc(b.x, b.y, R, 0, 2 * Math.PI);
  ctx.stroke();
  if (Number.isInteger(n) && n >= 1 && n <= 15) {
    ctx.fillStyle = '#f8f6ef';
    dot(ctx, b.x, b.y, R * 0.5);
    ctx.save();
    ctx.translate(b.x, b.y);
    // Text upright in a y-up world, set at 35 units to a ball of 50: a font of a few hundredths
    // of a unit (metres) is clamped or dropped by some browsers (Firefox).
    const unit = R / 50;
    ctx.scale(unit, -unit);
    ctx.fillStyle = '#111';
    ctx.font = 'bold 35px system-ui, sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(String(n), 0, 2.5);
    ctx.restore();
  }
  // A highlight, so balls read as spheres.
  ctx.fillStyle = 'rgba(255,255,255,0.35)';
  dot(ctx, b.x - R * 0.35, b.y + R * 0.35, R * 0.22);
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
  ctx.fill();
}
