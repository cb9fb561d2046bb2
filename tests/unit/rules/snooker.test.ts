import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/tables.ts';
import {
  applyShot,
  decide,
  isSnookered,
  legalTargets,
  newGame,
  placeCueBall,
  RuleError,
  snookerMarks,
  type Ball,
  type SnookerGame,
} from '../../../shared/rules/index.ts';
import { deepFreeze, outcome, shotFor, withState, expectRuleError } from '../../support/rules-outcome.ts';

const spec = tableSpec('snooker-12ft');
const R = spec.ballRadius;
const m = snookerMarks(spec);
const S = m.spots;

function snooker(seed = 1): SnookerGame {
  return newGame('snooker', ['ann', 'bob'], { seed }) as SnookerGame;
}

function at(patch: Partial<SnookerGame>): SnookerGame {
  return withState(snooker(), { ballInHand: false, ...patch });
}

const colours = (): Ball[] => (['yellow', 'green', 'brown', 'blue', 'pink', 'black'] as const).map((c) => ({ id: c, ...S[c] }));

/** Cue ball, two reds away from everything, colours on their spots. */
function reds2(): Ball[] {
  return [{ id: 'cue', x: -0.8, y: 0.3 }, { id: 'red1', x: 0.4, y: 0.5 }, { id: 'red2', x: 0.6, y: -0.5 }, ...colours()];
}


describe('snooker set-up (WPBSA S1 R1, S3 Position of Balls)', () => {
  it('puts the colours on their spots and the reds in a triangle behind the pink', () => {
    const g = snooker();
    const half = spec.length / 2;
    expect(m.baulkX).toBeCloseTo(-half + 0.737, 12);
    const by = (id: string) => g.balls.find((b) => b.id === id)!;
    expect(by('brown')).toMatchObject({ x: m.baulkX, y: 0 });
    expect(by('yellow')).toMatchObject({ x: m.baulkX, y: -0.292 }); // right of brown seen from baulk
    expect(by('green')).toMatchObject({ x: m.baulkX, y: 0.292 });
    expect(by('blue')).toMatchObject({ x: 0, y: 0 });
    expect(by('pink').x).toBeCloseTo(half / 2, 12);
    expect(by('black').x).toBeCloseTo(half - 0.324, 12);
    const reds = g.balls.filter((b) => b.id.startsWith('red'));
    expect(reds).toHaveLength(15);
    const apex = reds.reduce((a, b) => (b.x < a.x ? b : a));
    expect(apex.y).toBe(0);
    expect(apex.x - by('pink').x).toBeGreaterThan(2 * R); // not touching the pink
    expect(apex.x - by('pink').x).toBeLessThan(2 * R + 0.002); // but as near as possible
    for (const r of reds) expect(r.x).toBeLessThan(by('black').x - 2 * R);
    expect(g.balls).toHaveLength(22);
    expect(g.ballInHand).toBe('D');
    expect(g.on).toBe('red');
    expect(legalTargets(g)).toHaveLength(15);
  });

  it('takes the cue ball in hand in the D only', () => {
    const g = snooker();
    expect(placeCueBall(g, 'ann', { x: m.baulkX - 0.1, y: 0.15 }).balls[0]).toEqual({ id: 'cue', x: m.baulkX - 0.1, y: 0.15 });
    expect(placeCueBall(g, 'ann', { x: m.baulkX, y: 0.15 }).balls[0]!.x).toBe(m.baulkX); // on the line
    expectRuleError(() => placeCueBall(g, 'ann', { x: m.baulkX + 0.01, y: 0.1 }), 'bad-placement'); // beyond the baulk line
    expectRuleError(() => placeCueBall(g, 'ann', { x: m.baulkX - 0.05, y: 0.29 }), 'bad-placement'); // outside the semicircle
    expectRuleError(() => placeCueBall(g, 'ann', { x: m.baulkX, y: 0.01 }), 'bad-placement'); // on the brown
  });
});

