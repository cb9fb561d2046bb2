// Draws a table's playing area and cushions on a canvas, scaled to fit.
import type { TableSpec } from '../shared/physics/index.ts';

export function drawTable(canvas: HTMLCanvasElement, table: TableSpec): void {
  const ctx = canvas.getContext('2d');
  if (!ctx) return;
  const rail = 0.08; // drawn rail width in metres, only for looks
  const scale = Math.min(canvas.width / (table.length + 2 * rail), canvas.height / (table.width + 2 * rail));
  ctx.save();
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.translate(canvas.width / 2, canvas.height / 2);
  ctx.scale(scale, -scale); // world y points up
  ctx.fillStyle = '#4a2c17';
  ctx.fillRect(-table.length / 2 - rail, -table.width / 2 - rail, table.length + 2 * rail, table.width + 2 * rail);
  ctx.fillStyle = '#1d7a45';
  ctx.fillRect(-table.length / 2, -table.width / 2, table.length, table.width);
  ctx.restore();
}
