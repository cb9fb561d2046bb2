// The fit of the simulation to tracked shots (fidelity/), on an excerpt of the data.
import fc from 'fast-check';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { simulate, type Scene, type Shot } from '../../shared/physics/index.ts';
import {
  DATA_SCALE, firstContactTime, fitShot, fitStrike, nelderMead, openingError, readShots, residuals, rmsError, rollingDeceleration, sceneOf,
  seedStrike, t0Range, TABLE, toShot,
} from '../../fidelity/index.ts';

const EXCERPT = join(import.meta.dirname, '..', 'fixtures', 'three-cushion-excerpt.json');
const shots = readShots(EXCERPT);

describe('the tracked shots', () => {
  it('are read at the match table\'s scale, each with its cue ball: the one whose second sample comes first', () => {
    expect(shots.map((s) => s.id)).toEqual([4, 11, 24]);
    for (const s of shots) {
      const ids = Object.keys(s.balls).sort();
      expect(ids).toEqual(['1', '2', '3']);
      for (const id of ids) expect(s.balls[s.cue]!.t[1]!).toBeLessThanOrEqual(s.balls[id]!.t[1] ?? Infinity);
      for (const b of Object.values(s.balls)) {
        for (let i = 0; i < b.t.length; i++) {
          expect(Math.abs(b.x[i]!)).toBeLessThan(TABLE.length / 2);
          expect(Math.abs(b.y[i]!)).toBeLessThan(TABLE.width / 2);
        }
      }
    }
    const raw = toShot({ id: 0, balls: { 1: { t: [0, 0.02], x: [DATA_SCALE, 0], y: [0, 0] }, 2: { t: [0, 1], x: [0.5, 0.5], y: [0, 0] }, 3: { t: [0, 1], x: [-0.5, -0.5], y: [0, 0] } } });
    expect(raw.balls['1']!.x[0]).toBeCloseTo(1, 12);
    expect(raw.cue).toBe('1');
  });

  it('say clearly when the file is missing', () => {
    expect(() => readShots('/nonexistent/trajectories.json')).toThrow(/cannot read the tracked shots at \/nonexistent/);
  });

  it('give scenes within 1 cm of the data\'s first positions that the simulation accepts', () => {
    for (const s of shots) {
      const scene = sceneOf(s);
      expect(() => simulate(scene, { ball: 'white', heading: 0, speed: 0.1, side: 0, top: 0 })).not.toThrow();
      const [lo, hi] = t0Range(s);
      const cue = s.balls[s.cue]!;
      expect(lo).toBeGreaterThanOrEqual(cue.t[0]!);
      expect(hi).toBe(cue.t[1]);
      expect(hi - lo).toBeLessThanOrEqual(0.1 + 1e-12);
      for (const b of scene.balls) {
        const id = Object.keys(s.balls).sort()[scene.balls.indexOf(b)]!;
        expect(Math.hypot(b.x - s.balls[id]!.x[0]!, b.y - s.balls[id]!.y[0]!)).toBeLessThan(0.01);
      }
    }
  });
});

