// A simple bot that plays a game to its end through a simulate() function: it aims the struck ball
// straight at the first of legalTargets(), makes the declarations the rules need, and shoots.
// Written for the real simulation (issue 4) once it exists; until then the tests drive it with
// the stand-in of rules-fake-sim.ts.
import {
  applyShot,
  cueBallId,
  legalTargets,
  sceneOf,
  strikeOf,
  type Ball,
  type Game,
  type Outcome,
  type PocketId,
  type Shot,
  type StrikeParams,
  type TableName,
} from '../../shared/rules/index.ts';
import { tableSpec } from '../../shared/physics/tables.ts';

export type Simulate = (scene: { table: TableName; balls: Ball[] }, shot: StrikeParams) => Outcome;

/** The pocket nearest to a point (by the naming of shared/rules/pockets.ts). */
export function nearestPocket(table: TableName, p: { x: number; y: number }): PocketId {
  const L = tableSpec(table).length;
  const end = p.x < -L / 6 ? 'B' : p.x > L / 6 ? 'T' : 'M';
  return `${end}${p.y >= 0 ? 'L' : 'R'}` as PocketId;
}

export function botShot(g: Game): Shot {
  const cueId = cueBallId(g);
  const cue = g.balls.find((b) => b.id === cueId)!;
  const targets = legalTargets(g);
  const targetId = targets[g.shots % Math.max(1, targets.length)] ?? targets[0];
  const target = g.balls.find((b) => b.id === targetId) ?? cue;
  // Tests may use Math.atan2: only shared/ must be bit-identical across engines.
  const heading = Math.atan2(target.y - cue.y, target.x - cue.x);
  const shot: Shot = { player: g.turn, ball: cueId, heading, speed: 1 + (g.shots % 13) / 10, side: 0, top: 0 };
  if (g.kind === 'eightball' && targetId === '8' && g.groups !== null) shot.calledPocket = nearestPocket(g.table, target);
  if (g.kind === 'snooker' && targetId !== undefined) {
    const onRed = g.on === 'red' && targetId.startsWith('red');
    const onColour = g.on === 'colour';
    const onIt = onRed || g.on === targetId;
    if (onColour || (g.freeBall && !onIt)) shot.nominated = targetId;
  }
  return shot;
}

/** Play until someone wins or maxShots shots were played; returns the final game and every game on the way. */
export function playToEnd(start: Game, simulate: Simulate, maxShots = 3000): { game: Game; history: Game[] } {
  let g = start;
  const history: Game[] = [g];
  for (let i = 0; i < maxShots && g.winner === null; i++) {
    const shot = botShot(g);
    const out = simulate(sceneOf(g), strikeOf(shot));
    g = applyShot(g, shot, out);
    history.push(g);
  }
  return { game: g, history };
}
