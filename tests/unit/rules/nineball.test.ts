import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/tables.ts';
import {
  applyShot,
  decide,
  newGame,
  placeCueBall,
  RuleError,
  type Ball,
  type Game,
  type NineBallGame,
} from '../../../shared/rules/index.ts';
import { deepFreeze, outcome, shotFor, withState, expectRuleError } from '../../support/rules-outcome.ts';

const spec = tableSpec('pool-9ft');
const R = spec.ballRadius;
const footX = spec.length / 4;

function nine(seed = 7, raceTo?: number): NineBallGame {
  return newGame('nineball', ['ann', 'bob'], raceTo === undefined ? { seed } : { seed, raceTo }) as NineBallGame;
}

/** A mid-rack position: ann to shoot, no push-out any more. */
function midRack(balls: Ball[], patch: Partial<NineBallGame> = {}): NineBallGame {
  return withState(nine(), { balls, phase: 'play', ballInHand: false, ...patch });
}

const open: Ball[] = [
  { id: 'cue', x: -0.6, y: 0 },
  { id: '2', x: 0, y: 0 },
  { id: '3', x: 0.3, y: 0.3 },
  { id: '5', x: 0.5, y: -0.3 },
  { id: '9', x: 0.8, y: 0.1 },
];


describe('nine-ball rack (WPA 2.2)', () => {
  it('racks a diamond with the 1 on the foot spot and the 9 in the middle, cue ball in the kitchen', () => {
    const g = nine();
    expect(g.kind).toBe('nineball');
    expect(g.table).toBe('pool-9ft');
    expect(g.balls.map((b) => b.id).sort()).toEqual(['1', '2', '3', '4', '5', '6', '7', '8', '9', 'cue'].sort());
    const one = g.balls.find((b) => b.id === '1')!;
    expect(one).toMatchObject({ x: footX, y: 0 });
    const nineBall = g.balls.find((b) => b.id === '9')!;
    expect(nineBall.x).toBeCloseTo(footX + 2 * R * Math.sqrt(3), 12);
    expect(nineBall.y).toBeCloseTo(0, 12);
    // every object ball is frozen to a neighbour and none overlaps
    const objects = g.balls.filter((b) => b.id !== 'cue');
    for (const a of objects) {
      const d = objects.filter((b) => b !== a).map((b) => Math.sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)));
      expect(Math.min(...d)).toBeCloseTo(2 * R, 9);
      for (const x of d) expect(x).toBeGreaterThan(2 * R - 1e-9);
    }
    expect(g.ballInHand).toBe('kitchen');
    expect(g.balls.find((b) => b.id === 'cue')!.x).toBeLessThan(-spec.length / 4);
    expect(g.turn).toBe('ann');
    expect(g.scores).toEqual({ ann: 0, bob: 0 });
    expect(g.winner).toBeNull();
    expect(JSON.parse(JSON.stringify(g))).toEqual(g);
  });

  it('draws the order of the other balls from the seed', () => {
    expect(nine(1).balls).toEqual(nine(1).balls);
    const orders = new Set([1, 2, 3, 4, 5, 6].map((s) => nine(s).balls.map((b) => b.id).join()));
    expect(orders.size).toBeGreaterThan(1);
  });
});

