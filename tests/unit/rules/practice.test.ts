import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/tables.ts';
import {
  applyShot,
  ballSet,
  concede,
  newGame,
  placeBall,
  placeBalls,
  placeCueBall,
  removeBall,
  replay,
  replayScript,
  RuleError,
  strikeOf,
  undo,
  type Game,
  type PracticeGame,
  type Shot,
  type Outcome,
} from '../../../shared/rules/index.ts';
import { deepFreeze, outcome, shotFor, expectRuleError } from '../../support/rules-outcome.ts';

const pool = tableSpec('pool-9ft');
const R = pool.ballRadius;

function practice(options = {}): PracticeGame {
  return newGame('practice', ['pat'], { seed: 4, ...options }) as PracticeGame;
}


const layout = [
  { id: 'cue', x: -0.5, y: 0 },
  { id: '3', x: 0.2, y: 0.1 },
  { id: '11', x: 0.6, y: -0.4 },
];

describe('practice set-up', () => {
  it('has one player, the eight-ball rack on the pool table by default', () => {
    const g = practice();
    expect(g.kind).toBe('practice');
    expect(g.players).toEqual(['pat']);
    expect(g.turn).toBe('pat');
    expect(g.table).toBe('pool-9ft');
    expect(g.layout).toBe('eightball');
    expect(g.balls).toHaveLength(16);
    expect(g.history).toEqual([]);
  });

  it('takes one player only', () => {
    expectRuleError(() => newGame('practice', ['a', 'b']), 'bad-player');
    expectRuleError(() => newGame('practice', []), 'bad-player');
  });

  it('sets any layout on its own table, and refuses a layout on the wrong table', () => {
    expect(practice({ layout: 'snooker' })).toMatchObject({ table: 'snooker-12ft', layout: 'snooker' });
    expect(practice({ table: 'carom-match' })).toMatchObject({ table: 'carom-match', layout: 'threecushion' });
    expect(practice({ layout: 'nineball' }).balls).toHaveLength(10);
    expect(practice({ table: 'snooker-12ft', layout: 'empty' }).balls).toEqual([{ id: 'cue', x: -tableSpec('snooker-12ft').length / 4, y: 0 }]);
    expectRuleError(() => practice({ table: 'carom-match', layout: 'snooker' }), 'bad-options');
    expectRuleError(() => practice({ table: 'billiards-10ft' }), 'bad-options');
  });
});

describe('practice free placement', () => {
  it('places any set of balls of the table', () => {
    const g = placeBalls(practice(), 'pat', layout);
    expect(g.balls).toEqual(layout);
    expect((g as PracticeGame).history).toHaveLength(1);
  });

  it('refuses overlapping balls, balls off the bed, unknown or repeated balls', () => {
    const g = deepFreeze(practice());
    expectRuleError(() => placeBalls(g, 'pat', [{ id: 'cue', x: 0, y: 0 }, { id: '1', x: 2 * R - 0.001, y: 0 }]), 'bad-placement');
    expectRuleError(() => placeBalls(g, 'pat', [{ id: 'cue', x: pool.length / 2, y: 0 }]), 'bad-placement');
    expectRuleError(() => placeBalls(g, 'pat', [{ id: 'red1', x: 0, y: 0 }]), 'bad-placement');
    expectRuleError(() => placeBalls(g, 'pat', [{ id: '1', x: 0, y: 0 }, { id: '1', x: 0.5, y: 0 }]), 'bad-placement');
    expectRuleError(() => placeBalls(g, 'pat', [{ id: '1', x: Number.NaN, y: 0 }]), 'bad-placement');
    expectRuleError(() => placeBalls(g, 'someone', layout), 'bad-player');
  });

  it('allows balls frozen together and against the cushion', () => {
    const edge = pool.width / 2 - R;
    const g = placeBalls(practice(), 'pat', [{ id: 'cue', x: 0, y: edge }, { id: '1', x: 2 * R, y: edge }]);
    expect(g.balls).toHaveLength(2);
  });

  it('moves one ball, adds one from the set, removes one', () => {
    let g: Game = placeBalls(practice(), 'pat', layout);
    g = placeBall(g, 'pat', { id: '3', x: -0.2, y: 0.4 });
    expect(g.balls.find((b) => b.id === '3')).toEqual({ id: '3', x: -0.2, y: 0.4 });
    g = placeBall(g, 'pat', { id: '8', x: 1.0, y: 0 });
    expect(g.balls).toHaveLength(4);
    g = removeBall(g, 'pat', '11');
    expect(g.balls.map((b) => b.id).sort()).toEqual(['3', '8', 'cue']);
    expectRuleError(() => removeBall(g, 'pat', '11'), 'bad-placement');
    expectRuleError(() => placeBall(g, 'pat', { id: '8', x: -0.2, y: 0.4 + R }), 'bad-placement');
  });

  it('knows the ball sets', () => {
    expect(ballSet('pool-9ft')).toHaveLength(16);
    expect(ballSet('snooker-12ft')).toHaveLength(22);
    expect(ballSet('carom-match')).toEqual(['white', 'yellow', 'red']);
  });
});