describe('snooker scoring (WPBSA S3 Mode of Play, Spotting Colours)', () => {
  it('a red scores 1 and the striker is on a colour', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'red1').pot('red1', 'TL').build()) as SnookerGame;
    expect(n.scores).toEqual({ ann: 1, bob: 0 });
    expect(n.on).toBe('colour');
    expect(n.turn).toBe('ann');
    expect(n.break).toBe(1);
  });

  it('two reds in one stroke score 2', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'red1').hit('red1', 'red2').pot('red1', 'TL').pot('red2', 'BR').build());
    expect(n.scores.ann).toBe(2);
  });

  it('the colour after a red scores its value and is re-spotted; then reds again', () => {
    const g = at({ balls: reds2(), on: 'colour' });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').pot('black', 'TL').build()) as SnookerGame;
    expect(n.verdict?.points.ann).toBe(7);
    expect(n.balls.find((b) => b.id === 'black')).toEqual({ id: 'black', ...S.black });
    expect(n.verdict?.spotted).toEqual(['black']);
    expect(n.on).toBe('red');
    expect(n.turn).toBe('ann');
  });

  it('a colour whose spot is taken goes on the highest spot available', () => {
    const balls = reds2().filter((b) => b.id !== 'blue');
    balls.push({ id: 'red3', ...S.black }, { id: 'blue', x: 0.3, y: -0.6 });
    balls.find((b) => b.id === 'red1')!.x = S.pink.x; // red1 on the pink spot... the pink must move
    balls.find((b) => b.id === 'red1')!.y = 0;
    balls.find((b) => b.id === 'pink')!.y = 0.6;
    const g = at({ balls, on: 'colour' });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').pot('black', 'TL').build());
    expect(n.balls.find((b) => b.id === 'black')).toEqual({ id: 'black', ...S.blue });
  });

  it('with every spot taken, a colour goes as near its spot as possible towards the top cushion', () => {
    const balls = [...reds2(), { id: 'red3', ...S.black }];
    const g = at({ balls, on: 'colour' });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').pot('black', 'TL').build());
    const black = n.balls.find((b) => b.id === 'black')!;
    expect(black.y).toBe(0);
    expect(black.x).toBeGreaterThan(S.black.x + 2 * R);
    expect(black.x).toBeLessThan(S.black.x + 2 * R + 1e-6);
  });

  it('after the last red and its colour, the colours are taken in order and stay down', () => {
    const g = at({ balls: [{ id: 'cue', x: -0.5, y: 0.3 }, { id: 'red1', x: 0.4, y: 0.5 }, ...colours()] });
    const a = applyShot(g, shotFor(g), outcome(g).hit('cue', 'red1').pot('red1', 'TL').build()) as SnookerGame;
    const b = applyShot(a, shotFor(a, { nominated: 'blue' }), outcome(a).hit('cue', 'blue').pot('blue', 'ML').build()) as SnookerGame;
    expect(b.balls.some((x) => x.id === 'blue')).toBe(true); // the colour after the last red is re-spotted
    expect(b.on).toBe('yellow');
    const c = applyShot(b, shotFor(b), outcome(b).hit('cue', 'yellow').pot('yellow', 'BR').build()) as SnookerGame;
    expect(c.balls.some((x) => x.id === 'yellow')).toBe(false);
    expect(c.on).toBe('green');
    expect(c.scores.ann).toBe(1 + 5 + 2);
    expect(c.break).toBe(8);
    expect(legalTargets(c)).toEqual(['green']);
  });

  it('potting the black last ends the frame: the higher score wins', () => {
    const g = at({ balls: [{ id: 'cue', x: 1.0, y: 0.1 }, { id: 'black', ...S.black }], on: 'black', scores: { ann: 50, bob: 55 } });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').pot('black', 'TL').build());
    expect(n.scores).toEqual({ ann: 57, bob: 55 });
    expect(n.winner).toBe('ann');
  });

  it('a tie after the last black re-spots the black; lots drawn from the seed; the next score ends it', () => {
    const chooser = new Set<string>();
    for (let seed = 1; seed <= 16; seed++) {
      const g = withState(newGame('snooker', ['ann', 'bob'], { seed }) as SnookerGame, {
        balls: [{ id: 'cue', x: 1.0, y: 0.1 }, { id: 'black', ...S.black }],
        on: 'black',
        ballInHand: false,
        scores: { ann: 33, bob: 40 },
      });
      const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').pot('black', 'TL').build()) as SnookerGame;
      expect(n.winner).toBeNull();
      expect(n.respottedBlack).toBe(true);
      expect(n.balls.find((b) => b.id === 'black')).toEqual({ id: 'black', ...S.black });
      expect(n.ballInHand).toBe('D');
      expect(n.choices).toEqual(['pass']);
      chooser.add(n.turn);
      const p = decide(n, n.turn, 'pass');
      const end = applyShot(p, shotFor(p), outcome(p).hit('cue', 'black').pot('black', 'TR').build());
      expect(end.winner).toBe(p.turn);
      expect(end.scores[p.turn]).toBe(47);
    }
    expect(chooser).toEqual(new Set(['ann', 'bob']));
  });
});

