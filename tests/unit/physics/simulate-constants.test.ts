import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  cushionParamsOf, energyAt, sampleOutcome, simulate, SimulationInputError, tableSpec,
  type CushionParams, type Outcome, type SimOptions,
} from '../../../shared/physics/index.ts';
import { simulateOn } from '../../../shared/physics/diagnostics.ts';
import type { TableSpec } from '../../../shared/physics/tables.ts';
import { corpusCases, type CorpusCase } from '../../../shared/scenes/index.ts';

const KEYS = ['M', 'R', 'h', 'ee', 'muS', 'muW'] as const;
const CAROM = corpusCases('carom');
/** A few corpus shots on every table, all of them with cushion impacts. */
const SAMPLE: readonly CorpusCase[] = [
  CAROM[0]!, CAROM[CAROM.length - 1]!, corpusCases('bank')[0]!, corpusCases('nineball-break')[0]!,
  corpusCases('snooker-break')[0]!, corpusCases('pocket')[0]!,
];
const own = (c: CorpusCase): CushionParams => cushionParamsOf(tableSpec(c.scene.table));
const run = (c: CorpusCase, options?: SimOptions): Outcome => simulate(c.scene, c.shot, options);

/** A carom shot that stays far from every cushion: a bad option must throw without any impact. */
const QUIET: CorpusCase = { name: 'quiet', tags: [], scene: { table: 'carom-match', balls: [{ id: 'w', x: 0, y: 0 }] }, shot: { ball: 'w', heading: 0, speed: 0.05, side: 0, top: 0 } };
const R = tableSpec('carom-match').ballRadius;
const H = tableSpec('carom-match').cushion.height;

function rejects(cushion: unknown, message: RegExp): void {
  const options = { cushion } as SimOptions;
  const before = structuredClone(options);
  expect(() => simulate(QUIET.scene, QUIET.shot, options)).toThrow(SimulationInputError);
  expect(() => simulate(QUIET.scene, QUIET.shot, options)).toThrow(message);
  expect(options).toEqual(before); // nothing changed
}

