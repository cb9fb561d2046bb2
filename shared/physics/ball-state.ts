// The state of one ball during the simulation: a motion segment that starts at t0 and follows a
// closed form until its next event. Positions in metres, velocities in m/s, spins in rad/s.

export type Motion = 'sliding' | 'rolling' | 'spinning' | 'rest' | 'pocketed';

export interface BallState {
  readonly id: string;
  /** Index in the scene (the order of scene.balls): ties between events break by it. */
  readonly index: number;
  motion: Motion;
  /** Start of the current segment (s). */
  t0: number;
  x: number;
  y: number;
  vx: number;
  vy: number;
  wx: number;
  wy: number;
  wz: number;
  /** Constant linear acceleration of the current segment (m/s^2). */
  ax: number;
  ay: number;
  /** Time the current motion ends by itself (s, absolute); Infinity at rest or pocketed. */
  tEnd: number;
  /** Bumped at every change of segment; queued predictions carry the version they were made for. */
  version: number;
  pocket: string | undefined;
}

/** A snapshot of a ball at some time: position, velocity and spin. */
export interface BallSample {
  x: number;
  y: number;
  vx: number;
  vy: number;
  wx: number;
  wy: number;
  wz: number;
}

/** Copies position, velocity and spin from one sample (or ball) into another. */
export function copySample(from: BallSample, to: BallSample): BallSample {
  to.x = from.x;
  to.y = from.y;
  to.vx = from.vx;
  to.vy = from.vy;
  to.wx = from.wx;
  to.wy = from.wy;
  to.wz = from.wz;
  return to;
}
