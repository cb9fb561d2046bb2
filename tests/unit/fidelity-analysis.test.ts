// What the fidelity report measures on tracked and simulated balls (fidelity/analysis.ts), on
// tracks with known answers and on a simulated shot.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { simulate, tableSpec } from '../../shared/physics/index.ts';
import { cushionRebounds, openingAlongAcross, openingRun, slowRuns, trackedAs, type Strike, type Track, type TrackedShot } from '../../fidelity/index.ts';

const TABLE = tableSpec('carom-match');
const RAIL_X = TABLE.length / 2 - TABLE.ballRadius;

/** A ball at constant velocity into the +x rail between two frames, leaving with normal ratio e and tangential ratio k. */
function bounce(vin: number, tin: number, e: number, k: number): Track {
  const t: number[] = [];
  const x: number[] = [];
  const y: number[] = [];
  const tHit = 0.205;
  for (let i = 0; i <= 20; i++) {
    const ti = i * 0.02;
    const dt = ti - tHit;
    t.push(ti);
    x.push(dt <= 0 ? RAIL_X + vin * dt : RAIL_X - e * vin * dt);
    y.push(dt <= 0 ? tin * dt : k * tin * dt);
  }
  return { t, x, y };
}

describe('cushion rebounds', () => {
  it('are read off a track at the rail, whatever the speeds', () => {
    fc.assert(fc.property(
      fc.double({ min: 0.3, max: 4, noNaN: true }), fc.double({ min: -2, max: 2, noNaN: true }),
      fc.double({ min: 0.4, max: 0.95, noNaN: true }), fc.double({ min: 0.5, max: 1, noNaN: true }),
      (vin, tin, e, k) => {
        const hits = cushionRebounds(bounce(vin, tin, e, k), TABLE);
        expect(hits).toHaveLength(1);
        expect(hits[0]!.vin).toBeCloseTo(vin, 9);
        expect(hits[0]!.vout / hits[0]!.vin).toBeCloseTo(e, 9);
        expect(hits[0]!.tin).toBeCloseTo(tin, 9);
        expect(hits[0]!.tout).toBeCloseTo(k * tin, 9);
      },
    ), { numRuns: 50 });
  });

  it('are not found on a run that never reaches a rail', () => {
    const t = Array.from({ length: 30 }, (_, i) => i * 0.02);
    expect(cushionRebounds({ t, x: t.map((ti) => ti), y: t.map(() => 0) }, TABLE)).toEqual([]);
  });
});

describe('slow straight runs', () => {
  it('give back the deceleration and a slope common to the table', () => {
    const decel = 0.045;
    const slope: [number, number] = [0.002, -0.003];
    const tracks: Track[] = [];
    for (let k = 0; k < 24; k++) {
      // Integrated finely (the deceleration along the current motion), sampled every 0.02 s.
      const a = (2 * Math.PI * k) / 24;
      let [px, py, vx, vy] = [-0.2 * Math.cos(a), -0.2 * Math.sin(a), 0.4 * Math.cos(a), 0.4 * Math.sin(a)];
      const t: number[] = [];
      const x: number[] = [];
      const y: number[] = [];
      for (let i = 0; i <= 100 * 200; i++) {
        if (i % 200 === 0) {
          t.push(i / 200 * 0.02);
          x.push(px);
          y.push(py);
        }
        const h = 0.0001;
        const v = Math.hypot(vx, vy);
        const ax = -decel * vx / v + slope[0];
        const ay = -decel * vy / v + slope[1];
        px += h * vx + 0.5 * h * h * ax;
        py += h * vy + 0.5 * h * h * ay;
        vx += h * ax;
        vy += h * ay;
      }
      tracks.push({ t, x, y });
    }
    const r = slowRuns(tracks, TABLE);
    expect(r.windows).toBeGreaterThan(24);
    expect(r.decel).toBeCloseTo(decel, 4);
    expect(r.slope[0]).toBeCloseTo(slope[0], 4);
    expect(r.slope[1]).toBeCloseTo(slope[1], 4);
    // A slope bends the runs across their motion by up to its size.
    expect(r.across).toBeGreaterThan(0.001);
    expect(r.across).toBeLessThanOrEqual(Math.hypot(...slope) + 1e-4);
  });
});

