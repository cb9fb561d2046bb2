import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/tables.ts';
import {
  applyShot,
  decide,
  groupOf,
  legalTargets,
  newGame,
  placeCueBall,
  RuleError,
  type Ball,
  type EightBallGame,
} from '../../../shared/rules/index.ts';
import { deepFreeze, outcome, shotFor, withState, expectRuleError } from '../../support/rules-outcome.ts';

const spec = tableSpec('pool-9ft');
const R = spec.ballRadius;
const footX = spec.length / 4;

function eight(seed = 3): EightBallGame {
  return newGame('eightball', ['ann', 'bob'], { seed }) as EightBallGame;
}

function inPlay(balls: Ball[], patch: Partial<EightBallGame> = {}): EightBallGame {
  return withState(eight(), { balls, phase: 'play', ballInHand: false, groups: null, ...patch });
}

const solidsStripes = { ann: 'solids', bob: 'stripes' } as const;

const position: Ball[] = [
  { id: 'cue', x: -0.6, y: 0 },
  { id: '1', x: 0, y: 0 },
  { id: '2', x: 0.3, y: 0.3 },
  { id: '9', x: 0.5, y: -0.3 },
  { id: '10', x: -0.2, y: 0.4 },
  { id: '8', x: 0.8, y: 0.1 },
];

const onEight: Ball[] = [
  { id: 'cue', x: -0.6, y: 0 },
  { id: '9', x: 0.5, y: -0.3 },
  { id: '8', x: 0.8, y: 0.1 },
];


describe('eight-ball rack (WPA 3.2)', () => {
  it('racks a triangle: apex on the foot spot, 8 in the middle, a solid and a stripe on the back corners', () => {
    for (const seed of [1, 2, 3, 4, 5, 6, 7, 8]) {
      const g = eight(seed);
      expect(g.balls).toHaveLength(16);
      const objects = g.balls.filter((b) => b.id !== 'cue');
      const apex = objects.reduce((a, b) => (b.x < a.x ? b : a));
      expect(apex).toMatchObject({ x: footX, y: 0 });
      const e = g.balls.find((b) => b.id === '8')!;
      expect(e.x).toBeCloseTo(footX + 2 * R * Math.sqrt(3), 12);
      expect(e.y).toBeCloseTo(0, 12);
      const back = objects.filter((b) => Math.abs(b.x - (footX + 4 * R * Math.sqrt(3))) < 1e-9 && Math.abs(Math.abs(b.y) - 4 * R) < 1e-9);
      expect(back).toHaveLength(2);
      expect(new Set(back.map((b) => groupOf(b.id)))).toEqual(new Set(['solids', 'stripes']));
    }
    expect(eight(9).balls).toEqual(eight(9).balls);
    expect(new Set([1, 2, 3, 4].map((s) => eight(s).balls.map((b) => b.id).join())).size).toBeGreaterThan(1);
  });
});

