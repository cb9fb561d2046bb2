// The cue strike: a level cue hitting the ball with tip offsets gives it speed V along the heading
// and spin ω = (5V / 2R) × offset (the angular impulse r × J over I = 2MR²/5 with J = MV; Alciatore,
// "The Illustrated Principles of Pool and Billiards", 2004): the vertical offset b spins it about
// the horizontal axis across the heading (b = 0.4 is natural roll, since then ωR = V),
// the horizontal offset a about the vertical. Right english (a > 0): the tip pushes the ball's
// right side forward, so it spins counter-clockwise seen from above, ω_z > 0 with z up.
// Offsets beyond half the radius miscue.
import type { BallSample } from './ball-state.ts';
import { sinCos } from './det-math.ts';

/** Largest tip offset, as a fraction of R, that does not miscue. */
export const MISCUE_LIMIT = 0.5;

export class MiscueError extends RangeError {
  override readonly name = 'MiscueError';
}

export function strikeBall(heading: number, speed: number, side: number, top: number, R: number, out: BallSample): BallSample {
  const offset = Math.sqrt(side * side + top * top);
  if (offset > MISCUE_LIMIT) {
    throw new MiscueError(`miscue: tip offset ${offset.toFixed(3)} R is beyond ${MISCUE_LIMIT} R (side ${side}, top ${top})`);
  }
  const { cos, sin } = sinCos(heading);
  const k = (5 * speed) / (2 * R);
  out.vx = speed * cos;
  out.vy = speed * sin;
  // Rolling forward along d = (cos, sin) has ω = (-d_y, d_x) V / R.
  out.wx = -k * top * sin;
  out.wy = k * top * cos;
  // r × J with r = a R (sin, -cos) (right of the heading) and J along (cos, sin): +a R J about z.
  out.wz = k * side;
  return out;
}
