// Where to put the ball in hand: behind each promising pot at a comfortable distance and a slight
// cut (a dead-straight pot leaves no angle to move the cue ball), plus a grid of the legal area,
// each scored by the best geometric pot from there. Every place returned passes placementProblem.
import { tableSpec } from '../../physics/index.ts';
import { cueBallId, legalTargets, placementProblem, snookerMarks, type Ball, type Game, type Point } from '../../rules/index.ts';
import { pocketAims } from './geometry.ts';
import { chanceFrom } from './position.ts';

const DISTANCES = [0.3, 0.55];
/** Sines and cosines of cut angles 0, +-12, +-25 degrees. */
const CUTS: readonly [number, number][] = [
  [0.2079, 0.9781],
  [-0.2079, 0.9781],
  [0.4226, 0.9063],
  [-0.4226, 0.9063],
  [0, 1],
];

export function placements(game: Game, sigma: number, count: number): Point[] {
  const area = game.ballInHand;
  if (area === false) return [];
  const spec = tableSpec(game.table);
  const id = cueBallId(game);
  const R = spec.ballRadius;
  const spots: Point[] = [];
  for (const tid of legalTargets(game)) {
    const t = game.balls.find((b) => b.id === tid);
    if (!t) continue;
    for (const pk of pocketAims(spec)) {
      const dx = pk.aim.x - t.x;
      const dy = pk.aim.y - t.y;
      const d = Math.sqrt(dx * dx + dy * dy);
      if (d < 1e-6) continue;
      const ux = dx / d;
      const uy = dy / d;
      const gx = t.x - 2 * R * ux;
      const gy = t.y - 2 * R * uy;
      for (const [s, c] of CUTS) {
        const vx = ux * c - uy * s;
        const vy = ux * s + uy * c;
        for (const D of DISTANCES) spots.push({ x: gx - vx * D, y: gy - vy * D });
      }
    }
  }
  // A grid over the area, for the kitchen and the D where the spots behind the balls fall outside.
  const nx = 12;
  const ny = 7;
  for (let i = 0; i < nx; i++)
    for (let j = 0; j < ny; j++)
      spots.push({ x: -spec.length / 2 + ((i + 0.5) * spec.length) / nx, y: -spec.width / 2 + R + ((j + 0.5) * (spec.width - 2 * R)) / ny });
  if (area === 'D') {
    const m = snookerMarks(spec);
    for (let i = 0; i <= 8; i++) for (let j = -4; j <= 4; j++) spots.push({ x: m.baulkX - (i * m.dRadius) / 8, y: (j * m.dRadius) / 4.2 });
  }
  if (area === 'kitchen') {
    for (let i = 0; i < 5; i++) for (let j = -6; j <= 6; j++) spots.push({ x: -spec.length / 4 - 0.02 - (i * (spec.length / 4 - 0.05)) / 5, y: (j * (spec.width / 2 - 2 * R)) / 6 });
  }
  const scored: { p: Point; v: number }[] = [];
  for (const p of spots) {
    if (placementProblem(spec, game.balls, id, p, area) !== null) continue;
    const v = chanceFrom(game, { id, x: p.x, y: p.y } as Ball, sigma);
    scored.push({ p, v });
  }
  scored.sort((a, b) => b.v - a.v);
  const out: Point[] = [];
  for (const s of scored) {
    if (out.length >= count) break;
    // Keep the places apart, so the search sees different shots.
    if (out.some((q) => (q.x - s.p.x) * (q.x - s.p.x) + (q.y - s.p.y) * (q.y - s.p.y) < 0.01)) continue;
    out.push(s.p);
  }
  if (out.length === 0) {
    const cue = game.balls.find((b) => b.id === id);
    if (cue && placementProblem(spec, game.balls, id, cue, area) === null) out.push({ x: cue.x, y: cue.y });
    else if (scored.length > 0) out.push(scored[0]!.p);
  }
  return out;
}