describe('a simulated ball tracked as the data was', () => {
  it('is sampled at the given times from t0 on, on a millimetre grid, kept samples 2 mm apart', () => {
    const scene = { table: 'carom-match' as const, balls: [{ id: 'white', x: -0.5, y: 0 }, { id: 'yellow', x: 0.5, y: 0.3 }, { id: 'red', x: 0.5, y: -0.3 }] };
    const out = simulate(scene, { ball: 'white', heading: 0.3, speed: 2, side: 0.1, top: 0.2 });
    const times = Array.from({ length: 400 }, (_, i) => i * 0.02);
    const tr = trackedAs(out, 'white', times, 0.1, TABLE);
    expect(tr.t[0]).toBeCloseTo(0.1, 12);
    expect(tr.t.length).toBeGreaterThan(20);
    for (let i = 0; i < tr.t.length; i++) {
      expect(Math.abs(tr.x[i]! * 1000 - Math.round(tr.x[i]! * 1000))).toBeLessThan(1e-6);
      if (i > 0) expect(Math.hypot(tr.x[i]! - tr.x[i - 1]!, tr.y[i]! - tr.y[i - 1]!)).toBeGreaterThanOrEqual(0.002 - 1e-9);
    }
    // It starts where the scene put the ball.
    expect(tr.x[0]).toBeCloseTo(-0.5, 3);
  });
});

describe('the cue ball\'s opening error', () => {
  const scene = { table: 'carom-match' as const, balls: [{ id: 'white', x: -1, y: 0 }, { id: 'yellow', x: 1.2, y: 0.55 }, { id: 'red', x: 1.2, y: -0.55 }] };
  const out = simulate(scene, { ball: 'white', heading: 0, speed: 1.5, side: 0, top: 0.3 });
  const times = Array.from({ length: 40 }, (_, i) => i * 0.02);
  const exact = trackedAs(out, 'white', times, 0, TABLE);

  it('is timing when the strike time is off: along the motion, nothing across', () => {
    const r = openingAlongAcross(exact, out, 0.02, TABLE);
    // The simulated ball is 0.02 s behind: about 0.02 s of its speed along, none across.
    expect(r.along).toBeGreaterThan(0.02);
    expect(r.along).toBeLessThan(0.04);
    expect(r.across).toBeLessThan(0.001);
  });

  it('is line when the track is beside the path: across the motion', () => {
    const beside = { ...exact, y: exact.y.map((y) => y + 0.01) };
    const r = openingAlongAcross(beside, out, 0, TABLE);
    expect(r.across).toBeCloseTo(0.01, 3);
    expect(r.along).toBeLessThan(0.001);
  });
});

describe('the cue ball\'s opening run fitted alone', () => {
  // A shot tracked as the data was from a known strike between two frames: the cue ball's track
  // starts where it rests, the object balls' where they are first sampled.
  const scene = { table: 'carom-match' as const, balls: [{ id: 'white', x: -1, y: 0 }, { id: 'yellow', x: 0.5, y: 0.05 }, { id: 'red', x: 1, y: -0.4 }] };
  const strike: Strike = { heading: 0, speed: 2, side: 0.1, top: 0.2, t0: 0.01 };
  const out = simulate(scene, { ball: 'white', ...strike });
  const times = Array.from({ length: 300 }, (_, i) => i * 0.02);
  const track = (id: string): Track => trackedAs(out, id, times, strike.t0, TABLE);
  const cue = track('white');
  const shot: TrackedShot = {
    id: 1,
    cue: '1',
    balls: { 1: { t: [0, ...cue.t], x: [-1, ...cue.x], y: [0, ...cue.y] }, 2: track('yellow'), 3: track('red') },
  };

  it('matches the run, and so does the true strike', () => {
    const r = openingRun(shot, strike, TABLE)!;
    expect(r.alone).toBeLessThan(0.002);
    expect(r.whole).toBeLessThan(0.002);
    expect(r.speedRatio).toBeCloseTo(1, 2);
  });

  it('finds the speed a slower strike gives up at the first contact', () => {
    const r = openingRun(shot, { ...strike, speed: strike.speed * 0.95 }, TABLE)!;
    expect(r.alone).toBeLessThan(0.002);
    expect(r.whole).toBeGreaterThan(0.01);
    expect(r.speedRatio).toBeGreaterThan(1.03);
    expect(r.speedRatio).toBeLessThan(1.08);
  });
});
