// How each ball is turned: a unit quaternion per ball (body frame to world frame), advanced by the
// ball's angular velocity from sampleOutcome. World axes as in shared/physics: x along the table,
// y across, z up, right-handed; ω in rad/s, so a ball rolling along +x at v has ω = (0, v/R, 0).
// Pure: no DOM, unit-tested.

/** [w, x, y, z], unit length. */
export type Quat = readonly [number, number, number, number];
export type Vec3 = readonly [number, number, number];

export const IDENTITY: Quat = [1, 0, 0, 0];

/** a ⊗ b: b's rotation, then a's. */
export function multiply(a: Quat, b: Quat): Quat {
  const [aw, ax, ay, az] = a;
  const [bw, bx, by, bz] = b;
  return [
    aw * bw - ax * bx - ay * by - az * bz,
    aw * bx + ax * bw + ay * bz - az * by,
    aw * by - ax * bz + ay * bw + az * bx,
    aw * bz + ax * by - ay * bx + az * bw,
  ];
}

export function normalize(q: Quat): Quat {
  const n = Math.hypot(q[0], q[1], q[2], q[3]);
  return n === 0 ? IDENTITY : [q[0] / n, q[1] / n, q[2] / n, q[3] / n];
}

/** The rotation by angle |ω|·dt about ω (right-hand rule): the exact exponential of ω·dt. */
export function fromSpin(wx: number, wy: number, wz: number, dt: number): Quat {
  const w = Math.hypot(wx, wy, wz);
  const angle = w * dt;
  if (w === 0 || angle === 0) return IDENTITY;
  const s = Math.sin(angle / 2) / w;
  return [Math.cos(angle / 2), wx * s, wy * s, wz * s];
}

/** q turned further by the world-frame angular velocity ω for dt seconds. */
export function advance(q: Quat, wx: number, wy: number, wz: number, dt: number): Quat {
  if (wx === 0 && wy === 0 && wz === 0) return q;
  return normalize(multiply(fromSpin(wx, wy, wz, dt), q));
}

/** The body-frame vector v in the world frame. */
export function rotate(q: Quat, v: Vec3): Vec3 {
  const [w, x, y, z] = q;
  const [vx, vy, vz] = v;
  // v + 2w (u × v) + 2 u × (u × v), u = (x, y, z)
  const tx = 2 * (y * vz - z * vy);
  const ty = 2 * (z * vx - x * vz);
  const tz = 2 * (x * vy - y * vx);
  return [vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz), vz + w * tz + (x * ty - y * tx)];
}

/**
 * Every ball's orientation on one page, by ball id, so that balls at rest keep theirs between
 * shots. A ball not seen before starts upright (its number facing up, its stripe across).
 */
export class Orientations {
  private readonly map = new Map<string, Quat>();

  get(id: string): Quat {
    return this.map.get(id) ?? IDENTITY;
  }

  set(id: string, q: Quat): void {
    this.map.set(id, q);
  }

  /** Turns ball `id` by ω for dt seconds. */
  spin(id: string, wx: number, wy: number, wz: number, dt: number): void {
    if (dt <= 0 || (wx === 0 && wy === 0 && wz === 0)) return;
    this.map.set(id, advance(this.get(id), wx, wy, wz, dt));
  }
}

/**
 * A mark on the ball's surface as the camera above sees it: a disc of angular radius `radius`
 * centred on the body direction `centre`, drawn as a flat disc at depth cos(radius) under its own
 * tangent frame. Returns the affine map from the mark's plane (u right, v up, in ball radii) to the
 * view (x, y in ball radii from the ball's centre) as [a, b, c, d, e, f] in canvas order
 * (x = a u + c v + e, y = b u + d v + f), and how far the mark faces the camera (`facing`: the
 * world z of its centre direction, 1 on top, below 0 past the rim).
 */
export function markFrame(q: Quat, centre: Vec3, right: Vec3, up: Vec3, radius: number): { m: [number, number, number, number, number, number]; facing: number } {
  const n = rotate(q, centre);
  const r = rotate(q, right);
  const u = rotate(q, up);
  const depth = Math.cos(radius);
  return { m: [r[0], r[1], u[0], u[1], depth * n[0], depth * n[1]], facing: n[2] };
}
