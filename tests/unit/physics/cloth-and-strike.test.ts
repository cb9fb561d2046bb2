import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { BallState } from '../../../shared/physics/ball-state.ts';
import { emptySample, sampleAt, specificEnergy, startSegment, type ClothParams } from '../../../shared/physics/cloth-motion.ts';
import { MiscueError, strikeBall } from '../../../shared/physics/strike.ts';

const P: ClothParams = { R: 0.028575, g: 9.81, muSlide: 0.2, muRoll: 0.01, spinDecel: 10 };

function ball(): BallState {
  return { id: 'b', index: 0, motion: 'rest', t0: 0, x: 0, y: 0, vx: 0, vy: 0, wx: 0, wy: 0, wz: 0, ax: 0, ay: 0, tEnd: Infinity, version: 0, pocket: undefined };
}

function struck(heading: number, speed: number, side: number, top: number): BallState {
  const b = ball();
  startSegment(b, 0, strikeBall(heading, speed, side, top, P.R, { x: 0, y: 0, vx: 0, vy: 0, wx: 0, wy: 0, wz: 0 }), P);
  return b;
}

describe('the cue strike', () => {
  it('gives natural roll at a top offset of 0.4 R', () => {
    const b = struck(0.7, 2, 0, 0.4);
    expect(b.motion).toBe('rolling');
    expect(b.vx).toBeCloseTo(2 * Math.cos(0.7), 12);
    expect(b.vy).toBeCloseTo(2 * Math.sin(0.7), 12);
  });

  it('spins counter-clockwise seen from above with right english, and slides with a centre hit', () => {
    const b = struck(0, 2, 0.3, 0);
    expect(b.wz).toBeCloseTo((5 * 2 * 0.3) / (2 * P.R), 10);
    expect(struck(0, 2, -0.3, 0).wz).toBeCloseTo((-5 * 2 * 0.3) / (2 * P.R), 10);
    expect(b.motion).toBe('sliding');
  });

  it('rejects tip offsets beyond half the radius as a miscue', () => {
    expect(() => strikeBall(0, 2, 0.4, 0.4, P.R, emptySample())).toThrow(MiscueError);
    expect(() => strikeBall(0, 2, 0, -0.51, P.R, emptySample())).toThrow(/miscue: tip offset 0.510 R/);
  });
});

describe('motion on the cloth (Han 2005)', () => {
  it('slides for 2|u0| / (7 μs g), then rolls with v0 - (2/7) u0', () => {
    const b = struck(0, 3, 0, -0.3); // draw: slip u0 = v0 (1 + 5·0.3/2)
    const u0 = 3 * (1 + 2.5 * 0.3);
    expect(b.motion).toBe('sliding');
    expect(b.tEnd).toBeCloseTo((2 * u0) / (7 * P.muSlide * P.g), 12);
    const s = sampleAt(b, b.tEnd, P, emptySample());
    expect(s.vx).toBeCloseTo(3 - (2 / 7) * u0, 10);
    // At the end of sliding the contact point no longer slips.
    expect(s.vx - P.R * s.wy).toBeCloseTo(0, 10);
    startSegment(b, b.tEnd, s, P);
    expect(b.motion).toBe('rolling');
  });

  it('rolls for |v| / (μr g) and then spins out the remaining side', () => {
    const b = struck(0, 1, 0.2, 0.4); // natural roll with side: rolling from the start
    expect(b.motion).toBe('rolling');
    expect(b.tEnd - b.t0).toBeCloseTo(1 / (P.muRoll * P.g), 10);
    const s2 = sampleAt(b, b.tEnd - b.t0, P, emptySample());
    expect(Math.hypot(s2.vx, s2.vy)).toBeLessThan(1e-12);
    expect(s2.x).toBeCloseTo(1 / (2 * P.muRoll * P.g), 10); // v²/(2a)
    startSegment(b, b.tEnd, s2, P);
    // 10.2 s of spin decay at 10 rad/s² has long used up 5·0.2/(2R) = 17.5 rad/s of side.
    expect(b.motion).toBe('rest');
    // A ball stopped dead with side (a stun shot straight on) spins in place, then rests.
    const spun = ball();
    startSegment(spun, 1, { x: 0, y: 0, vx: 0, vy: 0, wx: 0, wy: 0, wz: -12 }, P);
    expect(spun.motion).toBe('spinning');
    expect(spun.tEnd).toBeCloseTo(1 + 12 / P.spinDecel, 12);
    expect(sampleAt(spun, 0.6, P, emptySample()).wz).toBeCloseTo(-6, 12);
  });

  it('never gains energy along a segment (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -3.2, max: 3.2, noNaN: true }),
        fc.double({ min: 0.01, max: 10, noNaN: true }),
        fc.double({ min: -0.35, max: 0.35, noNaN: true }),
        fc.double({ min: -0.35, max: 0.35, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (h, v, side, top, frac) => {
          const b = struck(h, v, side, top);
          const e0 = specificEnergy(sampleAt(b, 0, P, emptySample()), P.R);
          const e1 = specificEnergy(sampleAt(b, frac * (b.tEnd - b.t0), P, emptySample()), P.R);
          expect(e1).toBeLessThanOrEqual(e0 * (1 + 1e-12));
        },
      ),
      { numRuns: 2000 },
    );
  });
});