describe('practice shots, undo and replay', () => {
  const start = placeBalls(practice(), 'pat', layout);

  it('a shot moves the balls and counts the pots', () => {
    const n = applyShot(start, shotFor(start), outcome(start).hit('cue', '3').pot('3', 'TL').move('cue', 0.1, 0.2).build());
    expect(n.balls).toEqual([{ id: 'cue', x: 0.1, y: 0.2 }, { id: '11', x: 0.6, y: -0.4 }]);
    expect(n.scores.pat).toBe(1);
    expect(n.turn).toBe('pat');
    expect(n.verdict).toMatchObject({ foul: false, potted: ['3'], continues: true });
  });

  it('a cue ball down comes back in hand anywhere, to be placed freely', () => {
    const n = applyShot(start, shotFor(start), outcome(start).hit('cue', '3').pot('cue', 'BL').build());
    expect(n.ballInHand).toBe('anywhere');
    expect(n.balls.some((b) => b.id === 'cue')).toBe(true);
    expect(n.verdict?.reason).toBe('scratch');
    const p = placeCueBall(n, 'pat', { x: 1.0, y: 0.5 });
    expect(p.balls.find((b) => b.id === 'cue')).toEqual({ id: 'cue', x: 1.0, y: 0.5 });
  });

  it('undo goes back a shot, then a placement, and refuses when there is nothing left', () => {
    const n = applyShot(start, shotFor(start), outcome(start).hit('cue', '3').pot('3', 'TL').move('cue', 0.1, 0.2).build());
    const back = undo(n) as PracticeGame;
    expect(back.balls).toEqual(start.balls);
    expect(back.scores.pat).toBe(0);
    expect(back.shots).toBe(0);
    const first = undo(back) as PracticeGame;
    expect(first.balls).toEqual(practice().balls);
    expect(first.history).toEqual([]);
    expectRuleError(() => undo(first), 'nothing-to-undo');
  });

  it('records the shots with their scenes, and replaying the outcomes gives the same game', () => {
    const steps: Array<{ shot: Shot; outcome: Outcome }> = [];
    let g: Game = start;
    const s1 = shotFor(g, { heading: 0.3, speed: 1.5 });
    const o1 = outcome(g).hit('cue', '3').move('3', 0.5, 0.3).move('cue', 0.1, 0).build();
    steps.push({ shot: s1, outcome: o1 });
    g = applyShot(g, s1, o1);
    const s2 = shotFor(g, { heading: -1, speed: 2.5, side: 0.2 });
    const o2 = outcome(g).hit('cue', '11').pot('11', 'TR').build();
    steps.push({ shot: s2, outcome: o2 });
    g = applyShot(g, s2, o2);
    const script = replayScript(g);
    expect(script).toHaveLength(2);
    expect(script[0]).toEqual({ scene: { table: 'pool-9ft', balls: layout }, shot: strikeOf(s1) });
    expect(script[1]!.scene.balls).toEqual([{ id: 'cue', x: 0.1, y: 0 }, { id: '3', x: 0.5, y: 0.3 }, { id: '11', x: 0.6, y: -0.4 }]);
    expect(script[1]!.shot).toEqual({ ball: 'cue', heading: -1, speed: 2.5, side: 0.2, top: 0 });
    expect(replay(start, steps)).toEqual(g);
  });

  it('strikes only the cue ball on pool tables, either cue ball on the carom table', () => {
    expectRuleError(() => applyShot(start, { ...shotFor(start), ball: '3' }, outcome(start).build()), 'wrong-ball');
    const c = practice({ layout: 'threecushion' });
    expect(applyShot(c, { ...shotFor(c), ball: 'yellow' }, outcome(c).hit('yellow', 'red').build()).verdict?.foul).toBe(false);
    expectRuleError(() => applyShot(c, { ...shotFor(c), ball: 'red' }, outcome(c).build()), 'wrong-ball');
  });

  it('refuses a shot at a cue ball that was taken off the table', () => {
    const g = removeBall(start, 'pat', 'cue');
    expectRuleError(() => applyShot(g, shotFor(g), outcome(g).build()), 'wrong-ball');
  });

  it('refuses the practice actions in a real game, and declarations in practice', () => {
    const nine = newGame('nineball', ['a', 'b']);
    expectRuleError(() => undo(nine), 'bad-choice');
    expectRuleError(() => placeBalls(nine, 'a', layout), 'bad-choice');
    expectRuleError(() => replayScript(nine), 'bad-choice');
    expectRuleError(() => applyShot(start, shotFor(start, { pushOut: true }), outcome(start).build()), 'bad-declaration');
    expectRuleError(() => applyShot(start, shotFor(start, { calledPocket: 'TL' }), outcome(start).build()), 'bad-declaration');
  });

  it('never writes into the game or outcome it is given', () => {
    const g = deepFreeze(structuredClone(start));
    const o = deepFreeze(outcome(g).hit('cue', '3').pot('3', 'TL').build());
    const n = applyShot(g, shotFor(g), o);
    expect(n).not.toBe(g);
    expect(undo(n)).toEqual(g);
  });

  it('undoes several shots one by one back to the start', () => {
    let g: Game = start;
    const seen: Game[] = [g];
    for (const x of [0.1, 0.2, 0.3]) {
      g = applyShot(g, shotFor(g), outcome(g).hit('cue', '11').move('cue', x, -0.1).build());
      seen.push(g);
    }
    for (let i = seen.length - 2; i >= 0; i--) {
      g = undo(g);
      expect(g.balls).toEqual(seen[i]!.balls);
      expect(g.shots).toBe(seen[i]!.shots);
    }
  });

  it('the replay script leaves the placements out', () => {
    let g: Game = applyShot(start, shotFor(start), outcome(start).hit('cue', '3').build());
    g = placeBall(g, 'pat', { id: '5', x: 1.0, y: 0.3 });
    g = applyShot(g, shotFor(g), outcome(g).hit('cue', '5').build());
    const script = replayScript(g);
    expect(script).toHaveLength(2);
    expect(script[1]!.scene.balls.some((b) => b.id === '5')).toBe(true);
    expect(script[0]!.scene.balls.some((b) => b.id === '5')).toBe(false);
  });

  it('pots on a snooker table stay down in practice (no spotting)', () => {
    const g = practice({ layout: 'snooker' });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', 'black').pot('black', 'TL').build());
    expect(n.balls.some((b) => b.id === 'black')).toBe(false);
    expect(n.scores.pat).toBe(1);
  });

  it('the cue ball is not in hand unless it went down; only the player may act; nobody to concede to', () => {
    expectRuleError(() => placeCueBall(start, 'pat', { x: 0, y: 0.5 }), 'not-in-hand');
    expectRuleError(() => applyShot(start, { ...shotFor(start), player: 'max' }, outcome(start).build()), 'bad-player');
    expectRuleError(() => concede(start, 'pat'), 'bad-choice');
  });

  it('refuses an outcome about balls that are not on the table', () => {
    const o = outcome(start).hit('cue', '3').build();
    expectRuleError(() => applyShot(start, shotFor(start), { ...o, balls: [...o.balls, { id: '1', x: 0, y: 0, pocketed: false }] }), 'bad-outcome');
  });
});
