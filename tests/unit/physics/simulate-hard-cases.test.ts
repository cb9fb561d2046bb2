// The hard cases of docs/simulation.md, each through the public simulate() on the corpus scene
// that defines it.
import { describe, expect, it } from 'vitest';
import { sampleOutcome, simulate, tableSpec, type Outcome } from '../../../shared/physics/index.ts';
import { CORPUS } from '../../../shared/scenes/index.ts';
import { corpusCase } from '../../support/corpus.ts';
import { firstViolation } from '../../support/sim-checks.ts';

function run(name: string): Outcome {
  const c = corpusCase(name);
  return simulate(c.scene, c.shot);
}

function final(o: Outcome, id: string) {
  return o.balls.find((b) => b.id === id)!;
}

describe('hard cases', () => {
  it('every corpus case keeps every invariant at every event', () => {
    for (const c of CORPUS) {
      const o = simulate(c.scene, c.shot);
      expect(firstViolation(o), c.name).toBeUndefined();
      expect(o.events.length, c.name).toBeGreaterThan(0);
    }
  });

  it('a line of frozen balls struck straight passes the impulse down the line at one instant', () => {
    const o = run('line of three frozen balls struck straight');
    const first = o.events[0]!;
    expect(first).toMatchObject({ kind: 'ball', balls: ['cue', '1'] });
    const atOnce = o.events.filter((e) => e.t === first.t);
    expect(atOnce.map((e) => e.balls.join('-'))).toEqual(expect.arrayContaining(['cue-1', '1-2', '2-3']));
    expect(atOnce.length).toBeLessThan(10); // a finite cascade, not a train of ever smaller impacts
    // Just after, the last ball carries almost all the speed and the others almost none.
    const after = sampleOutcome(o, first.t);
    const speed = (id: string) => Math.hypot(after.find((b) => b.id === id)!.vx, after.find((b) => b.id === id)!.vy);
    expect(speed('3')).toBeGreaterThan(0.9 * 2.62);
    for (const id of ['cue', '1', '2']) expect(speed(id)).toBeLessThan(0.1);
  });

  it('two balls hit at the same instant both move off, on their own sides', () => {
    const o = run('two balls hit at the same instant');
    const t = o.events[0]!.t;
    expect(o.events.filter((e) => e.t === t && e.kind === 'ball').map((e) => e.balls.join('-'))).toEqual(['cue-1', 'cue-2']);
    const after = sampleOutcome(o, t);
    expect(after.find((b) => b.id === '1')!.vy).toBeGreaterThan(0);
    expect(after.find((b) => b.id === '2')!.vy).toBeLessThan(0);
  });

  it('a grazing contact is found, and a micrometre miss is not', () => {
    const graze = run('grazing ball-ball contact');
    expect(graze.events.some((e) => e.kind === 'ball')).toBe(true);
    const miss = run('near miss by a micrometre');
    expect(miss.events.some((e) => e.kind === 'ball')).toBe(false);
    expect(final(miss, '1')).toMatchObject({ x: 0.3, pocketed: false });
  });

  it('a state change at the instant of a collision is handled once each', () => {
    const o = run('state change at the instant of a collision');
    const hit = o.events.find((e) => e.kind === 'ball')!;
    expect(hit.balls).toEqual(['cue', '1']);
    // The cue ball is struck as it stops sliding: whichever comes first, nothing repeats.
    expect(o.events.filter((e) => e.t === hit.t).length).toBeLessThanOrEqual(2);
  });

  it('a ball frozen to a rail and struck along it runs along the rail without bouncing', () => {
    const o = run('frozen to a rail, struck along it');
    expect(o.events.filter((e) => e.kind === 'cushion' && e.cushion?.startsWith('top-long'))).toEqual([]);
    expect(final(o, 'cue')).toMatchObject({ pocketed: true, pocket: 'TL' });
  });

  it('a ball frozen to a rail and struck into it rebounds at once', () => {
    const o = run('frozen to a rail, struck into it');
    expect(o.events[0]).toMatchObject({ t: 0, kind: 'cushion', balls: ['cue'] });
    expect(o.events[0]!.cushion).toMatch(/^bottom-long/);
  });

  it('a ball into a corner meets both cushions at the same instant', () => {
    const o = run('carom straight into a corner (two cushions at once)');
    const cushions = o.events.filter((e) => e.kind === 'cushion');
    expect(cushions[1]!.t - cushions[0]!.t).toBeLessThan(1e-12);
    expect(new Set([cushions[0]!.cushion, cushions[1]!.cushion])).toEqual(new Set(['right-short', 'top-long']));
  });

  it('follow and draw: the cue ball goes on through, or comes back', () => {
    const follow = run('follow shot (equal accelerations after)');
    const draw = run('draw shot');
    const contact = (o: Outcome) => o.events.find((e) => e.kind === 'ball')!.t;
    // 0.2 s after contact, before anything else happens to it, the cue ball moves forward or back.
    const vx = (o: Outcome) => sampleOutcome(o, contact(o) + 0.2).find((b) => b.id === 'cue')!.vx;
    expect(vx(follow)).toBeGreaterThan(0.3);
    expect(vx(draw)).toBeLessThan(-0.3);
  });

  it('balls rattle in the jaws: nose and face hits on the curved jaws, staying out', () => {
    const snooker = run('snooker corner jaw rattle');
    const jawHits = snooker.events.filter((e) => e.kind === 'cushion' && /^TL-(long|short)-(nose|face)$/.test(e.cushion ?? ''));
    expect(jawHits.length).toBeGreaterThanOrEqual(2);
    expect(final(snooker, 'cue').pocketed).toBe(false);
    const side = run('middle pocket jaw at an angle');
    expect(side.events.some((e) => e.cushion === 'ML-right-nose')).toBe(true);
  });

  it('pots go down: a ball into a corner and into a middle pocket', () => {
    expect(final(run('snooker black into the corner'), 'black')).toMatchObject({ pocketed: true, pocket: 'TL' });
    expect(final(run('pot into a middle pocket'), 'cue')).toMatchObject({ pocketed: true, pocket: 'ML' });
  });

  it('a very slow cushion impact rebounds without gaining energy', () => {
    const o = run('very slow into a cushion (0.05 m/s)');
    const hit = o.events.find((e) => e.kind === 'cushion')!;
    expect(hit.speed).toBeGreaterThan(0.01);
    expect(hit.speed).toBeLessThan(0.05);
    expect(final(o, 'cue').y).toBeLessThan(tableSpec('pool-9ft').width / 2 - tableSpec('pool-9ft').ballRadius);
  });

  it('hard breaks on the pool and snooker tables, beyond the rigid-cushion limit, stay sound', () => {
    for (const name of ['nineball break 11 m/s from y=0.25', 'eightball break 12 m/s', 'snooker hard break beyond the rigid limit', 'snooker break 10 m/s']) {
      const o = run(name);
      expect(firstViolation(o), name).toBeUndefined();
      expect(o.events.filter((e) => e.kind === 'ball').length, name).toBeGreaterThan(10);
    }
  });
});
