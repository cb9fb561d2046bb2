// Invariants every simulated outcome must satisfy, checked at every event: no NaN, no overlap, no
// ball through a cushion, energy never rising, events in time order and bounded in number.
import { energyAt, sampleOutcome, tableSpec, type Outcome } from '../../shared/physics/index.ts';
import { inArcSpan } from '../../shared/physics/detect.ts';

export const OVERLAP_TOLERANCE = 1e-9;

export interface Violation {
  readonly t: number;
  readonly what: string;
}

/** The first broken invariant of an outcome, or undefined. */
export function firstViolation(o: Outcome, maxEventsPerBall = 100): Violation | undefined {
  const table = tableSpec(o.table);
  const R = table.ballRadius;
  if (!Number.isFinite(o.duration) || o.duration < 0) return { t: o.duration, what: `duration ${o.duration}` };
  if (o.events.length > maxEventsPerBall * o.balls.length + 50) return { t: o.duration, what: `${o.events.length} events for ${o.balls.length} balls` };
  for (const b of o.balls) {
    if (!Number.isFinite(b.x) || !Number.isFinite(b.y)) return { t: o.duration, what: `ball ${b.id} ends at (${b.x}, ${b.y})` };
  }
  let lastT = 0;
  let lastEnergy = energyAt(o, 0);
  const times = [...new Set(o.events.map((e) => e.t))];
  for (const t of times) {
    if (!(t >= lastT)) return { t, what: `events out of order (${t} after ${lastT})` };
    lastT = t;
    const balls = sampleOutcome(o, t).filter((b) => b.motion !== 'pocketed');
    for (const b of balls) {
      for (const v of [b.x, b.y, b.vx, b.vy, b.wx, b.wy, b.wz]) if (!Number.isFinite(v)) return { t, what: `ball ${b.id} has a non-finite state` };
      if (Math.abs(b.x) > table.length / 2 + 0.2 || Math.abs(b.y) > table.width / 2 + 0.2) return { t, what: `ball ${b.id} off the table at (${b.x}, ${b.y})` };
      for (const c of table.cushions) {
        if (c.kind === 'segment') {
          const ex = c.bx - c.ax;
          const ey = c.by - c.ay;
          const along = ((b.x - c.ax) * ex + (b.y - c.ay) * ey) / (ex * ex + ey * ey);
          const gap = -(c.nx * (b.x - c.ax) + c.ny * (b.y - c.ay)) - R;
          // Only the side of the segment the ball can be on: within R of the line.
          if (along >= 0 && along <= 1 && gap < -OVERLAP_TOLERANCE && gap > -R) return { t, what: `ball ${b.id} through cushion ${c.name} by ${-gap}` };
        } else {
          const dx = b.x - c.cx;
          const dy = b.y - c.cy;
          const d = Math.sqrt(dx * dx + dy * dy);
          if (d < R + c.r - OVERLAP_TOLERANCE && inArcSpan(c, dx, dy)) return { t, what: `ball ${b.id} into ${c.name} by ${R + c.r - d}` };
        }
      }
    }
    for (let i = 0; i < balls.length; i++) {
      for (let j = i + 1; j < balls.length; j++) {
        const d = Math.hypot(balls[i]!.x - balls[j]!.x, balls[i]!.y - balls[j]!.y);
        if (d < 2 * R - OVERLAP_TOLERANCE) return { t, what: `balls ${balls[i]!.id} and ${balls[j]!.id} overlap by ${2 * R - d}` };
      }
    }
    const e = energyAt(o, t);
    if (e > lastEnergy * (1 + 1e-9) + 1e-12) return { t, what: `energy rose from ${lastEnergy} to ${e}` };
    lastEnergy = e;
  }
  return undefined;
}