describe('eight-ball break (WPA 3.3)', () => {
  it('four balls to rails and nothing down: legal, the table is open, the opponent plays', () => {
    const g = eight();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '3').cushions(['1', '2', '4', '5']).build()) as EightBallGame;
    expect(n.verdict?.foul).toBe(false);
    expect(n.turn).toBe('bob');
    expect(n.groups).toBeNull();
    expect(n.phase).toBe('play');
  });

  it('a ball down on the break keeps the breaker at the table, the table stays open', () => {
    const g = eight();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').pot('4', 'TL').build()) as EightBallGame;
    expect(n.verdict?.continues).toBe(true);
    expect(n.groups).toBeNull();
    expect(legalTargets(n)).not.toContain('8');
  });

  it('an illegal break lets the opponent play on, re-rack and break, or make the breaker break again', () => {
    const g = eight();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').cushions(['2', '3']).build()) as EightBallGame;
    expect(n.verdict).toMatchObject({ foul: true, reason: 'illegal-break', next: 'bob' });
    expect(n.ballInHand).toBe(false);
    expect(n.choices).toEqual(['rerack', 'rerack-other']);
    const self = decide(n, 'bob', 'rerack') as EightBallGame;
    expect(self).toMatchObject({ turn: 'bob', breaker: 'bob', phase: 'break', ballInHand: 'kitchen' });
    expect(self.balls).toHaveLength(16);
    expect(self.rng).not.toBe(n.rng);
    const again = decide(n, 'bob', 'rerack-other') as EightBallGame;
    expect(again).toMatchObject({ turn: 'ann', breaker: 'ann', phase: 'break' });
    // playing on accepts the table
    const played = applyShot(n, shotFor(n), outcome(n).hit('cue', '2').cushion('2').build());
    expect(played.verdict?.player).toBe('bob');
    expect(played.choices).toEqual([]);
    expectRuleError(() => decide(n, 'ann', 'rerack'), 'wrong-player');
    expectRuleError(() => decide(n, 'bob', 'pass'), 'bad-choice');
  });

  it('a scratch on a legal break gives ball in hand in the kitchen, and it must be placed there', () => {
    const g = eight();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').pot('5', 'TL').pot('cue', 'TR').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'scratch', potted: ['5'] });
    expect(n.ballInHand).toBe('kitchen');
    expect(n.turn).toBe('bob');
    expect(n.balls.find((b) => b.id === 'cue')!.x).toBeLessThan(-spec.length / 4);
    expectRuleError(() => placeCueBall(n, 'bob', { x: 0, y: 0.5 }), 'bad-placement');
    expect(placeCueBall(n, 'bob', { x: -1.0, y: -0.4 }).balls.find((b) => b.id === 'cue')).toEqual({ id: 'cue', x: -1.0, y: -0.4 });
  });

  it('from the kitchen, meeting first a ball behind the head string without leaving the kitchen is a foul', () => {
    const g = inPlay(
      [{ id: 'cue', x: -1.0, y: 0 }, { id: '3', x: -0.8, y: 0.1 }, { id: '11', x: 0.5, y: 0 }, { id: '8', x: 0.7, y: 0.3 }],
      { ballInHand: 'kitchen', turn: 'bob' },
    );
    const bad = applyShot(g, shotFor(g), outcome(g).hit('cue', '3').cushion('3').build());
    expect(bad.verdict).toMatchObject({ foul: true, reason: 'kitchen-not-crossed' });
    const good = applyShot(g, shotFor(g), outcome(g).hit('cue', '11').cushion('11').build());
    expect(good.verdict?.foul).toBe(false);
  });

  it('the 8 on the break is spotted and the breaker continues (or may re-break)', () => {
    const g = eight();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').pot('8', 'ML').build());
    expect(n.winner).toBeNull();
    expect(n.verdict).toMatchObject({ foul: false, continues: true, spotted: ['8'] });
    const e = n.balls.find((b) => b.id === '8')!;
    expect(e.y).toBe(0);
    expect(e.x).toBeGreaterThanOrEqual(footX); // on the foot spot or behind the balls there
    expect(n.choices).toEqual(['rerack']);
    const re = decide(n, 'ann', 'rerack') as EightBallGame;
    expect(re).toMatchObject({ breaker: 'ann', phase: 'break' });
  });

  it('the 8 with a scratch on the break: spotted, opponent in hand in the kitchen, not a loss', () => {
    const g = eight();
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').pot('8', 'ML').pot('cue', 'BL').build());
    expect(n.winner).toBeNull();
    expect(n.verdict).toMatchObject({ foul: true, spotted: ['8'], next: 'bob' });
    expect(n.ballInHand).toBe('kitchen');
    expect(n.choices).toEqual(['rerack']);
  });
});

describe('eight-ball open table and groups (WPA 3.4, 3.5)', () => {
  it('a legally pocketed solid gives the shooter the solids', () => {
    const g = inPlay(position);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').pot('2', 'TL').build()) as EightBallGame;
    expect(n.groups).toEqual({ ann: 'solids', bob: 'stripes' });
    expect(n.verdict?.continues).toBe(true);
    expect(legalTargets(n)).toEqual(['1']);
  });

  it('a stripe hit first on an open table is fine and decides the group when it drops', () => {
    const g = inPlay(position);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '9').hit('9', '1').pot('9', 'BR').pot('1', 'TR').build()) as EightBallGame;
    expect(n.groups).toEqual({ ann: 'stripes', bob: 'solids' });
  });

  it('the 8 may not be met first on an open table', () => {
    const g = inPlay(position);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '8').cushion('8').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'wrong-ball-first' });
    expect(n.ballInHand).toBe('anywhere');
  });

  it('no group is chosen on a foul, and the balls pocketed stay down', () => {
    const g = inPlay(position);
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '2').pot('2', 'TL').pot('cue', 'TR').build()) as EightBallGame;
    expect(n.groups).toBeNull();
    expect(n.balls.some((b) => b.id === '2')).toBe(false);
    expect(n.turn).toBe('bob');
  });

  it('meeting an opponent ball first is a foul: ball in hand anywhere', () => {
    const g = inPlay(position, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '9').hit('9', '1').pot('1', 'TL').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'wrong-ball-first', next: 'bob' });
    expect(n.ballInHand).toBe('anywhere');
  });

  it('pocketing only an opponent ball after a fair hit ends the turn', () => {
    const g = inPlay(position, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').hit('1', '9').pot('9', 'TL').build());
    expect(n.verdict).toMatchObject({ foul: false, continues: false, next: 'bob', potted: ['9'] });
  });

  it('no rail after contact is a foul', () => {
    const g = inPlay(position, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').build());
    expect(n.verdict).toMatchObject({ foul: true, reason: 'no-rail' });
  });
});

