// What happens when two equal balls meet: an instantaneous impulse with restitution along the line
// of centres and friction at the contact, which throws the object ball off that line.
//
// Normal: per unit mass J_n = (1 + e)/2 · v_rel·n (equal masses).
// Friction (Alciatore, technical proofs ): the contact point slips with the relative
// velocity u of the two surfaces there (including the vertical slip that follow or draw gives);
// the friction impulse opposes u with magnitude μ(|u|) J_n, μ(v) = a + b e^(-c v), capped where the
// slip would stop: each ball adds 1/m + R²/I = 7/(2m) to the tangential inverse mass, so the cap is
// |u| / 7 per unit mass. Its horizontal part moves the balls; the vertical part is taken by the
// cloth and only turns them. Both balls' spins change alike: Δω = (5/2R) n × J for each.
import type { BallSample } from './ball-state.ts';
import { detExp } from './det-math.ts';

export interface BallBallParams {
  readonly R: number;
  readonly restitution: number;
  readonly frictionA: number;
  readonly frictionB: number;
  readonly frictionC: number;
}

export function ballFriction(p: BallBallParams, slip: number): number {
  return p.frictionB === 0 ? p.frictionA : p.frictionA + p.frictionB * detExp(-p.frictionC * slip);
}

/**
 * Resolves the impact of a on b in place. Returns the normal impulse per unit mass (0 when the
 * balls do not approach along their line of centres).
 */
export function collideBalls(a: BallSample, b: BallSample, p: BallBallParams): number {
  let nx = b.x - a.x;
  let ny = b.y - a.y;
  const d = Math.sqrt(nx * nx + ny * ny);
  nx /= d;
  ny /= d;
  const approach = (a.vx - b.vx) * nx + (a.vy - b.vy) * ny;
  if (!(approach > 0)) return 0;
  const R = p.R;
  // Relative velocity of the surfaces at the contact (a's minus b's): v_a + ω_a × Rn - v_b - ω_b × (-Rn).
  const ux = a.vx - b.vx - R * (a.wz + b.wz) * ny;
  const uy = a.vy - b.vy + R * (a.wz + b.wz) * nx;
  const uz = R * ((a.wx + b.wx) * ny - (a.wy + b.wy) * nx);
  // Its part across the line of centres.
  const un = ux * nx + uy * ny;
  const tx = ux - un * nx;
  const ty = uy - un * ny;
  const tz = uz;
  const slip = Math.sqrt(tx * tx + ty * ty + tz * tz);

  const jn = 0.5 * (1 + p.restitution) * approach;
  a.vx -= jn * nx;
  a.vy -= jn * ny;
  b.vx += jn * nx;
  b.vy += jn * ny;
  if (slip === 0) return jn;

  const jt = Math.min(ballFriction(p, slip) * jn, slip / 7);
  // Friction impulse on a, per unit mass: J = -jt û; b receives -J.
  const jx = (-jt * tx) / slip;
  const jy = (-jt * ty) / slip;
  const jz = (-jt * tz) / slip;
  a.vx += jx;
  a.vy += jy;
  b.vx -= jx;
  b.vy -= jy;
  // Δω = (5 / 2R) n × J, the same for both balls (b's contact is at -Rn and its impulse is -J).
  const k = 5 / (2 * R);
  const dwx = k * (ny * jz);
  const dwy = k * (-nx * jz);
  const dwz = k * (nx * jy - ny * jx);
  a.wx += dwx;
  a.wy += dwy;
  a.wz += dwz;
  b.wx += dwx;
  b.wy += dwy;
  b.wz += dwz;
  return jn;
}
