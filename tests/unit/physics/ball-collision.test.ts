import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { collideBalls, type BallBallParams } from '../../../shared/physics/ball-collision.ts';
import type { BallSample } from '../../../shared/physics/ball-state.ts';
import { specificEnergy } from '../../../shared/physics/cloth-motion.ts';

const DEG = Math.PI / 180;

/** The velocity a sliding ball ends up rolling with: v - (2/7) u (Han 2005). */
function rolledOut(s: BallSample, R: number): { vx: number; vy: number } {
  const ux = s.vx - R * s.wy;
  const uy = s.vy + R * s.wx;
  return { vx: s.vx - (2 / 7) * ux, vy: s.vy - (2 / 7) * uy };
}

function at(x: number, y: number, vx = 0, vy = 0, wx = 0, wy = 0, wz = 0): BallSample {
  return { x, y, vx, vy, wx, wy, wz };
}

describe('ball-ball impact', () => {
  // Mathavan, Jackson and Parkin 2014 (Sports Engineering 17:227-237), Tables 1-2, with their
  // constants: R 0.02625, e 0.89, μ_b 0.05 (constant), μ_s 0.21. Values once both balls roll.
  const M14: BallBallParams = { R: 0.02625, restitution: 0.89, frictionA: 0.05, frictionB: 0, frictionC: 0 };
  const rows = [
    [1.539, 58.63, 33.83, 0.914, 0.831, 31.93, 32.2],
    [1.032, 39.31, 26.36, 0.52, 0.599, 32.45, 25.07],
    [1.364, 51.96, 40.52, 0.917, 0.676, 29.91, 38.62],
    [1.731, 65.94, 46.5, 1.28, 0.78, 27.32, 44.38],
    [0.942, 35.89, 18.05, 0.383, 0.579, 29.47, 17.15],
  ] as const;
  it.each(rows)('reproduces Mathavan 2014: V %s m/s, ω_T %s rad/s, cut %s° (speeds within 1%, angles within 0.5°)', (V, wT, cut, cueSpeed, objSpeed, cueAngle, objAngle) => {
    const c = cut * DEG;
    const cue = at(0, 0, V * Math.cos(c), V * Math.sin(c), -wT * Math.sin(c), wT * Math.cos(c));
    const obj = at(2 * M14.R, 0);
    collideBalls(cue, obj, M14);
    const a = rolledOut(cue, M14.R);
    const b = rolledOut(obj, M14.R);
    expect(Math.abs(Math.hypot(a.vx, a.vy) / cueSpeed - 1)).toBeLessThan(0.01);
    expect(Math.abs(Math.hypot(b.vx, b.vy) / objSpeed - 1)).toBeLessThan(0.01);
    expect(Math.abs(Math.abs(Math.atan2(a.vy, a.vx) - c) / DEG - cueAngle)).toBeLessThan(0.5);
    expect(Math.abs(Math.abs(Math.atan2(b.vy, b.vx) - c) / DEG - objAngle)).toBeLessThan(0.5);
  });

  const POOL: BallBallParams = { R: 0.028575, restitution: 0.95, frictionA: 9.951e-3, frictionB: 0.108, frictionC: 1.088 };

  /** Throw of a stun shot: the object ball's direction off the line of centres, degrees. */
  function stunThrow(speed: number, cutDeg: number, side = 0): number {
    const c = cutDeg * DEG;
    const cue = at(0, 0, speed * Math.cos(c), speed * Math.sin(c), 0, 0, (-5 * speed * side) / (2 * POOL.R));
    const obj = at(2 * POOL.R, 0);
    collideBalls(cue, obj, POOL);
    return Math.atan2(obj.vy, obj.vx) / DEG;
  }

  it('throws a cut object ball by a few degrees, most at slow speed (Alciatore, A-14)', () => {
    // Alciatore's measurements and model: stun throw peaks around 4-6° near a half-ball hit and
    // falls with speed.
    const slow = stunThrow(0.45, 30);
    const fast = stunThrow(3.5, 30);
    expect(slow).toBeGreaterThan(3);
    expect(slow).toBeLessThan(7);
    expect(fast).toBeGreaterThan(0.5);
    expect(fast).toBeLessThan(slow);
    // Throw pushes the object ball along the cue ball's direction: positive for a positive cut.
    expect(stunThrow(1, 15)).toBeGreaterThan(0);
    expect(stunThrow(1, -15)).toBeCloseTo(-stunThrow(1, 15), 12);
  });

  it('cancels throw with the matching english (gearing outside english)', () => {
    // Right english on a cut to the left (positive cut) reduces the contact slip.
    expect(Math.abs(stunThrow(1, 30, -0.2))).toBeLessThan(Math.abs(stunThrow(1, 30)));
  });

  it('head-on stun: the cue ball keeps (1 - e)/2 of its speed, the object ball takes (1 + e)/2', () => {
    const cue = at(0, 0, 2, 0);
    const obj = at(2 * POOL.R, 0);
    collideBalls(cue, obj, POOL);
    expect(cue.vx).toBeCloseTo(0.05, 12);
    expect(obj.vx).toBeCloseTo(1.95, 12);
    expect(cue.vy).toBe(0);
    expect(obj.vy).toBe(0);
  });

  it('never adds energy and keeps momentum (property)', () => {
    const spin = fc.double({ min: -200, max: 200, noNaN: true });
    fc.assert(
      fc.property(fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }), fc.double({ min: -4, max: 4, noNaN: true }), fc.double({ min: -4, max: 4, noNaN: true }), spin, spin, spin, spin, spin, spin, (phi, vx, vy, w1, w2, w3, w4, w5, w6) => {
        const a = at(0, 0, vx, vy, w1, w2, w3);
        const b = at(2 * POOL.R * Math.cos(phi), 2 * POOL.R * Math.sin(phi), 0.3 * vy, -0.2 * vx, w4, w5, w6);
        const e0 = specificEnergy(a, POOL.R) + specificEnergy(b, POOL.R);
        const px = a.vx + b.vx;
        const py = a.vy + b.vy;
        collideBalls(a, b, POOL);
        expect(specificEnergy(a, POOL.R) + specificEnergy(b, POOL.R)).toBeLessThanOrEqual(e0 * (1 + 1e-12) + 1e-15);
        expect(a.vx + b.vx).toBeCloseTo(px, 10);
        expect(a.vy + b.vy).toBeCloseTo(py, 10);
      }),
      { numRuns: 3000 },
    );
  });
});