describe('the fits', () => {
  it('a shot\'s strike: far closer to the tracked paths than the first guess, its time within the window', () => {
    for (const s of shots.slice(0, 2)) {
      const seed = seedStrike(s);
      const seedError = rmsError(s, sceneOf(s), seed, TABLE);
      const fit = fitShot(s, TABLE);
      expect(fit.rms).toBeLessThan(seedError / 2);
      expect(fit.rms).toBeCloseTo(rmsError(s, sceneOf(s), fit.strike, TABLE), 12);
      const [lo, hi] = t0Range(s);
      expect(fit.strike.t0).toBeGreaterThanOrEqual(lo);
      expect(fit.strike.t0).toBeLessThanOrEqual(hi);
      expect(Math.hypot(fit.strike.side, fit.strike.top)).toBeLessThanOrEqual(0.5);
    }
  }, 60_000);

  it("the cue ball's opening run: ends before an object ball moves, and its own fit brings the cue ball closer", () => {
    for (const s of shots) {
      const until = firstContactTime(s);
      expect(until).toBeGreaterThan(t0Range(s)[1]);
      for (const [id, b] of Object.entries(s.balls)) if (id !== s.cue && b.t.length > 2) expect(until).toBeLessThan(b.t[1]!);
      const seed = seedStrike(s);
      const fit = fitStrike(s, TABLE, seed, 100, until);
      // (Shot 11's cue ball goes round three cushions first: 3.6 s, 47 cm off at the seed.)
      expect(fit.rms).toBeLessThan(openingError(s, sceneOf(s), seed, TABLE, until) / 5);
      expect(fit.rms).toBeCloseTo(openingError(s, sceneOf(s), fit.strike, TABLE, until), 12);
    }
  });

  it('Nelder-Mead finds the minimum of a shifted quadratic bowl from anywhere nearby', () => {
    fc.assert(
      fc.property(fc.array(fc.double({ min: -3, max: 3, noNaN: true }), { minLength: 2, maxLength: 5 }), (centre) => {
        const f = (x: number[]): number => x.reduce((a, v, i) => a + (i + 1) * (v - centre[i]!) ** 2, 0);
        const m = nelderMead(f, centre.map(() => 0), centre.map(() => 0.5), 4000, 1e-14);
        m.x.forEach((v, i) => expect(Math.abs(v - centre[i]!)).toBeLessThan(1e-3));
      }),
      { numRuns: 50, seed: 30 },
    );
  });

  it('reads the cloth\'s rolling deceleration off straight runs', () => {
    // One ball rolling straight from 1.2 m/s at 0.05 m/s² for 6 s after a second at rest.
    const t: number[] = [];
    const x: number[] = [];
    for (let i = 0; i <= 350; i++) {
      const ti = i * 0.02;
      const s = ti < 1 ? 0 : 1.2 * (ti - 1) - 0.025 * (ti - 1) ** 2;
      t.push(ti);
      x.push((-1 + s * 0.3) * DATA_SCALE);
    }
    const ball = { t, x, y: t.map(() => 0) };
    const rest = { t: [0, 7], x: [0.5, 0.5], y: [0.5, 0.5] };
    const shot = toShot({ id: 1, balls: { 1: ball, 2: rest, 3: { ...rest, y: [-0.5, -0.5] } } });
    expect(rollingDeceleration([shot])).toBeCloseTo(0.05 * 0.3, 3);
  });
});

describe('docs/fidelity.json', () => {
  const doc = JSON.parse(readFileSync(join(import.meta.dirname, '..', '..', 'docs', 'fidelity.json'), 'utf8')) as {
    test: number[];
    shots: { id: number; t0: number; balls: Record<string, string>; scene: Scene; shot: Shot; rms: number }[];
  };

  it('holds every shot, the odd ids held out, each ball mapped', () => {
    expect(doc.shots.length).toBe(182);
    expect(doc.test).toEqual(doc.shots.map((s) => s.id).filter((id) => id % 2 === 1));
    for (const s of doc.shots) {
      expect(Object.keys(s.balls).sort()).toEqual(['1', '2', '3']);
      expect(new Set(Object.values(s.balls)).size).toBe(3);
      expect(s.scene.table).toBe('carom-match');
    }
  });

  it('on the excerpt\'s shots, reproduces its recorded errors with the shipped constants and no option', () => {
    for (const shot of shots) {
      const rec = doc.shots.find((s) => s.id === shot.id)!;
      const [lo, hi] = t0Range(shot);
      expect(rec.t0).toBeGreaterThanOrEqual(lo);
      expect(rec.t0).toBeLessThanOrEqual(hi);
      for (const [dataId, simId] of Object.entries(rec.balls)) {
        const b = rec.scene.balls.find((x) => x.id === simId)!;
        expect(Math.hypot(b.x - shot.balls[dataId]!.x[0]!, b.y - shot.balls[dataId]!.y[0]!)).toBeLessThan(0.01);
      }
      const out = simulate(rec.scene, rec.shot);
      const r = residuals(shot, out, rec.t0, TABLE);
      expect(Math.sqrt(r.reduce((a, x) => a + x.d2, 0) / r.length)).toBeCloseTo(rec.rms, 9);
    }
  });
});