describe('nine-ball break (WPA 2.3)', () => {
  it('is legal with the 1 first and four balls to rails; the other player may then push out', () => {
    const g = nine();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').cushions(['2', '3', '4', '5']).build()) as NineBallGame;
    expect(n.verdict?.foul).toBe(false);
    expect(n.turn).toBe('bob');
    expect(n.phase).toBe('push-out');
    expect(n.ballInHand).toBe(false);
  });

  it('with only three balls to rails and nothing down is a foul: ball in hand anywhere', () => {
    const g = nine();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').cushions(['2', '3', '4']).build()) as NineBallGame;
    expect(n.verdict).toMatchObject({ foul: true, reason: 'illegal-break', next: 'bob' });
    expect(n.ballInHand).toBe('anywhere');
    expect(n.phase).toBe('play'); // no push-out after a foul break
  });

  it('must meet the 1 first', () => {
    const g = nine();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').cushions(['3', '4', '5', '6']).build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'wrong-ball-first' });
    expect(n.turn).toBe('bob');
  });

  it('pocketing a ball on the break keeps the breaker at the table', () => {
    const g = nine();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').hit('1', '4').pot('4', 'TL').build()) as NineBallGame;
    expect(n.verdict).toMatchObject({ foul: false, continues: true, potted: ['4'] });
    expect(n.turn).toBe('ann');
    expect(n.phase).toBe('push-out');
    expect(n.balls.some((b) => b.id === '4')).toBe(false);
  });

  it('the 9 on a legal break wins the rack', () => {
    const g = nine();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').pot('9', 'TR').build());
    expect(n.winner).toBe('ann');
    expect(n.scores).toEqual({ ann: 1, bob: 0 });
    expect(n.verdict?.rackWinner).toBe('ann');
  });

  it('the 9 with a scratch on the break is spotted on the foot spot and the opponent has ball in hand', () => {
    const g = nine();
    const o = outcome(g).hit('cue', '1').hit('1', '9').pot('9', 'TR').pot('cue', 'BL').move('1', 1.0, 0.4).build();
    const n = applyShot(g, shotFor(g), o);
    expect(n.winner).toBeNull();
    expect(n.verdict).toMatchObject({ foul: true, reason: 'scratch', spotted: ['9'] });
    expect(n.balls.find((b) => b.id === '9')).toEqual({ id: '9', x: footX, y: 0 });
    expect(n.ballInHand).toBe('anywhere');
    expect(n.turn).toBe('bob');
    expect(n.balls.some((b) => b.id === 'cue')).toBe(true);
  });
});

describe('nine-ball push-out (WPA 2.4)', () => {
  function afterBreak(): NineBallGame {
    const g = nine();
    return applyShot(g, shotFor(g), outcome(g).hit('cue', '1').cushions(['2', '3', '4', '5']).build()) as NineBallGame;
  }

  it('needs no contact nor rail, and the other player chooses who shoots', () => {
    const g = afterBreak();
    const n = applyShot(g, shotFor(g, { pushOut: true }), outcome(g).move('cue', 0.2, 0.4).build());
    expect(n.verdict?.foul).toBe(false);
    expect(n.turn).toBe('ann');
    expect(n.choices).toEqual(['pass']);
    const passed = decide(n, 'ann', 'pass');
    expect(passed.turn).toBe('bob');
    expect(passed.choices).toEqual([]);
    // playing on instead of passing is accepting the position
    const played = applyShot(n, shotFor(n), outcome(n).hit('cue', '1').cushion('1').build());
    expect(played.verdict?.player).toBe('ann');
  });

  it('cannot be declared on the break, nor after the shot following the break', () => {
    const g = nine();
    const frozen = deepFreeze(structuredClone(g));
    expectRuleError(() => applyShot(frozen, shotFor(frozen, { pushOut: true }), outcome(frozen).build()), 'bad-declaration');
    const later = midRack(open);
    expectRuleError(() => applyShot(later, shotFor(later, { pushOut: true }), outcome(later).build()), 'bad-declaration');
  });

  it('a 9 pocketed on a push-out is spotted, and the pusher does not continue', () => {
    const g = afterBreak();
    const n = applyShot(g, shotFor(g, { pushOut: true }), outcome(g).hit('cue', '9').pot('9', 'ML').build());
    expect(n.winner).toBeNull();
    expect(n.verdict?.spotted).toEqual(['9']);
    expect(n.balls.some((b) => b.id === '9')).toBe(true);
    expect(n.turn).toBe('ann');
  });

  it('a scratch on a push-out is still a foul', () => {
    const g = afterBreak();
    const n = applyShot(g, shotFor(g, { pushOut: true }), outcome(g).pot('cue', 'MR').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'scratch' });
    expect(n.ballInHand).toBe('anywhere');
    expect(n.choices).toEqual([]);
  });
});