describe('snooker fouls (WPBSA S3 Fouls, Penalties)', () => {
  it('missing every ball costs 4 (the minimum) and the other player comes in', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).cushion('cue').build()) as SnookerGame;
    expect(n.verdict).toMatchObject({ foul: true, reason: 'no-contact', points: { ann: 0, bob: 4 }, next: 'bob' });
    expect(n.scores).toEqual({ ann: 0, bob: 4 });
    expect(n.choices).toEqual(['pass']);
  });

  it('hitting the black first when on a red costs 7', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').build());
    expect(n.verdict).toMatchObject({ reason: 'wrong-ball-first' });
    expect(n.scores.bob).toBe(7);
  });

  it('on a nominated blue, hitting the pink first costs 6 (the higher value)', () => {
    const g = at({ balls: reds2(), on: 'colour' });
    const n = applyShot(g, shotFor(g, { nominated: 'blue' }), outcome(g).hit('cue', 'pink').build());
    expect(n.scores.bob).toBe(6);
  });

  it('on a colour, potting a red is a foul of at least the colour value', () => {
    const g = at({ balls: reds2(), on: 'colour' });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'blue').hit('blue', 'red1').pot('red1', 'TL').build()) as SnookerGame;
    expect(n.verdict).toMatchObject({ foul: true, reason: 'pot-not-on' });
    expect(n.scores).toEqual({ ann: 0, bob: 5 });
    expect(n.balls.some((b) => b.id === 'red1')).toBe(false); // reds are not replaced
    expect(n.on).toBe('red');
  });

  it('a red and a colour met at the same instant is a foul valued by the colour', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).hitTogether('cue', ['red1', 'green']).cushion('red1').build());
    expect(n.verdict?.reason).toBe('wrong-ball-first');
    expect(n.scores.bob).toBe(4);
    const h = applyShot(g, shotFor(g), outcome(g).hitTogether('cue', ['red1', 'pink']).build());
    expect(h.scores.bob).toBe(6);
  });

  it('an in-off costs at least 4, the colour potted in the foul comes back, the next player is in hand in the D', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'red1').hit('red1', 'blue').pot('blue', 'ML').pot('cue', 'TL').build()) as SnookerGame;
    expect(n.verdict?.fouls).toEqual(['pot-not-on', 'in-off']);
    expect(n.scores.bob).toBe(5);
    expect(n.balls.find((b) => b.id === 'blue')).toEqual({ id: 'blue', ...S.blue });
    expect(n.ballInHand).toBe('D');
    expect(n.freeBall).toBe(false);
  });

  it('in the end sequence, potting a colour out of order is a foul and the colour is re-spotted', () => {
    const g = at({ balls: [{ id: 'cue', x: -0.5, y: 0.5 }, ...colours()], on: 'yellow' });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'green').pot('green', 'BL').build()) as SnookerGame;
    expect(n.scores.bob).toBe(4);
    expect(n.balls.find((b) => b.id === 'green')).toEqual({ id: 'green', ...S.green });
    expect(n.on).toBe('yellow');
  });

  it('the last red potted on a foul leaves the next player on the yellow', () => {
    const g = at({ balls: [{ id: 'cue', x: -0.5, y: 0.3 }, { id: 'red1', x: 0.4, y: 0.5 }, ...colours()] });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'red1').pot('red1', 'TL').pot('cue', 'TR').build()) as SnookerGame;
    expect(n.on).toBe('yellow');
    expect(n.scores).toEqual({ ann: 0, bob: 4 });
  });

  it('a foul when only the black remains ends the frame', () => {
    const g = at({ balls: [{ id: 'cue', x: 1.0, y: 0.4 }, { id: 'black', ...S.black }], on: 'black', scores: { ann: 40, bob: 30 } });
    const n = applyShot(g, shotFor(g), outcome(g).cushion('cue').build());
    expect(n.scores).toEqual({ ann: 40, bob: 37 });
    expect(n.winner).toBe('ann');
  });

  it('after a foul the next player may have the offender play again', () => {
    const g = at({ balls: reds2() });
    const n = applyShot(g, shotFor(g), outcome(g).cushion('cue').build());
    const back = decide(n, 'bob', 'pass') as SnookerGame;
    expect(back.turn).toBe('ann');
    expect(back.choices).toEqual([]);
    expect(back.scores).toEqual(n.scores);
    const next = applyShot(back, shotFor(back), outcome(back).hit('cue', 'red1').pot('red1', 'TL').build());
    expect(next.scores).toEqual({ ann: 1, bob: 4 });
  });
});

