import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/tables.ts';
import {
  applyShot,
  cueBallId,
  legalTargets,
  newGame,
  placeCueBall,
  RuleError,
  type Game,
  type ThreeCushionGame,
} from '../../../shared/rules/index.ts';
import { deepFreeze, outcome, shotFor, withState, expectRuleError } from '../../support/rules-outcome.ts';

const spec = tableSpec('carom-match');

function carom(raceTo?: number): ThreeCushionGame {
  return newGame('threecushion', ['ann', 'bob'], raceTo === undefined ? { seed: 2 } : { seed: 2, raceTo }) as ThreeCushionGame;
}

/** After the opening shot: ann still to play (shots > 0). */
function midGame(patch: Partial<ThreeCushionGame> = {}): ThreeCushionGame {
  return withState(carom(), { shots: 4, ...patch });
}


const point = (g: Game, cue = cueBallId(g), other = cue === 'white' ? 'yellow' : 'white') =>
  applyShot(g, shotFor(g), outcome(g).hit(cue, 'red').cushion(cue, 3).hit(cue, other).build());

describe('three-cushion set-up (UMB opening position)', () => {
  it('red on the top spot, yellow on the head spot, white on the head string beside it', () => {
    const g = carom();
    const q = spec.length / 4;
    expect(g.table).toBe('carom-match');
    expect(g.balls).toEqual([
      { id: 'white', x: -q, y: -0.182 },
      { id: 'yellow', x: -q, y: 0 },
      { id: 'red', x: q, y: 0 },
    ]);
    expect(g.ballInHand).toBe(false);
    expect(g.turn).toBe('ann');
    expect(cueBallId(g)).toBe('white');
    expect(legalTargets(g)).toEqual(['yellow', 'red']);
    expect(g.raceTo).toBe(15);
    expect(g.innings).toEqual({ ann: 1, bob: 0 });
  });

  it('takes raceTo from the options and refuses a bad one', () => {
    expect(carom(3).raceTo).toBe(3);
    expectRuleError(() => newGame('threecushion', ['a', 'b'], { raceTo: 0 }), 'bad-options');
    expectRuleError(() => newGame('threecushion', ['a', 'b'], { raceTo: 2.5 }), 'bad-options');
    expectRuleError(() => newGame('threecushion', ['a'], {}), 'bad-player');
    expectRuleError(() => newGame('threecushion', ['a', 'a'], {}), 'bad-player');
  });
});

describe('three-cushion counting (UMB: both balls, three cushions before the second)', () => {
  it('the opening shot must meet the red first', () => {
    const g = carom();
    const good = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 3).hit('white', 'yellow').build());
    expect(good.scores).toEqual({ ann: 1, bob: 0 });
    const bad = applyShot(g, shotFor(g), outcome(g).cushion('white', 3).hit('white', 'yellow').hit('white', 'red').build());
    expect(bad.verdict).toMatchObject({ foul: true, reason: 'break-red-first' });
    expect(bad.scores).toEqual({ ann: 0, bob: 0 });
    expect(bad.turn).toBe('bob');
  });

  it('a point: first ball, three cushions, second ball; the player goes on', () => {
    const g = midGame();
    const n = point(g) as ThreeCushionGame;
    expect(n.verdict).toMatchObject({ foul: false, continues: true, points: { ann: 1, bob: 0 } });
    expect(n.turn).toBe('ann');
    expect(n.run).toBe(1);
  });

  it('cushions before the first ball count', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).cushion('white', 3).hit('white', 'yellow').hit('white', 'red').build());
    expect(n.scores.ann).toBe(1);
    const m = applyShot(g, shotFor(g), outcome(g).cushion('white', 1).hit('white', 'red').cushion('white', 2).hit('white', 'yellow').build());
    expect(m.scores.ann).toBe(1);
  });

  it('two cushions are not enough', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 2).hit('white', 'yellow').build());
    expect(n.scores.ann).toBe(0);
    expect(n.turn).toBe('bob');
    expect(n.verdict?.message).toMatch(/2 cushions/);
  });

  it('cushions after the second ball do not count', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 2).hit('white', 'yellow').cushion('white', 3).build());
    expect(n.scores.ann).toBe(0);
  });

  it('a cushion at the very instant of the second contact does not come before it', () => {
    const g = midGame();
    const o = outcome(g).hit('white', 'red').cushion('white', 2).build();
    const t = 5;
    const events = [...o.events, { t, kind: 'cushion', balls: ['white'] }, { t, kind: 'ball', balls: ['white', 'yellow'] }];
    expect(applyShot(g, shotFor(g), { ...o, events }).scores.ann).toBe(0);
  });

  it('one object ball only, with any number of cushions, is no point', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).cushion('white', 5).hit('white', 'red').cushion('white', 4).build());
    expect(n.scores.ann).toBe(0);
    expect(n.verdict?.message).toMatch(/only one object ball/);
  });

  it('object balls meeting each other (a kiss) are not cue ball contacts', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 3).hit('red', 'yellow').build());
    expect(n.scores.ann).toBe(0);
  });

  it('a second contact with the first ball does not stand for the second ball', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 3).hit('white', 'red').cushion('white').hit('white', 'yellow').build());
    expect(n.scores.ann).toBe(1); // 4 cushions before the first contact with the yellow
  });

  it('reads events given out of time order', () => {
    const g = midGame();
    const o = outcome(g).hit('white', 'red').cushion('white', 3).hit('white', 'yellow').build();
    expect(applyShot(g, shotFor(g), { ...o, events: [...o.events].reverse() }).scores.ann).toBe(1);
  });

  it('the second player strikes the yellow', () => {
    const g = midGame({ turn: 'bob' });
    expect(cueBallId(g)).toBe('yellow');
    const n = applyShot(g, shotFor(g), outcome(g).hit('yellow', 'white').cushion('yellow', 3).hit('yellow', 'red').build());
    expect(n.scores.bob).toBe(1);
    expectRuleError(() => applyShot(g, { ...shotFor(g), ball: 'white' }, outcome(g).build()), 'wrong-ball');
    expectRuleError(() => applyShot(g, { ...shotFor(g), ball: 'red' }, outcome(g).build()), 'wrong-ball');
  });

  it('final positions come from the outcome', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').move('white', 0.5, 0.5).move('red', -1, 0.3).build());
    expect(n.balls).toEqual([
      { id: 'white', x: 0.5, y: 0.5 },
      { id: 'yellow', x: -spec.length / 4, y: 0 },
      { id: 'red', x: -1, y: 0.3 },
    ]);
  });
});

