// The balls' orientation: turned by their spin about the physics' axes (x along, y across, z up).
import { describe, expect, it } from 'vitest';
import { advance, IDENTITY, markFrame, Orientations, rotate, type Quat, type Vec3 } from '../../../client/table/orientation.ts';

const close = (a: Vec3, b: Vec3, eps = 1e-9) => a.forEach((v, i) => expect(v).toBeCloseTo(b[i]!, -Math.log10(eps)));
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('ball orientation', () => {
  it('turns a marked point by |ω|·t about ω, leaving its component along ω alone', () => {
    const w: Vec3 = [3, -4, 12]; // |ω| = 13 rad/s
    const axis: Vec3 = [3 / 13, -4 / 13, 12 / 13];
    const p: Vec3 = [0.6, 0.8, 0];
    const t = 0.1;
    const q = advance(IDENTITY, w[0], w[1], w[2], t);
    const r = rotate(q, p);
    expect(dot(r, axis)).toBeCloseTo(dot(p, axis), 12);
    // The angle swept in the plane across ω, with the right-hand sense.
    const perp = (v: Vec3): Vec3 => { const k = dot(v, axis); return [v[0] - k * axis[0], v[1] - k * axis[1], v[2] - k * axis[2]]; };
    const a = perp(p);
    const b = perp(r);
    const cross: Vec3 = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const angle = Math.atan2(dot(cross, axis), dot(a, b));
    expect(angle).toBeCloseTo(13 * t, 12);
  });

  it('many small steps land where one exact step does', () => {
    let q: Quat = IDENTITY;
    for (let i = 0; i < 1000; i++) q = advance(q, 5, 2, -7, 0.001);
    close(rotate(q, [0, 0, 1]), rotate(advance(IDENTITY, 5, 2, -7, 1), [0, 0, 1]), 1e-9);
    expect(Math.hypot(...q)).toBeCloseTo(1, 12);
  });

  it('a ball rolling along +x (ω = (0, v/R, 0)) carries its top forward: a quarter turn brings it to the front', () => {
    const v = 2;
    const R = 0.028575;
    const t = (Math.PI / 2) / (v / R);
    const q = advance(IDENTITY, 0, v / R, 0, t);
    close(rotate(q, [0, 0, 1]), [1, 0, 0]);
    // And early on the top moves the way the ball goes, at v relative to the centre (rolling: 2v on the cloth).
    const early = rotate(advance(IDENTITY, 0, v / R, 0, 1e-6), [0, 0, R]);
    expect(early[0] / 1e-6).toBeCloseTo(v, 3);
  });

  it('right english (ω_z > 0) turns the ball counter-clockwise seen from above', () => {
    const q = advance(IDENTITY, 0, 0, 10, 0.05);
    const p = rotate(q, [1, 0, 0]);
    expect(p[1]).toBeGreaterThan(0);
    expect(p[2]).toBeCloseTo(0, 12);
  });

  it('keeps each ball\'s orientation by id, upright until spun', () => {
    const o = new Orientations();
    expect(o.get('9')).toEqual(IDENTITY);
    o.spin('9', 0, 40, 0, 0.01);
    const q = o.get('9');
    expect(q).not.toEqual(IDENTITY);
    o.spin('9', 0, 0, 0, 1); // at rest: unchanged
    expect(o.get('9')).toEqual(q);
    expect(o.get('3')).toEqual(IDENTITY);
  });

  it('sees a mark on top face up, and one past the rim foreshortened and turned away', () => {
    const top = markFrame(IDENTITY, [0, 0, 1], [1, 0, 0], [0, 1, 0], 0.5);
    expect(top.facing).toBe(1);
    expect(top.m.slice(0, 4)).toEqual([1, 0, 0, 1]);
    // Rolled a little over 90° about y: the mark has gone past the front rim (+x).
    const q = advance(IDENTITY, 0, 1, 0, Math.PI / 2 + 0.2);
    const f = markFrame(q, [0, 0, 1], [1, 0, 0], [0, 1, 0], 0.5);
    expect(f.facing).toBeLessThan(0);
    expect(f.m[4]).toBeGreaterThan(0.8); // near the +x rim
    expect(Math.abs(f.m[0])).toBeLessThan(0.25); // its across-the-rim axis squashed
    expect(f.m[3]).toBeCloseTo(1, 12); // the axis along the rim keeps its length
  });
});
