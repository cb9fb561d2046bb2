// Draws a table (cloth, rails, pockets) and balls on a canvas, scaled to fit.
import type { TableSpec } from '../shared/physics/index.ts';

export interface DrawnBall {
  readonly id: string;
  readonly x: number;
  readonly y: number;
}

const RAIL = 0.08; // drawn rail width in metres, only for looks

const BALL_COLOURS: Readonly<Record<string, string>> = {
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
const POOL_COLOURS = ['#f2c511', '#2e5cb8', '#c0392b', '#6c3483', '#e67e22', '#1e8449', '#7b241c', '#111111'];

export function ballColour(id: string): string {
  if (BALL_COLOURS[id]) return BALL_COLOURS[id]!;
  if (id.startsWith('red')) return BALL_COLOURS.red!;
  const n = Number(id);
  if (Number.isInteger(n) && n >= 1 && n <= 15) return POOL_COLOURS[(n - 1) % 8]!;
  return '#bbbbbb';
}

export function drawTable(canvas: HTMLCanvasElement, table: TableSpec, balls: readonly DrawnBall[] = []): void {
  const ctx = canvas.getContext('2d');
  if (!ctx) return;
  const scale = Math.min(canvas.width / (table.length + 2 * RAIL), canvas.height / (table.width + 2 * RAIL));
  ctx.save();
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.translate(canvas.width / 2, canvas.height / 2);
  ctx.scale(scale, -scale); // world y points up
  ctx.fillStyle = '#4a2c17';
  ctx.fillRect(-table.length / 2 - RAIL, -table.width / 2 - RAIL, table.length + 2 * RAIL, table.width + 2 * RAIL);
  ctx.fillStyle = '#1d7a45';
  ctx.fillRect(-table.length / 2, -table.width / 2, table.length, table.width);
  ctx.fillStyle = '#0b0b0b';
  for (const p of table.pockets) {
    ctx.beginPath();
    ctx.arc(p.x, p.y, p.r, 0, 2 * Math.PI);
    ctx.fill();
  }
  for (const b of balls) {
    ctx.fillStyle = ballColour(b.id);
    ctx.beginPath();
    ctx.arc(b.x, b.y, table.ballRadius, 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.restore();
}