describe('simulate with the cushion constants of the call (options.cushion)', () => {
  it('the sample hits cushions', () => {
    for (const c of SAMPLE) expect(run(c).events.some((e) => e.kind === 'cushion')).toBe(true);
    expect(run(QUIET).events.some((e) => e.kind === 'cushion')).toBe(false);
  });

  it('gives the same outcome, bit for bit, without the option, with {} and with cushion: {} or undefined', () => {
    for (const c of SAMPLE) {
      const base = run(c);
      for (const options of [{}, { cushion: {} }, { cushion: undefined }, { cushion: { ee: undefined } }] as SimOptions[]) {
        const o = run(c, options);
        expect(o.hash, c.name).toBe(base.hash);
        expect(o.events, c.name).toEqual(base.events);
      }
    }
  });

  it("gives the same outcome with the table's own constants passed explicitly", () => {
    for (const c of SAMPLE) {
      const base = run(c);
      const o = run(c, { cushion: own(c) });
      expect(o.hash, c.name).toBe(base.hash);
      expect(o.events, c.name).toEqual(base.events);
    }
  });

  it('with a lower restitution, a ball that meets its first cushion at 45° or more leaves it slower, and the table holds less energy', () => {
    // (Nearer the grazing, a lower restitution also means less friction at the cushion, and the
    // ball can leave faster.)
    let checked = 0;
    for (const c of CAROM) {
      expect(own(c).ee).toBeGreaterThan(0.5);
      const base = run(c);
      const soft = run(c, { cushion: { ee: 0.5 } });
      expect(soft.hash, c.name).not.toBe(base.hash);
      // Everything up to the first cushion impact is the same; that impact then differs.
      const i = base.events.findIndex((e) => e.kind === 'cushion');
      expect(soft.events.slice(0, i + 1), c.name).toEqual(base.events.slice(0, i + 1));
      const { t, balls: [id], speed } = base.events[i]!;
      const speedAt = (o: Outcome, at: number): number => {
        const b = sampleOutcome(o, at).find((x) => x.id === id)!;
        return Math.hypot(b.vx, b.vy);
      };
      if (!(speed! >= Math.SQRT1_2 * speedAt(base, t - 1e-9))) continue;
      checked++;
      expect(speedAt(soft, t), c.name).toBeLessThan(speedAt(base, t));
      expect(energyAt(soft, t), c.name).toBeLessThan(energyAt(base, t));
    }
    expect(checked).toBeGreaterThanOrEqual(2);
  });

  it('accepts the bounds: ee 0 and 1, no friction', () => {
    for (const cushion of [{ ee: 0 }, { ee: 1 }, { muS: 0, muW: 0 }, { ee: 1, muS: 0, muW: 0 }]) {
      const o = run(CAROM[0]!, { cushion });
      for (const b of o.balls) expect(Number.isFinite(b.x) && Number.isFinite(b.y)).toBe(true);
    }
  });

  it.each([
    ['a number', 0.5, /options\.cushion must be an object of cushion constants \{ M, R, h, ee, muS, muW \}, got 0\.5/],
    ['null', null, /options\.cushion must be an object/],
    ['a string', 'soft', /options\.cushion must be an object/],
    ['an array', [0.5], /options\.cushion must be an object/],
    ['an unknown key', { e: 0.5 }, /options\.cushion\.e is not a cushion constant: use M, R, h, ee, muS, muW/],
    ['ee NaN', { ee: Number.NaN }, /options\.cushion\.ee must be a finite number, got NaN/],
    ['M Infinity', { M: Infinity }, /options\.cushion\.M must be a finite number, got Infinity/],
    ['muW -Infinity', { muW: -Infinity }, /options\.cushion\.muW must be a finite number, got -Infinity/],
    ['R a string', { R: '0.03' }, /options\.cushion\.R must be a finite number, got 0\.03/],
    ['h null', { h: null }, /options\.cushion\.h must be a finite number, got null/],
    ['M 0', { M: 0 }, /options\.cushion\.M must be > 0 kg, got 0/],
    ['M negative', { M: -0.2 }, /options\.cushion\.M must be > 0 kg, got -0\.2/],
    ['R 0', { R: 0 }, /options\.cushion\.R must be > 0 m, got 0/],
    ['R negative', { R: -R }, /options\.cushion\.R must be > 0 m/],
    ['h = R', { h: R }, /options\.cushion\.h must be in \(R, 2R\) = \(0\.03075, 0\.0615\) m, got 0\.03075$/],
    ['h = 2R', { h: 2 * R }, /options\.cushion\.h must be in \(R, 2R\)/],
    ['h below the ball', { h: 0.01 }, /options\.cushion\.h must be in \(R, 2R\)/],
    // h is checked against the merged R: the table's h no longer fits a smaller ball.
    ["R that the table's h does not fit", { R: H / 2 }, new RegExp(`options\\.cushion\\.h must be in \\(R, 2R\\) = \\(${H / 2}, ${H}\\) m, got ${H} \\(the table's\\)`)],
    ['ee negative', { ee: -0.1 }, /options\.cushion\.ee must be in \[0, 1\], got -0\.1/],
    ['ee above 1', { ee: 1.01 }, /options\.cushion\.ee must be in \[0, 1\], got 1\.01/],
    ['muS negative', { muS: -0.01 }, /options\.cushion\.muS must be >= 0, got -0\.01/],
    ['muW negative', { muW: -1e-9 }, /options\.cushion\.muW must be >= 0, got -1e-9/],
  ] as const)('rejects %s with a SimulationInputError naming the field, before simulating', (_name, cushion, message) => {
    rejects(cushion, message);
  });

  it('a kernel R far from the ball\'s changes the contact angle, never adds energy: the break settles', () => {
    const c = corpusCases('hard').find((x) => x.name === 'snooker hard break beyond the rigid limit')!;
    const R0 = tableSpec(c.scene.table).ballRadius;
    for (const r of [0.1, 0.3, 3]) {
      const o = run(c, { cushion: { R: R0 * r, h: R0 * r * 1.4 } });
      // Energy on the table never grows from one event to the next.
      let last = energyAt(o, 0);
      for (const e of o.events) {
        const now = energyAt(o, e.t + 1e-9);
        expect(now).toBeLessThanOrEqual(last * (1 + 1e-9));
        last = now;
      }
    }
  });

  it('property: valid overrides never throw and end at finite positions', () => {
    const d = (min: number, max: number): fc.Arbitrary<number> => fc.double({ min, max, noNaN: true });
    const overrides = fc.record(
      // r: the kernel's R as a fraction of the ball's; hf: where h lies in (R, 2R).
      { M: d(0.01, 10), ee: d(0, 1), muS: d(0, 1), muW: d(0, 1), r: d(0.1, 10), hf: d(0.01, 0.99) },
      { requiredKeys: [] },
    );
    fc.assert(
      fc.property(fc.constantFrom(...SAMPLE), overrides, (c, { r, hf, ...rest }) => {
        const R0 = tableSpec(c.scene.table).ballRadius;
        const Rk = r === undefined ? R0 : R0 * r;
        const cushion: Partial<CushionParams> = { ...rest, ...(r === undefined ? {} : { R: Rk }), ...(hf === undefined ? {} : { h: Rk * (1 + hf) }) };
        // The table's h must fit a changed R; otherwise that is an invalid input, tested below.
        if (cushion.h === undefined && !(own(c).h > Rk && own(c).h < 2 * Rk)) return;
        const o = run(c, { cushion });
        for (const b of o.balls) expect(Number.isFinite(b.x) && Number.isFinite(b.y)).toBe(true);
      }),
      { numRuns: 400, seed: 20260303 },
    );
  });

  it('property: an invalid value of any field always throws, naming the field', () => {
    const key = fc.constantFrom(...KEYS);
    const notFinite = fc.constantFrom<unknown>(Number.NaN, Infinity, -Infinity, '0.5', null, true, {}, []);
    const below = (max: number): fc.Arbitrary<number> => fc.double({ min: -1e6, max, noNaN: true });
    const bad = fc.oneof(
      fc.record({ key, value: notFinite }),
      fc.record({ key: fc.constant('M'), value: below(0) }),
      fc.record({ key: fc.constant('R'), value: below(0) }),
      fc.record({ key: fc.constant('h'), value: fc.oneof(below(R), fc.double({ min: 2 * R, max: 1e6, noNaN: true })) }),
      fc.record({ key: fc.constant('ee'), value: fc.oneof(below(-Number.MIN_VALUE), fc.double({ min: 1 + Number.EPSILON, max: 1e6, noNaN: true })) }),
      fc.record({ key: fc.constantFrom('muS', 'muW'), value: below(-Number.MIN_VALUE) }),
      fc.record({ key: fc.string({ minLength: 1 }).filter((k) => !(KEYS as readonly string[]).includes(k)), value: fc.double() }),
    );
    // Valid values of the other fields beside the bad one.
    const others = fc.record({ M: fc.double({ min: 0.01, max: 10, noNaN: true }), ee: fc.double({ min: 0, max: 1, noNaN: true }), muS: fc.double({ min: 0, max: 1, noNaN: true }) }, { requiredKeys: [] });
    fc.assert(
      fc.property(bad, others, ({ key: k, value }, rest) => {
        const cushion = { ...rest, [k]: value };
        const escaped = k.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
        expect(() => simulate(QUIET.scene, QUIET.shot, { cushion } as SimOptions)).toThrow(SimulationInputError);
        expect(() => simulate(QUIET.scene, QUIET.shot, { cushion } as SimOptions)).toThrow(new RegExp(`^options\\.cushion\\.${escaped} `));
      }),
      { numRuns: 2000, seed: 20260304 },
    );
  });
});

