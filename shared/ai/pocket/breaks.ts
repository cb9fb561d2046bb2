// Opening strokes. Pool: from the kitchen, a full hit on the head ball of the rack at 8-9 m/s with
// a touch of draw to keep the cue ball central. Snooker: the standard break-off, from the D a thin
// contact on an end red of the back row with side, the cue ball coming back towards baulk.
import { detAtan2, tableSpec } from '../../physics/index.ts';
import { cueBallId, poolMarks, snookerMarks, type Ball, type Game } from '../../rules/index.ts';
import type { Candidate } from './candidates.ts';

export function isPoolBreak(game: Game): boolean {
  return (game.kind === 'nineball' || game.kind === 'eightball') && game.phase === 'break';
}

/** The snooker frame's first stroke: all fifteen reds and the cue ball in the D. */
export function isSnookerBreakOff(game: Game): boolean {
  return game.kind === 'snooker' && game.ballInHand === 'D' && game.balls.filter((b) => b.id.startsWith('red')).length === 15;
}

export function poolBreaks(game: Game, speed: number): Candidate[] {
  const spec = tableSpec(game.table);
  const cueId = cueBallId(game);
  const objects = game.balls.filter((b) => b.id !== cueId);
  let head: Ball | undefined;
  for (const b of objects) if (!head || b.x < head.x) head = b;
  if (!head) return [];
  const x = poolMarks(spec).headStringX - 0.05;
  const out: Candidate[] = [];
  for (const y of [0, 0.15, -0.15, 0.3, -0.3]) {
    const cueBall = { x, y };
    const heading = detAtan2(head.y - y, head.x - x);
    for (const top of [-0.15, 0.1]) out.push({ shot: { player: game.turn, ball: cueId, heading, speed, side: 0, top }, cueBall, prior: 0 });
  }
  return out;
}

export function snookerBreakOffs(game: Game): Candidate[] {
  const spec = tableSpec(game.table);
  const R = spec.ballRadius;
  const m = snookerMarks(spec);
  const cueId = cueBallId(game);
  const reds = game.balls.filter((b) => b.id.startsWith('red'));
  let back = -Infinity;
  for (const r of reds) back = Math.max(back, r.x);
  const out: Candidate[] = [];
  for (const sign of [-1, 1]) {
    // The end red of the back row on this side.
    let end: Ball | undefined;
    for (const r of reds) if (r.x > back - 1e-6 && (!end || sign * r.y > sign * end.y)) end = r;
    if (!end) continue;
    for (const y of [0.08, 0.16, 0.24]) {
      const cueBall = { x: m.baulkX, y: sign * y };
      for (const o of [1.55, 1.75, 1.9]) {
        const heading = detAtan2(end.y + sign * o * R - cueBall.y, end.x - cueBall.x);
        for (const speed of [2.8, 3.4, 4]) {
          for (const side of [0, -sign * 0.3]) out.push({ shot: { player: game.turn, ball: cueId, heading, speed, side, top: 0 }, cueBall, prior: 0 });
        }
      }
    }
  }
  return out;
}
