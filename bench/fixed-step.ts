// The yardstick for bench:sim: the same physics stepped at a fixed 1/512 s with explicit Euler, the
// way one engine in this field steps time. Each step moves every ball by its velocity, applies the
// cloth's friction, then resolves any overlapping approaching pair and any ball past a cushion with
// the very same impact functions the event-driven simulation uses. It is written only to be
// measured against: impacts land after contact, fast balls can tunnel.
import { collideBalls } from '../shared/physics/ball-collision.ts';
import type { BallSample } from '../shared/physics/ball-state.ts';
import { cushionRebound } from '../shared/physics/index.ts';
import { strikeBall } from '../shared/physics/strike.ts';
import { inArcSpan } from '../shared/physics/detect.ts';
import { tableSpec, type Scene, type Shot } from '../shared/physics/index.ts';

export const STEP = 1 / 512;

interface Ball extends BallSample {
  id: string;
  pocketed: boolean;
  moving: boolean;
}

export interface FixedStepResult {
  readonly balls: readonly { id: string; x: number; y: number; pocketed: boolean }[];
  readonly steps: number;
  readonly duration: number;
}

export function simulateFixedStep(scene: Scene, shot: Shot, maxTime = 60): FixedStepResult {
  const t = tableSpec(scene.table);
  const R = t.ballRadius;
  const g = t.g;
  const balls: Ball[] = scene.balls.map((b) => ({ id: b.id, x: b.x, y: b.y, vx: 0, vy: 0, wx: 0, wy: 0, wz: 0, pocketed: false, moving: false }));
  const cue = balls.find((b) => b.id === shot.ball)!;
  strikeBall(shot.heading, shot.speed, shot.side, shot.top, R, cue);
  cue.moving = true;
  const bb = { R, ...t.ballBall };
  const cp = { M: t.ballMass, R, h: t.cushion.height, ee: t.cushion.restitution, muS: t.cloth.muSlide, muW: t.cushion.friction };
  const k = 5 / (2 * R);
  let steps = 0;
  let time = 0;
  while (time < maxTime && balls.some((b) => b.moving)) {
    steps++;
    time += STEP;
    for (const b of balls) {
      if (!b.moving || b.pocketed) continue;
      b.x += b.vx * STEP;
      b.y += b.vy * STEP;
      const ux = b.vx - R * b.wy;
      const uy = b.vy + R * b.wx;
      const u = Math.sqrt(ux * ux + uy * uy);
      const speed = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
      if (u > (7 / 2) * t.cloth.muSlide * g * STEP) {
        const ax = (-t.cloth.muSlide * g * ux) / u;
        const ay = (-t.cloth.muSlide * g * uy) / u;
        b.vx += ax * STEP;
        b.vy += ay * STEP;
        b.wx += k * ay * STEP;
        b.wy -= k * ax * STEP;
      } else if (speed > t.cloth.muRoll * g * STEP) {
        b.vx -= (t.cloth.muRoll * g * b.vx * STEP) / speed;
        b.vy -= (t.cloth.muRoll * g * b.vy * STEP) / speed;
        b.wx = -b.vy / R;
        b.wy = b.vx / R;
      } else {
        b.vx = b.vy = b.wx = b.wy = 0;
      }
      const dz = t.cloth.spinDecel * STEP;
      b.wz = Math.abs(b.wz) <= dz ? 0 : b.wz - Math.sign(b.wz) * dz;
      b.moving = b.vx !== 0 || b.vy !== 0 || b.wz !== 0;
    }
    // Contacts found by overlap at the end of the step.
    for (let i = 0; i < balls.length; i++) {
      const a = balls[i]!;
      if (a.pocketed) continue;
      for (let j = i + 1; j < balls.length; j++) {
        const b = balls[j]!;
        if (b.pocketed || (!a.moving && !b.moving)) continue;
        const dx = b.x - a.x;
        const dy = b.y - a.y;
        if (dx * dx + dy * dy < 4 * R * R && (a.vx - b.vx) * dx + (a.vy - b.vy) * dy > 0) {
          collideBalls(a, b, bb);
          a.moving = b.moving = true;
        }
      }
      if (!a.moving) continue;
      for (const c of t.cushions) {
        let nx: number;
        let ny: number;
        if (c.kind === 'segment') {
          const ex = c.bx - c.ax;
          const ey = c.by - c.ay;
          const along = ((a.x - c.ax) * ex + (a.y - c.ay) * ey) / (ex * ex + ey * ey);
          const gap = -(c.nx * (a.x - c.ax) + c.ny * (a.y - c.ay)) - R;
          if (along < 0 || along > 1 || gap >= 0 || gap < -2 * R) continue;
          nx = c.nx;
          ny = c.ny;
        } else {
          const dx = a.x - c.cx;
          const dy = a.y - c.cy;
          const d = Math.sqrt(dx * dx + dy * dy);
          if (d >= R + c.r || !inArcSpan(c, dx, dy)) continue;
          nx = -dx / d;
          ny = -dy / d;
        }
        const vyf = a.vx * nx + a.vy * ny;
        if (vyf <= 0) continue;
        const out = cushionRebound({ vx: a.vx * ny - a.vy * nx, vy: vyf, wx: a.wx * ny - a.wy * nx, wy: a.wx * nx + a.wy * ny, wz: a.wz }, cp, { tolerance: 'accurate' });
        a.vx = out.vx * ny + out.vy * nx;
        a.vy = -out.vx * nx + out.vy * ny;
        a.wx = out.wx * ny + out.wy * nx;
        a.wy = -out.wx * nx + out.wy * ny;
        a.wz = out.wz;
      }
      for (const p of t.pockets) {
        if ((a.x - p.x) * (a.x - p.x) + (a.y - p.y) * (a.y - p.y) < p.r * p.r) {
          a.pocketed = true;
          a.moving = false;
        }
      }
    }
  }
  return { balls: balls.map((b) => ({ id: b.id, x: b.x, y: b.y, pocketed: b.pocketed })), steps, duration: time };
}