describe('nine-ball play (WPA 2.5-2.8, 6.1-6.3)', () => {
  it('the lowest ball must be met first', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '3').cushion('3').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'wrong-ball-first', next: 'bob' });
    expect(n.ballInHand).toBe('anywhere');
  });

  it('missing every ball is a foul', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).cushion('cue', 2).build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'no-contact' });
  });

  it('no ball to a rail after the contact, nothing down, is a foul', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).cushion('cue').hit('cue', '2').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'no-rail' });
  });

  it('a legal miss passes the turn without ball in hand and clears the foul count', () => {
    const g = midRack(open, { fouls: { ann: 2, bob: 0 } });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').cushion('2').move('2', 0.1, 0.5).build()) as NineBallGame;
    expect(n.verdict).toMatchObject({ foul: false, continues: false, next: 'bob' });
    expect(n.ballInHand).toBe(false);
    expect(n.fouls.ann).toBe(0);
    expect(n.balls.find((b) => b.id === '2')).toEqual({ id: '2', x: 0.1, y: 0.5 });
  });

  it('a legally pocketed ball keeps the shooter at the table', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').pot('2', 'TL').build());
    expect(n.verdict).toMatchObject({ continues: true, potted: ['2'] });
    expect(n.turn).toBe('ann');
  });

  it('the 9 pocketed in a combination after the lowest ball wins', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').hit('2', '9').pot('9', 'TR').build());
    expect(n.winner).toBe('ann');
  });

  it('the 9 pocketed on a foul is spotted (behind the foot spot when it is taken)', () => {
    const blocker = { id: '5', x: footX, y: 0 };
    const g = midRack([{ id: 'cue', x: -0.6, y: 0 }, { id: '2', x: 0, y: 0.3 }, blocker, { id: '9', x: 0.8, y: 0.4 }]);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '9').pot('9', 'TL').build());
    expect(n.winner).toBeNull();
    expect(n.verdict).toMatchObject({ foul: true, reason: 'wrong-ball-first', spotted: ['9'] });
    const spotted = n.balls.find((b) => b.id === '9')!;
    expect(spotted.y).toBe(0);
    expect(spotted.x).toBeCloseTo(footX + 2 * R, 9); // frozen behind the 5, towards the foot rail
  });

  it('simultaneous contact with the lowest ball and another is given to the shooter', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).hitTogether('cue', ['2', '3']).cushion('3').build());
    expect(n.verdict?.foul).toBe(false);
  });

  it('three consecutive fouls lose the rack; a legal shot in between resets the count', () => {
    let g: Game = midRack(open);
    const foul = (x: Game): Game => applyShot(x, shotFor(x), outcome(x).cushion('cue').build());
    const miss = (x: Game): Game => applyShot(x, shotFor(x), outcome(x).hit('cue', '2').cushion('2').build());
    g = foul(g); // ann 1
    g = miss(g); // bob
    g = foul(g); // ann 2
    expect((g as NineBallGame).fouls.ann).toBe(2);
    g = miss(g); // bob
    g = foul(g); // ann 3: loses
    expect(g.winner).toBe('bob');
    expect(g.verdict?.loss).toBe('three-fouls');

    let h: Game = midRack(open);
    h = foul(h);
    h = miss(h);
    h = foul(h);
    h = miss(h);
    h = miss(h); // ann legal: count back to 0
    h = miss(h);
    h = foul(h);
    expect(h.winner).toBeNull();
    expect((h as NineBallGame).fouls.ann).toBe(1);
  });

  it('ball in hand: placed anywhere clear of other balls, not elsewhere, only by the player on turn', () => {
    const g = midRack(open);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').cushion('2').pot('cue', 'BR').build());
    expect(n.ballInHand).toBe('anywhere');
    const placed = placeCueBall(n, 'bob', { x: 0.7, y: -0.5 });
    expect(placed.balls.find((b) => b.id === 'cue')).toEqual({ id: 'cue', x: 0.7, y: -0.5 });
    expectRuleError(() => placeCueBall(n, 'bob', { x: 0.01, y: 0.01 }), 'bad-placement'); // on the 2
    expectRuleError(() => placeCueBall(n, 'bob', { x: 1.5, y: 0 }), 'bad-placement'); // off the bed
    expectRuleError(() => placeCueBall(n, 'ann', { x: 0.7, y: -0.5 }), 'wrong-player');
    expectRuleError(() => placeCueBall(g, 'ann', { x: 0.7, y: -0.5 }), 'not-in-hand');
  });

  it('the break is played from the kitchen only', () => {
    const g = nine();
    expectRuleError(() => placeCueBall(g, 'ann', { x: 0, y: 0 }), 'bad-placement');
    const ok = placeCueBall(g, 'ann', { x: -0.9, y: 0.3 });
    expect(ok.balls.find((b) => b.id === 'cue')).toEqual({ id: 'cue', x: -0.9, y: 0.3 });
    // the short form places it for the player on turn
    expect(placeCueBall(g, { x: -0.9, y: -0.3 }).balls.find((b) => b.id === 'cue')).toEqual({ id: 'cue', x: -0.9, y: -0.3 });
  });

  it('a race to two: the other player breaks the next rack', () => {
    const g = nine(5, 2);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').pot('9', 'TR').build()) as NineBallGame;
    expect(n.winner).toBeNull();
    expect(n.scores).toEqual({ ann: 1, bob: 0 });
    expect(n.turn).toBe('bob');
    expect(n.breaker).toBe('bob');
    expect(n.phase).toBe('break');
    expect(n.ballInHand).toBe('kitchen');
    expect(n.balls).toHaveLength(10);
  });
});

