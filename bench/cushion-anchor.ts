// The yardstick: the anchors' scheme for the Mathavan 2010 cushion impact, as engines use it
// today: explicit Euler in the impulse
// with 100 steps of ΔP = max(M vy0 / 100, 0.001 N s), slip directions through atan2 and their
// cosines and sines through Math.cos / Math.sin, the work by the trapezoid rule; compression
// until vy <= 0, restitution until the work done since reaches e_e² W_c. Written for this
// benchmark; it lives in bench/ because shared/ may not use trigonometry.
import type { CushionParams, CushionState } from '../shared/physics/index.ts';

export const ANCHOR_STEPS = 100;
export const ANCHOR_FLOOR = 0.001;

export function anchorRebound(state: CushionState, p: CushionParams): CushionState {
  let { vx, vy, wx, wy, wz } = state;
  if (!(vy > 0)) return { vx, vy, wx, wy, wz };
  const { M, R, ee, muS, muW } = p;
  const s = (p.h - R) / R;
  const c = Math.sqrt(1 - s * s);
  const dP = Math.max((M * vy) / ANCHOR_STEPS, ANCHOR_FLOOR);
  const k = 5 / (2 * M * R);
  let W = 0;
  let Wc = 0;
  let compressing = true;
  let zPrev = vy * c;
  for (let n = 0; n < 1_000_000; n++) {
    const phi = Math.atan2(-vy * s + wx * R, vx + wy * R * s - wz * R * c);
    const phiC = Math.atan2(vy + wx * R, vx - wy * R);
    const cp = Math.cos(phi);
    const sp = Math.sin(phi);
    const cc = Math.cos(phiC);
    const sc = Math.sin(phiC);
    const A = s + muW * sp * c;
    vx -= ((muW * cp + muS * cc * A) * dP) / M;
    vy -= ((c - muW * s * sp + muS * sc * A) * dP) / M;
    wx -= k * (muW * sp + muS * sc * A) * dP;
    wy -= k * (muW * cp * s - muS * cc * A) * dP;
    wz += k * muW * cp * c * dP;
    const z = vy * c;
    W += 0.5 * dP * (z + zPrev);
    zPrev = z;
    if (compressing) {
      if (vy <= 0) {
        compressing = false;
        Wc = W;
      }
    } else if (Wc - W >= ee * ee * Wc) {
      return { vx, vy, wx, wy, wz };
    }
  }
  throw new Error('anchor: no end');
}
