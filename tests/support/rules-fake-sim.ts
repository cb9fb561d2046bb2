// A stand-in for simulate() (issue 4) in the referee tests: no physics at all, only the shape of
// its result. The struck ball meets the first ball on its line; a hash of the scene and the shot
// decides, deterministically, whether that ball drops (in the nearest pocket), goes to a cushion
// and moves elsewhere, whether the cue ball follows it in, and on the carom table whether the cue
// ball goes three cushions to the other ball.
import { tableSpec } from '../../shared/physics/tables.ts';
import { placementProblem } from '../../shared/rules/index.ts';
import type { Ball, Outcome, OutcomeEvent, StrikeParams, TableName } from '../../shared/rules/index.ts';
import { nearestPocket } from './rules-bot.ts';

function hash(values: number[]): number {
  let h = 0x811c9dc5;
  for (const v of values) {
    h ^= Math.round(v * 1e6) | 0;
    h = Math.imul(h, 0x01000193) >>> 0;
    h ^= h >>> 15;
  }
  return h >>> 0;
}

export function fakeSimulate(scene: { table: TableName; balls: Ball[] }, shot: StrikeParams): Outcome {
  const spec = tableSpec(scene.table);
  const R = spec.ballRadius;
  const cue = scene.balls.find((b) => b.id === shot.ball)!;
  const dx = Math.cos(shot.heading);
  const dy = Math.sin(shot.heading);
  let first: Ball | null = null;
  let best = Infinity;
  for (const b of scene.balls) {
    if (b.id === cue.id) continue;
    const along = (b.x - cue.x) * dx + (b.y - cue.y) * dy;
    const d2 = (b.x - cue.x) ** 2 + (b.y - cue.y) ** 2;
    if (along > 0 && d2 - along * along < 4 * R * R && along < best) {
      best = along;
      first = b;
    }
  }
  let h = hash([shot.heading, shot.speed, ...scene.balls.flatMap((b) => [b.x, b.y])]);
  const roll = (n: number): number => {
    h = Math.imul(h ^ (h >>> 13), 0x5bd1e995) >>> 0;
    return h % n;
  };
  const events: OutcomeEvent[] = [];
  let t = 0;
  const at = () => (t += 0.1);
  const finals = new Map(scene.balls.map((b) => [b.id, { x: b.x, y: b.y }]));
  const pockets = new Map<string, string>();
  if (first === null) {
    events.push({ t: at(), kind: 'cushion', balls: [cue.id] }, { t: at(), kind: 'cushion', balls: [cue.id] });
  } else {
    events.push({ t: at(), kind: 'ball', balls: [cue.id, first.id] });
    if (scene.table === 'carom-match') {
      const other = scene.balls.find((b) => b.id !== cue.id && b.id !== first!.id)!;
      const cushions = roll(100) < 45 ? 3 : roll(3);
      for (let i = 0; i < cushions; i++) events.push({ t: at(), kind: 'cushion', balls: [cue.id] });
      events.push({ t: at(), kind: 'ball', balls: [cue.id, other.id] });
    } else if (roll(100) < 55) {
      const pocket = nearestPocket(scene.table, first);
      events.push({ t: at(), kind: 'pocket', balls: [first.id], pocket });
      pockets.set(first.id, pocket);
      finals.set(cue.id, { x: first.x, y: first.y });
      if (roll(100) < 6) {
        events.push({ t: at(), kind: 'pocket', balls: [cue.id], pocket });
        pockets.set(cue.id, pocket);
      }
    } else {
      events.push({ t: at(), kind: 'cushion', balls: [first.id] });
    }
    if (!pockets.has(first.id)) {
      // the met ball ends somewhere else on the bed, clear of the others
      for (let k = 0; k < 50; k++) {
        const p = { x: ((roll(1000) / 1000) - 0.5) * (spec.length - 4 * R), y: ((roll(1000) / 1000) - 0.5) * (spec.width - 4 * R) };
        const others = scene.balls.filter((b) => b.id !== first!.id).map((b) => ({ id: b.id, ...finals.get(b.id)! }));
        if (placementProblem(spec, others, first.id, p, 'anywhere') === null) {
          finals.set(first.id, p);
          break;
        }
      }
    }
  }
  return {
    balls: scene.balls.map((b) => {
      const f = finals.get(b.id)!;
      const pocket = pockets.get(b.id);
      return pocket ? { id: b.id, x: f.x, y: f.y, pocketed: true, pocket } : { id: b.id, x: f.x, y: f.y, pocketed: false };
    }),
    events,
  };
}
