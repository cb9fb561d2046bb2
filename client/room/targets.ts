// What to aim at: a ring around each ball on, and the first ball the aim's straight line meets,
// checked against the balls on (a warning before an illegal first contact).
import type { Ball } from '../../shared/rules/index.ts';
import type { TableView } from '../table/view.ts';

/** Draws a ring around each ball in `ids` (table coordinates; called from the view's overlay). */
export function drawTargetRings(ctx: CanvasRenderingContext2D, view: TableView, balls: readonly Ball[], ids: readonly string[]): void {
  const R = view.spec.ballRadius;
  ctx.save();
  ctx.strokeStyle = 'rgba(255, 230, 90, 0.9)';
  // Many balls on (snooker's reds): thinner rings, so the pack stays readable.
  ctx.lineWidth = (ids.length > 6 ? 1 : 2) / view.pixelsPerMetre;
  ctx.setLineDash([4 / view.pixelsPerMetre, 3 / view.pixelsPerMetre]);
  for (const b of balls) {
    if (!ids.includes(b.id)) continue;
    ctx.beginPath();
    ctx.arc(b.x, b.y, R * (ids.length > 6 ? 1.25 : 1.45), 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.restore();
}

/**
 * The first ball the cue ball meets going straight along `heading` (null if none is in its way):
 * the nearest ball whose centre passes within 2R of the line, ahead of the cue ball. Spin and
 * cushions are left out: it is a warning, not the referee.
 */
export function firstBallAlong(cue: { x: number; y: number }, heading: number, balls: readonly Ball[], cueId: string, R: number): string | null {
  const dx = Math.cos(heading);
  const dy = Math.sin(heading);
  let best: { id: string; t: number } | null = null;
  for (const b of balls) {
    if (b.id === cueId) continue;
    const ox = b.x - cue.x;
    const oy = b.y - cue.y;
    const along = ox * dx + oy * dy;
    const off2 = ox * ox + oy * oy - along * along;
    const reach = 4 * R * R - off2;
    if (along <= 0 || reach < 0) continue;
    const t = along - Math.sqrt(reach);
    if (best === null || t < best.t) best = { id: b.id, t };
  }
  return best?.id ?? null;
}

/** The warning for a first contact with a ball that is not on, or '' when the contact is legal or unknown. */
export function contactWarning(first: string | null, on: readonly string[]): string {
  if (first === null || on.length === 0 || on.includes(first)) return '';
  const said = (id: string) => (/^red\d*$/.test(id) ? 'a red' : `the ${id}`);
  const colours = ['yellow', 'green', 'brown', 'blue', 'pink', 'black'];
  const onWords = on.every((id) => /^red\d*$/.test(id)) ? 'a red' : on.length === 1 ? said(on[0]!) : on.every((id) => colours.includes(id)) ? 'a colour' : on.length <= 3 ? on.map(said).join(' or ') : 'a ball of your group';
  return `Illegal: ${said(first)} is not the ball on (hit ${onWords} first).`;
}