describe('nine-ball illegal actions', () => {
  it('rejects a shot by the wrong player, the wrong ball, a foreign declaration, and leaves the game as it was', () => {
    const g = deepFreeze(midRack(open));
    const before = JSON.stringify(g);
    expectRuleError(() => applyShot(g, { ...shotFor(g), player: 'bob' }, outcome(g).build()), 'wrong-player');
    expectRuleError(() => applyShot(g, { ...shotFor(g), player: 'eve' }, outcome(g).build()), 'bad-player');
    expectRuleError(() => applyShot(g, { ...shotFor(g), ball: '2' }, outcome(g).build()), 'wrong-ball');
    expectRuleError(() => applyShot(g, shotFor(g, { calledPocket: 'TL' }), outcome(g).build()), 'bad-declaration');
    expectRuleError(() => applyShot(g, shotFor(g, { nominated: '2' }), outcome(g).build()), 'bad-declaration');
    expectRuleError(() => applyShot(g, { ...shotFor(g), speed: Number.NaN }, outcome(g).build()), 'bad-shot');
    expect(JSON.stringify(g)).toBe(before);
  });

  it('rejects an outcome that names balls not on the table', () => {
    const g = midRack(open);
    const o = outcome(g).hit('cue', '2').build();
    expectRuleError(() => applyShot(g, shotFor(g), { ...o, events: [...o.events, { t: 1, kind: 'pocket', balls: ['7'], pocket: 'TL' }] }), 'bad-outcome');
  });

  it('rejects any shot once the game is over', () => {
    const g = midRack(open);
    const won = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').pot('9', 'TR').build());
    expect(won.winner).toBe('ann');
    expectRuleError(() => applyShot(won, shotFor(won), outcome(won).build()), 'game-over');
  });

  it('is deterministic: the same game, shot and outcome give the same next game', () => {
    const g = nine(11);
    const o = outcome(g).hit('cue', '1').pot('3', 'BL').pot('cue', 'TL').build();
    expect(applyShot(g, shotFor(g), o)).toEqual(applyShot(structuredClone(g), shotFor(g), structuredClone(o)));
  });
});
