// The headings of the coarse search, in angular order so that neighbours in the list are
// neighbours on the table: contact points across each object ball (from a thin hit on one side,
// through full, to a thin hit on the other: the cue ball's deflection, hence its path round the
// table, follows the cut, as in the ghost-ball method), and an even fan all round for bank-first
// paths and round-the-table kicks.
import { detAtan2, tableSpec } from '../../physics/index.ts';
import { cueBallId, type Game } from '../../rules/index.ts';

const TAU = 2 * Math.PI;

/** Headings in [0, 2π), sorted, none closer than MIN_GAP to the one before. */
export function coarseHeadings(game: Game, step: number, cuts: number): number[] {
  const R = tableSpec(game.table).ballRadius;
  const cueId = cueBallId(game);
  const cue = game.balls.find((b) => b.id === cueId);
  const out: number[] = [];
  const fan = Math.max(1, Math.round(TAU / step));
  for (let i = 0; i < fan; i++) out.push((TAU * (i + 0.5)) / fan);
  if (cue) {
    for (const b of game.balls) {
      if (b.id === cueId) continue;
      const dx = b.x - cue.x;
      const dy = b.y - cue.y;
      const d = Math.sqrt(dx * dx + dy * dy);
      if (d <= 2 * R) continue;
      const toward = detAtan2(dy, dx);
      // Contact offsets b = f * 2R, f in (-1, 1): the heading turns by asin(b / d) off the centre line.
      for (let k = 0; k < 2 * cuts; k++) {
        const f = -1 + (k + 0.5) / cuts;
        const off = f * 2 * R;
        out.push(wrap(toward + detAtan2(off, Math.sqrt(d * d - off * off))));
      }
    }
  }
  out.sort((a, b) => a - b);
  const kept: number[] = [];
  for (const h of out) if (kept.length === 0 || h - kept[kept.length - 1]! > MIN_GAP) kept.push(h);
  return kept;
}

/** Headings closer than this (radians) are one heading. */
const MIN_GAP = 1e-4;

function wrap(a: number): number {
  let r = a;
  while (r < 0) r += TAU;
  while (r >= TAU) r -= TAU;
  return r;
}
