import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { simulate, TABLE_NAMES, type SceneBall, type Shot, type TableName } from '../../../shared/physics/index.ts';
import { randomScene } from '../../support/random-scenes.ts';
import { firstViolation } from '../../support/sim-checks.ts';

const RUNS = Number(process.env.BAIZE_PROPERTY_RUNS ?? 10_000);

const sceneAndShot = fc.record({
  table: fc.constantFrom(...TABLE_NAMES),
  count: fc.integer({ min: 1, max: 16 }),
  seed: fc.integer({ min: 1, max: 2 ** 31 - 1 }),
  frozen: fc.boolean(),
  // Random headings, and the exact multiples of π/4 whose halves a reduction may round either way.
  heading: fc.oneof(fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }), fc.integer({ min: -8, max: 8 }).map((k) => (k * Math.PI) / 4)),
  speed: fc.oneof(fc.double({ min: 0.01, max: 1, noNaN: true }), fc.double({ min: 1, max: 12, noNaN: true })),
  side: fc.double({ min: -0.35, max: 0.35, noNaN: true }),
  top: fc.double({ min: -0.35, max: 0.35, noNaN: true }),
});

const MIRROR_POCKET: Record<string, string> = { BL: 'BR', BR: 'BL', ML: 'MR', MR: 'ML', TL: 'TR', TR: 'TL' };

/** A shot and its mirror image y -> -y (heading and side negated) end in mirrored positions, to the bit. */
function expectMirrored(table: TableName, balls: readonly SceneBall[], shot: Shot): void {
  const a = simulate({ table, balls }, shot);
  const b = simulate({ table, balls: balls.map((x) => ({ ...x, y: -x.y })) }, { ...shot, heading: -shot.heading, side: -shot.side });
  expect(b.events.length).toBe(a.events.length);
  a.balls.forEach((ball, i) => {
    const m = b.balls[i]!;
    expect(m.x).toBe(ball.x);
    expect(m.y).toBe(ball.y === 0 ? 0 : -ball.y);
    expect(m.pocket).toBe(ball.pocket === undefined ? undefined : MIRROR_POCKET[ball.pocket]);
  });
}

describe('simulate on random scenes and shots (property)', () => {
  it(`keeps every invariant over ${RUNS} random scenes: no NaN, nothing off the table, no overlap, no energy gained, bounded events`, () => {
    fc.assert(
      fc.property(sceneAndShot, (p) => {
        const balls = randomScene(p.table, p.count, p.seed, p.frozen);
        const shot: Shot = { ball: balls[0]!.id, heading: p.heading, speed: p.speed, side: p.side, top: p.top };
        const o = simulate({ table: p.table, balls }, shot);
        const v = firstViolation(o, 200);
        expect(v, JSON.stringify(v)).toBeUndefined();
        // Where the balls come to rest is a scene the simulation takes again: a game can go on.
        const rest = o.balls.filter((b) => !b.pocketed).map(({ id, x, y }) => ({ id, x, y }));
        if (rest.length > 0) expect(() => simulate({ table: p.table, balls: rest }, { ...shot, ball: rest[0]!.id, speed: 0.01 })).not.toThrow();
        // Events at one instant stay few: a cascade through a cluster, not an endless repeat.
        const perInstant = new Map<number, number>();
        for (const e of o.events) perInstant.set(e.t, (perInstant.get(e.t) ?? 0) + 1);
        expect(Math.max(...perInstant.values())).toBeLessThanOrEqual(20 * balls.length);
      }),
      { numRuns: RUNS, seed: 20261122 },
    );
  }, 600_000);

  it('is mirror symmetric to the bit: y -> -y with heading and side negated', () => {
    fc.assert(
      fc.property(sceneAndShot, (p) => {
        const balls = randomScene(p.table, p.count, p.seed, p.frozen);
        expectMirrored(p.table, balls, { ball: balls[0]!.id, heading: p.heading, speed: p.speed, side: p.side, top: p.top });
      }),
      { numRuns: 300, seed: 7 },
    );
  });

  it('is mirror symmetric to the bit at every multiple of π/4, with and without side', () => {
    for (const table of TABLE_NAMES) {
      for (const seed of [1, 2, 3]) {
        const balls = randomScene(table, 1 + 5 * (seed - 1), seed, seed === 3);
        for (let k = -8; k <= 8; k++) {
          for (const side of [0, 0.3]) expectMirrored(table, balls, { ball: balls[0]!.id, heading: (k * Math.PI) / 4, speed: 2.5, side, top: 0.2 });
        }
      }
    }
  });

  it('is mirror symmetric along x within 1e-6 m for up to three balls (heading π - h rounds, and each impact amplifies that)', () => {
    fc.assert(
      fc.property(sceneAndShot, (p) => {
        const balls = randomScene(p.table, Math.min(p.count, 3), p.seed, false);
        const shot: Shot = { ball: balls[0]!.id, heading: p.heading, speed: Math.min(p.speed, 3), side: p.side, top: p.top };
        const a = simulate({ table: p.table, balls }, shot);
        const b = simulate({ table: p.table, balls: balls.map((x) => ({ ...x, x: -x.x })) }, { ...shot, heading: Math.PI - shot.heading, side: -shot.side });
        if (b.events.length !== a.events.length) return; // a contact decided by 1e-16 went the other way
        a.balls.forEach((ball, i) => {
          expect(Math.abs(b.balls[i]!.x + ball.x)).toBeLessThan(1e-6);
          expect(Math.abs(b.balls[i]!.y - ball.y)).toBeLessThan(1e-6);
        });
      }),
      { numRuns: 200, seed: 11 },
    );
  });
});
