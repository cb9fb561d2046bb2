// Property tests: random (but well-formed) outcomes fed to every referee.
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/tables.ts';
import {
  applyShot,
  cueBallId,
  decide,
  newGame,
  placementProblem,
  POCKETS,
  type Game,
  type GameKind,
  type Outcome,
  type OutcomeEvent,
  type Shot,
  type SnookerGame,
} from '../../../shared/rules/index.ts';
import { onTheEight } from '../../../shared/rules/eightball.ts';
import { deepFreeze } from '../../support/rules-outcome.ts';

interface Step {
  events: Array<{ kind: number; a: number; b: number; pocket: number; cueFirst: boolean }>;
  moves: Array<{ ball: number; x: number; y: number }>;
  choice: number;
  declare: number;
}

const stepArb: fc.Arbitrary<Step> = fc.record({
  events: fc.array(
    fc.record({
      kind: fc.integer({ min: 0, max: 5 }),
      a: fc.nat(40),
      b: fc.nat(40),
      pocket: fc.nat(5),
      cueFirst: fc.boolean(),
    }),
    { maxLength: 10 },
  ),
  moves: fc.array(fc.record({ ball: fc.nat(40), x: fc.double({ min: -0.45, max: 0.45, noNaN: true }), y: fc.double({ min: -0.45, max: 0.45, noNaN: true }) }), { maxLength: 3 }),
  choice: fc.nat(3),
  declare: fc.nat(7),
});

/** Build a well-formed outcome for `game` from a recipe: events on balls that are on the table. */
function outcomeFrom(game: Game, step: Step): Outcome {
  const ids = game.balls.map((b) => b.id);
  const cue = cueBallId(game);
  const spec = tableSpec(game.table);
  const events: OutcomeEvent[] = [];
  const potted = new Map<string, string>();
  let t = 0;
  for (const e of step.events) {
    t += 0.25;
    const a = e.cueFirst ? cue : (ids[e.a % ids.length] as string);
    const b = ids[e.b % ids.length] as string;
    if (e.kind <= 2) {
      if (a !== b && !potted.has(a) && !potted.has(b)) events.push({ t, kind: 'ball', balls: [a, b] });
    } else if (e.kind <= 4) {
      if (!potted.has(a)) events.push({ t, kind: 'cushion', balls: [a] });
    } else if (!potted.has(b)) {
      const pocket = POCKETS[e.pocket % POCKETS.length] as string;
      potted.set(b, pocket);
      events.push({ t, kind: 'pocket', balls: [b], pocket });
    }
  }
  // Final positions: the same, except a few balls moved to a free place on the bed (scaled).
  const finals = new Map(game.balls.map((b) => [b.id, { x: b.x, y: b.y }]));
  for (const mv of step.moves) {
    const id = ids[mv.ball % ids.length] as string;
    const p = { x: mv.x * spec.length, y: mv.y * spec.width };
    const others = game.balls.filter((b) => b.id !== id).map((b) => ({ id: b.id, ...finals.get(b.id)! }));
    if (placementProblem(spec, others, id, p, 'anywhere') === null) finals.set(id, p);
  }
  return {
    balls: game.balls.map((b) => {
      const f = finals.get(b.id)!;
      const pocket = potted.get(b.id);
      return pocket ? { id: b.id, x: f.x, y: f.y, pocketed: true, pocket } : { id: b.id, x: f.x, y: f.y, pocketed: false };
    }),
    events,
  };
}

function shotFrom(game: Game, step: Step): Shot {
  const shot: Shot = { player: game.turn, ball: cueBallId(game), heading: 0.5, speed: 3, side: 0, top: 0 };
  if (game.kind === 'nineball' && game.phase === 'push-out' && step.declare === 0) shot.pushOut = true;
  if (game.kind === 'eightball' && onTheEight(game) && step.declare < 6) shot.calledPocket = POCKETS[step.declare]!;
  if (game.kind === 'snooker' && game.freeBall && step.declare < 4) {
    const notOn = game.balls.filter((b) => b.id !== 'cue' && (game.on === 'red' ? !b.id.startsWith('red') : b.id !== game.on));
    const n = notOn[step.declare % Math.max(1, notOn.length)];
    if (n) shot.nominated = n.id;
  }
  return shot;
}