describe("a table's cushion restitution falling with the normal speed (CushionSpec.restitutionSlope)", () => {
  const carom = tableSpec('carom-match');
  const withSlope = (k: number): TableSpec => ({ ...carom, cushion: { ...carom.cushion, restitutionSlope: k } });
  /** One ball driven into the long rail at an angle: its first impact's normal speed. */
  const into = (speed: number): CorpusCase => ({
    name: `into the rail at ${speed} m/s`, tags: [],
    scene: { table: 'carom-match', balls: [{ id: 'w', x: 0, y: 0 }] },
    shot: { ball: 'w', heading: 1.2, speed, side: 0.1, top: 0.2 },
  });

  it('is off by default on every table, and a slope of 0 changes nothing, bit for bit', () => {
    for (const name of ['pool-9ft', 'snooker-12ft', 'carom-match'] as const) expect(tableSpec(name).cushion.restitutionSlope).toBeUndefined();
    for (const c of SAMPLE.filter((x) => x.scene.table === 'carom-match')) {
      const o = simulateOn(withSlope(0), c.scene, c.shot);
      expect(o.hash, c.name).toBe(run(c).hash);
      expect(o.events, c.name).toEqual(run(c).events);
    }
  });

  it("gives each impact the restitution restitution - slope * v_n: the first impact as with that e_e passed for the call", () => {
    for (const speed of [0.8, 2, 4]) {
      const c = into(speed);
      const k = 0.04;
      const sloped = simulateOn(withSlope(k), c.scene, c.shot);
      const first = sloped.events.find((e) => e.kind === 'cushion')!;
      const ee = carom.cushion.restitution - k * first.speed!;
      const fixed = run(c, { cushion: { ee } });
      const after = (o: Outcome): unknown => sampleOutcome(o, first.t + 1e-3).find((b) => b.id === 'w');
      expect(after(sloped), c.name).toEqual(after(fixed));
      // And a harder impact loses more: the rebound is slower than with the constant restitution.
      const vOf = (o: Outcome): number => { const b = sampleOutcome(o, first.t + 1e-3).find((x) => x.id === 'w')!; return Math.hypot(b.vx, b.vy); };
      expect(vOf(sloped), c.name).toBeLessThan(vOf(run(c)));
    }
  });

  it('keeps e_e within [0, 1] whatever the slope', () => {
    for (const k of [-10, 10]) {
      const o = simulateOn(withSlope(k), into(3).scene, into(3).shot);
      for (const b of o.balls) expect(Number.isFinite(b.x) && Number.isFinite(b.y)).toBe(true);
    }
  });
});
