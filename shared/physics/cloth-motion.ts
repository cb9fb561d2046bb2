// Motion on the cloth between events, in closed form (Han 2005, "Dynamics in carom and three
// cushion billiards", J. Mech. Sci. Tech. 19(4); with the corrections Kiefl published for pooltool).
//
// The contact point with the cloth sits at -R z, so its velocity (the slip) is
//   u = v + ω × (-R z) = (v_x - R ω_y, v_y + R ω_x).
// Sliding: friction μ_s m g opposes u, whose direction stays fixed, so
//   a = -μ_s g û,  dω_x/dt = (5/2R) a_y,  dω_y/dt = -(5/2R) a_x,
// hence du/dt = (7/2) a and sliding lasts t_s = 2|u0| / (7 μ_s g). The path is a parabola.
// Rolling: u = 0, v decelerates at μ_r g along v̂ for |v| / (μ_r g); ω follows v (ω_x = -v_y/R,
// ω_y = v_x/R). Spin about z decays at a constant rate α in every state (it does not move the
// ball on the cloth) and ends at |ω_z| / α; a ball whose only motion is ω_z is spinning.
import { copySample, type BallSample, type BallState, type Motion } from './ball-state.ts';

export interface ClothParams {
  /** Ball radius (m). */
  readonly R: number;
  /** Gravity (m/s^2). */
  readonly g: number;
  /** Sliding friction ball-cloth. */
  readonly muSlide: number;
  /** Rolling resistance. */
  readonly muRoll: number;
  /** Angular deceleration of spin about the vertical (rad/s^2). */
  readonly spinDecel: number;
}

/** Below these a speed counts as zero: far under what the eye, the table or the tests resolve. */
export const REST_SPEED = 1e-9; // m/s
export const REST_SPIN = 1e-7; // rad/s

/** The constant acceleration of the ball's current motion. */
export function acceleration(b: BallState, p: ClothParams): { ax: number; ay: number } {
  switch (b.motion) {
    case 'sliding': {
      const ux = b.vx - p.R * b.wy;
      const uy = b.vy + p.R * b.wx;
      const u = Math.sqrt(ux * ux + uy * uy);
      if (u === 0) return { ax: 0, ay: 0 };
      const k = (-p.muSlide * p.g) / u;
      return { ax: k * ux, ay: k * uy };
    }
    case 'rolling': {
      const v = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
      if (v === 0) return { ax: 0, ay: 0 };
      const k = (-p.muRoll * p.g) / v;
      return { ax: k * b.vx, ay: k * b.vy };
    }
    default:
      return { ax: 0, ay: 0 };
  }
}

/** Spin about z after dt: linear decay to zero. */
export function spinZAfter(wz: number, dt: number, p: ClothParams): number {
  const left = Math.abs(wz) - p.spinDecel * dt;
  if (left <= 0) return 0;
  return wz > 0 ? left : -left;
}

/**
 * A ball left by an event with both its speed and its slip below this (m/s) stops there: rolling,
 * it would go at most v²/(2 μ_r g) = 5 µm further. Without it, clusters of touching balls nudged
 * at a crawl trade thousands of ever smaller impacts (inelastic collapse) for nothing visible.
 */
export const SETTLE_SPEED = 1e-3;

/** The motion a ball is in, judged from its velocity and spin. */
export function classify(s: BallSample, p: ClothParams): Motion {
  const ux = s.vx - p.R * s.wy;
  const uy = s.vy + p.R * s.wx;
  const slip = Math.sqrt(ux * ux + uy * uy);
  const speed = Math.sqrt(s.vx * s.vx + s.vy * s.vy);
  if (slip < SETTLE_SPEED && speed < SETTLE_SPEED) return Math.abs(s.wz) > REST_SPIN ? 'spinning' : 'rest';
  if (slip > REST_SPEED) return 'sliding';
  if (speed > REST_SPEED) return 'rolling';
  if (Math.abs(s.wz) > REST_SPIN) return 'spinning';
  return 'rest';
}