/** Play a random game for up to `steps.length` shots; hands every step to `check`. */
function playRandom(kind: GameKind, seed: number, steps: Step[], check: (before: Game, after: Game) => void): Game {
  let g: Game = newGame(kind, kind === 'practice' ? ['p'] : ['a', 'b'], { seed, raceTo: 3 });
  for (const step of steps) {
    if (g.winner !== null) break;
    if (g.choices.length > 0 && step.choice < g.choices.length) {
      g = decide(g, g.turn, g.choices[step.choice]!);
      continue;
    }
    const before = deepFreeze(structuredClone(g));
    const shot = deepFreeze(shotFrom(before, step));
    const out = deepFreeze(outcomeFrom(before, step));
    const json = JSON.stringify([before, shot, out]);
    const after = applyShot(before, shot, out);
    expect(JSON.stringify([before, shot, out])).toBe(json); // inputs untouched (and frozen)
    expect(JSON.parse(JSON.stringify(after))).toEqual(after); // plain JSON data
    check(before, after);
    g = after;
  }
  return g;
}

const sum = (r: Record<string, number>): number => Object.values(r).reduce((a, b) => a + b, 0);
const kinds: GameKind[] = ['nineball', 'eightball', 'snooker', 'threecushion', 'practice'];

describe('referee properties (fast-check)', () => {
  it.each(kinds)('%s: inputs are never mutated, outputs are JSON, balls stay legal and unique', (kind) => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 2 ** 31 - 1 }), fc.array(stepArb, { minLength: 1, maxLength: 25 }), (seed, steps) => {
        playRandom(kind, seed, steps, (_before, after) => {
          const ids = after.balls.map((b) => b.id);
          expect(new Set(ids).size).toBe(ids.length);
          expect(after.verdict).not.toBeNull();
          expect(after.verdict?.next).toBe(after.turn);
          for (const s of Object.values(after.scores)) expect(s).toBeGreaterThanOrEqual(0);
          if (after.ballInHand !== false) {
            const spec = tableSpec(after.table);
            const cue = after.balls.find((b) => b.id === cueBallId(after));
            expect(cue).toBeDefined();
            expect(placementProblem(spec, after.balls, cue!.id, cue!, after.ballInHand)).toBeNull();
          }
        });
      }),
      { numRuns: 150 },
    );
  });

  it('three-cushion: scores never decrease, move by the verdict points, and innings follow the turns', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 1000 }), fc.array(stepArb, { minLength: 1, maxLength: 40 }), (seed, steps) => {
        let turnsChanged = 0;
        const end = playRandom('threecushion', seed, steps, (before, after) => {
          expect(after.balls.map((b) => b.id).sort()).toEqual(['red', 'white', 'yellow']); // balls off the table come back
          for (const p of after.players) expect(after.scores[p]!).toBeGreaterThanOrEqual(before.scores[p]!);
          expect(sum(after.scores) - sum(before.scores)).toBe(sum(after.verdict!.points));
          expect(sum(after.verdict!.points)).toBeLessThanOrEqual(1);
          if (after.turn !== before.turn) turnsChanged += 1;
        });
        if (end.kind === 'threecushion') expect(sum(end.innings)).toBe(1 + turnsChanged);
      }),
      { numRuns: 200 },
    );
  });

  it('snooker: points are conserved (scores move by the verdict points), reds never come back, fouls give at least 4', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 1000 }), fc.array(stepArb, { minLength: 1, maxLength: 40 }), (seed, steps) => {
        playRandom('snooker', seed, steps, (before, after) => {
          const v = after.verdict!;
          expect(sum(after.scores) - sum(before.scores)).toBe(sum(v.points));
          const reds = (g: Game) => g.balls.filter((b) => b.id.startsWith('red')).length;
          expect(reds(after)).toBeLessThanOrEqual(reds(before));
          if (v.foul) {
            const other = after.players.find((p) => p !== v.player)!;
            expect(v.points[other]).toBeGreaterThanOrEqual(4);
            expect(v.points[other]).toBeLessThanOrEqual(7);
            expect(v.points[v.player]).toBe(0);
          }
          const s = after as SnookerGame;
          if (s.winner === null) expect(s.balls.some((b) => b.id === 'cue')).toBe(true);
        });
      }),
      { numRuns: 200 },
    );
  });

  it('the same seed and the same shots give the same game; the seed changes the rack', () => {
    fc.assert(
      fc.property(fc.integer({ min: 0, max: 1000 }), fc.array(stepArb, { minLength: 1, maxLength: 15 }), (seed, steps) => {
        const a = playRandom('eightball', seed, steps, () => {});
        const b = playRandom('eightball', seed, steps, () => {});
        expect(a).toEqual(b);
      }),
      { numRuns: 50 },
    );
  });
});