describe('three-cushion innings and the race', () => {
  it('counts innings as each player comes to the table, runs and high runs', () => {
    let g: Game = midGame();
    const miss = (x: Game) => applyShot(x, shotFor(x), outcome(x).hit(cueBallId(x), 'red').build());
    g = point(g);
    g = point(g);
    g = miss(g); // ann's first inning ends: 2 points
    expect((g as ThreeCushionGame).innings).toEqual({ ann: 1, bob: 1 });
    g = point(g);
    g = miss(g);
    g = miss(g);
    const t = g as ThreeCushionGame;
    expect(t.innings).toEqual({ ann: 2, bob: 2 });
    expect(t.scores).toEqual({ ann: 2, bob: 1 });
    expect(t.highRun).toEqual({ ann: 2, bob: 1 });
    expect(t.run).toBe(0);
  });

  it('the first to raceTo points wins, and no shot is taken after that', () => {
    let g: Game = withState(carom(3), { shots: 1 });
    g = point(g);
    g = point(g);
    expect(g.winner).toBeNull();
    g = point(g);
    expect(g.winner).toBe('ann');
    expect(g.verdict?.rackWinner).toBe('ann');
    expectRuleError(() => point(g), 'game-over');
  });

  it('has no ball in hand, and refuses the declarations of other games', () => {
    const g = deepFreeze(midGame());
    expectRuleError(() => placeCueBall(g, 'ann', { x: 0, y: 0 }), 'not-in-hand');
    expectRuleError(() => applyShot(g, shotFor(g, { pushOut: true }), outcome(g).build()), 'bad-declaration');
    expectRuleError(() => applyShot(g, shotFor(g, { nominated: 'red' }), outcome(g).build()), 'bad-declaration');
    expectRuleError(() => applyShot(g, { ...shotFor(g), player: 'bob' }, outcome(g).build()), 'wrong-player');
  });

  it('a ball leaving the table is a foul: no point, the inning ends', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 3).hit('white', 'yellow').pot('red', 'off').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'ball-off-table', spotted: ['red'] });
    expect(n.scores.ann).toBe(0);
    expect(n.turn).toBe('bob');
    expect(n.balls.find((b) => b.id === 'red')).toEqual({ id: 'red', x: spec.length / 4, y: 0 });
    // the cue ball off the table comes back on the head spot, or the top spot when that is taken
    const h = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').move('red', 0.3, 0.3).pot('white', 'off').build());
    expect(h.balls.find((b) => b.id === 'white')).toEqual({ id: 'white', x: spec.length / 4, y: 0 });
    expect(h.balls).toHaveLength(3);
  });

  it('both object balls met at one instant after three cushions is a point; without the cushions it is not', () => {
    const g = midGame();
    expect(applyShot(g, shotFor(g), outcome(g).cushion('white', 3).hitTogether('white', ['red', 'yellow']).build()).scores.ann).toBe(1);
    expect(applyShot(g, shotFor(g), outcome(g).hitTogether('white', ['red', 'yellow']).cushion('white', 3).build()).scores.ann).toBe(0);
  });

  it('only the opening shot must meet the red first', () => {
    const g = carom();
    const opened = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('white', 3).hit('white', 'yellow').build());
    const n = applyShot(opened, shotFor(opened), outcome(opened).hit('white', 'yellow').cushion('white', 3).hit('white', 'red').build());
    expect(n.verdict?.foul).toBe(false);
    expect(n.scores.ann).toBe(2);
  });

  it('cushions met by the object balls do not count for the cue ball', () => {
    const g = midGame();
    const n = applyShot(g, shotFor(g), outcome(g).hit('white', 'red').cushion('red', 3).cushion('white').hit('white', 'yellow').build());
    expect(n.scores.ann).toBe(0);
  });
});