/** How long the current motion lasts from t0 (Infinity at rest). */
export function motionDuration(b: BallState, p: ClothParams): number {
  switch (b.motion) {
    case 'sliding': {
      const ux = b.vx - p.R * b.wy;
      const uy = b.vy + p.R * b.wx;
      return (2 * Math.sqrt(ux * ux + uy * uy)) / (7 * p.muSlide * p.g);
    }
    case 'rolling':
      return Math.sqrt(b.vx * b.vx + b.vy * b.vy) / (p.muRoll * p.g);
    case 'spinning':
      return Math.abs(b.wz) / p.spinDecel;
    default:
      return Infinity;
  }
}

/** What sampling a segment reads: its motion, its start state and its constant acceleration. */
export type SegmentState = Pick<BallState, 'motion' | 'x' | 'y' | 'vx' | 'vy' | 'wx' | 'wy' | 'wz' | 'ax' | 'ay'>;

/** The ball's state dt after t0 within its current segment (dt <= tEnd - t0). */
export function sampleAt(b: SegmentState, dt: number, p: ClothParams, out: BallSample): BallSample {
  const ax = b.ax;
  const ay = b.ay;
  out.x = b.x + (b.vx + 0.5 * ax * dt) * dt;
  out.y = b.y + (b.vy + 0.5 * ay * dt) * dt;
  out.vx = b.vx + ax * dt;
  out.vy = b.vy + ay * dt;
  out.wz = spinZAfter(b.wz, dt, p);
  if (b.motion === 'sliding') {
    const k = 5 / (2 * p.R);
    out.wx = b.wx + k * ay * dt;
    out.wy = b.wy - k * ax * dt;
  } else if (b.motion === 'rolling') {
    out.wx = -out.vy / p.R;
    out.wy = out.vx / p.R;
  } else {
    out.wx = 0;
    out.wy = 0;
    out.vx = 0;
    out.vy = 0;
  }
  return out;
}

export function emptySample(): BallSample {
  return { x: 0, y: 0, vx: 0, vy: 0, wx: 0, wy: 0, wz: 0 };
}

/**
 * Starts a new segment at time t from the sample s: the motion is classified afresh and the time
 * it ends is computed. Values too small to matter are set to exact zeros so that rest is rest.
 */
export function startSegment(b: BallState, t: number, s: BallSample, p: ClothParams): void {
  b.motion = settle(s, p);
  b.t0 = t;
  copySample(s, b);
  const a = acceleration(b, p);
  b.ax = a.ax;
  b.ay = a.ay;
  b.tEnd = t + motionDuration(b, p);
  b.version++;
}

/**
 * Classifies a sample's motion and makes the sample exactly that: a rolling ball's spin follows
 * its velocity, a spinning or resting ball has no velocity and no horizontal spin, spin too small
 * to matter is zero. Returns the motion.
 */
export function settle(s: BallSample, p: ClothParams): Motion {
  const motion = classify(s, p);
  if (!(Math.abs(s.wz) > REST_SPIN)) s.wz = 0;
  if (motion === 'rolling') {
    s.wx = -s.vy / p.R;
    s.wy = s.vx / p.R;
  } else if (motion === 'spinning' || motion === 'rest') {
    s.vx = 0;
    s.vy = 0;
    s.wx = 0;
    s.wy = 0;
  }
  return motion;
}

/** The cloth's acceleration of a settled sample along (nx, ny). */
export function accelerationAlong(s: BallSample, motion: Motion, nx: number, ny: number, p: ClothParams): number {
  if (motion === 'sliding') {
    const ux = s.vx - p.R * s.wy;
    const uy = s.vy + p.R * s.wx;
    const u = Math.sqrt(ux * ux + uy * uy);
    return u === 0 ? 0 : (-p.muSlide * p.g * (ux * nx + uy * ny)) / u;
  }
  if (motion === 'rolling') {
    const v = Math.sqrt(s.vx * s.vx + s.vy * s.vy);
    return v === 0 ? 0 : (-p.muRoll * p.g * (s.vx * nx + s.vy * ny)) / v;
  }
  return 0;
}

/** Kinetic plus rotational energy per unit mass (I = 2/5 m R^2): v^2/2 + R^2 ω^2 / 5. */
export function specificEnergy(s: BallSample, R: number): number {
  return 0.5 * (s.vx * s.vx + s.vy * s.vy) + 0.2 * R * R * (s.wx * s.wx + s.wy * s.wy + s.wz * s.wz);
}