describe('eight-ball: the called 8 (WPA 3.8 Losing the Rack)', () => {
  it('pocketing the 8 before the group is off the table loses', () => {
    const g = inPlay(position, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '1').hit('1', '8').pot('8', 'TL').build());
    expect(n.winner).toBe('bob');
    expect(n.verdict?.loss).toBe('eight-early');
  });

  it('pocketing the 8 with the last ball of the group loses', () => {
    const g = inPlay([...onEight, { id: '3', x: 0, y: 0 }], { groups: solidsStripes });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '3').pot('3', 'TR').pot('8', 'TL').build());
    expect(n.winner).toBe('bob');
    expect(n.verdict?.loss).toBe('eight-early');
  });

  it('the 8 in the called pocket wins', () => {
    const g = inPlay(onEight, { groups: solidsStripes });
    expect(legalTargets(g)).toEqual(['8']);
    const n = applyShot(g, shotFor(g, { calledPocket: 'TL', calledBall: '8' }), outcome(g).hit('cue', '8').pot('8', 'TL').build());
    expect(n.winner).toBe('ann');
    expect(n.scores).toEqual({ ann: 1, bob: 0 });
  });

  it('the 8 in another pocket than the called one loses', () => {
    const g = inPlay(onEight, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g, { calledPocket: 'TL' }), outcome(g).hit('cue', '8').pot('8', 'TR').build());
    expect(n.winner).toBe('bob');
    expect(n.verdict?.loss).toBe('eight-wrong-pocket');
  });

  it('the 8 pocketed without a call loses (an uncalled pocket)', () => {
    const g = inPlay(onEight, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g), outcome(g).hit('cue', '8').pot('8', 'TR').build());
    expect(n.winner).toBe('bob');
    expect(n.verdict?.loss).toBe('eight-wrong-pocket');
  });

  it('the 8 pocketed with a scratch loses', () => {
    const g = inPlay(onEight, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g, { calledPocket: 'TL' }), outcome(g).hit('cue', '8').pot('8', 'TL').pot('cue', 'BL').build());
    expect(n.winner).toBe('bob');
    expect(n.verdict?.loss).toBe('eight-with-foul');
  });

  it('a scratch while playing the 8 without pocketing it is only a foul', () => {
    const g = inPlay(onEight, { groups: solidsStripes });
    const n = applyShot(g, shotFor(g, { calledPocket: 'TL' }), outcome(g).hit('cue', '8').cushion('8').pot('cue', 'BL').build());
    expect(n.winner).toBeNull();
    expect(n.verdict).toMatchObject({ foul: true, reason: 'scratch' });
    expect(n.ballInHand).toBe('anywhere');
  });

  it('a called pocket is refused when the 8 is not the legal ball, a called ball other than the 8 too', () => {
    const g = deepFreeze(inPlay(position, { groups: solidsStripes }));
    expectRuleError(() => applyShot(g, shotFor(g, { calledPocket: 'TL' }), outcome(g).build()), 'bad-declaration');
    const h = inPlay(onEight, { groups: solidsStripes });
    expectRuleError(() => applyShot(h, shotFor(h, { calledPocket: 'TL', calledBall: '9' }), outcome(h).build()), 'bad-declaration');
    expectRuleError(() => applyShot(h, shotFor(h, { pushOut: true }), outcome(h).build()), 'bad-declaration');
    const open = eight();
    expectRuleError(() => applyShot(open, shotFor(open, { calledPocket: 'TL' }), outcome(open).build()), 'bad-declaration');
  });
});