describe('snooker free ball (WPBSA S3 Snookered after a Foul)', () => {
  // Only one red, and the blue between it and the cue ball after ann's foul.
  const lineUp: Ball[] = [
    { id: 'cue', x: -1.2, y: 0.5 },
    { id: 'red1', x: 0.5, y: 0.5 },
    { id: 'blue', x: -0.5, y: 0.5 },
    ...colours().filter((c) => c.id !== 'blue'),
  ];

  function afterFoul(blueY = 0.5): SnookerGame {
    const balls = lineUp.map((b) => (b.id === 'blue' ? { ...b, y: blueY } : b));
    const g = at({ balls });
    return applyShot(g, shotFor(g), outcome(g).cushion('cue').move('cue', -1.0, 0.5).build()) as SnookerGame;
  }

  it('is given when the foul leaves the next player snookered, also when only partly (one edge hidden)', () => {
    expect(afterFoul().freeBall).toBe(true);
    expect(afterFoul(0.5 + 0.06).freeBall).toBe(true); // full-ball line clear, an edge hidden
    expect(afterFoul(0.5 + 0.09).freeBall).toBe(false); // both edges visible
    expect(legalTargets(afterFoul())).toContain('blue');
  });

  it('a potted free ball counts as a red, is re-spotted, and the striker is on a colour', () => {
    const g = afterFoul();
    const n = applyShot(g, shotFor(g, { nominated: 'blue' }), outcome(g).hit('cue', 'blue').pot('blue', 'ML').build()) as SnookerGame;
    expect(n.verdict?.foul).toBe(false);
    expect(n.scores).toEqual({ ann: 0, bob: 4 + 1 });
    expect(n.balls.find((b) => b.id === 'blue')).toEqual({ id: 'blue', ...S.blue });
    expect(n.on).toBe('colour');
    expect(n.freeBall).toBe(false);
  });

  it('the nominated ball must be met first', () => {
    const g = afterFoul();
    const n = applyShot(g, shotFor(g, { nominated: 'blue' }), outcome(g).hit('cue', 'pink').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'wrong-ball-first' });
    expect(n.scores.ann).toBe(6);
  });

  it('leaving the opponent snookered behind the free ball is a foul', () => {
    const g = afterFoul();
    const n = applyShot(g, shotFor(g, { nominated: 'blue' }), outcome(g).hit('cue', 'blue').cushion('blue').move('cue', -1.2, 0.5).build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'free-ball-snooker' });
    expect(n.scores.ann).toBe(4);
  });

  it('a free ball must not be a ball on, and is void once the offender is asked to play again', () => {
    const g = deepFreeze(afterFoul());
    expectRuleError(() => applyShot(g, shotFor(g, { nominated: 'red1' }), outcome(g).build()), 'bad-declaration');
    expectRuleError(() => applyShot(g, shotFor(g, { nominated: 'cue' }), outcome(g).build()), 'bad-declaration');
    const back = decide(g, 'bob', 'pass') as SnookerGame;
    expect(back.freeBall).toBe(false);
    expectRuleError(() => applyShot(back, shotFor(back, { nominated: 'blue' }), outcome(back).build()), 'bad-declaration');
  });

  it('nomination applies only to a free ball or the colour after a red', () => {
    const g = at({ balls: reds2() });
    expectRuleError(() => applyShot(g, shotFor(g, { nominated: 'blue' }), outcome(g).build()), 'bad-declaration');
    const c = at({ balls: reds2(), on: 'colour' });
    expectRuleError(() => applyShot(c, shotFor(c, { nominated: 'red1' }), outcome(c).build()), 'bad-declaration');
    expectRuleError(() => applyShot(c, shotFor(c, { pushOut: true }), outcome(c).build()), 'bad-declaration');
  });
});

describe('the snookered test (line of sight on ball positions)', () => {
  const cue = { x: 0, y: 0 };
  const target = { id: 'red1', x: 1, y: 0 };
  it('is snookered behind a ball on the line, or one hiding an edge', () => {
    expect(isSnookered(cue, [target], [{ id: 'blue', x: 0.5, y: 0 }], R)).toBe(true);
    expect(isSnookered(cue, [target], [{ id: 'blue', x: 0.5, y: 0.06 }], R)).toBe(true);
    expect(isSnookered(cue, [target], [{ id: 'blue', x: 0.5, y: 0.2 }], R)).toBe(false);
    expect(isSnookered(cue, [target], [{ id: 'blue', x: -0.5, y: 0 }], R)).toBe(false); // behind the cue ball
    expect(isSnookered(cue, [target, { id: 'red2', x: 0, y: 1 }], [{ id: 'blue', x: 0.5, y: 0 }], R)).toBe(false);
  });
});
