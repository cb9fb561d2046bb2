// Three-cushion carom, by the UMB rules of carom billiards (three-cushion discipline).
import { addFoul, opponent, specOfGame } from './common.ts';
import { caromMarks } from './marks.ts';
import { freeSpot, overlapping } from './placement.ts';
import type { ShotFacts } from './outcome.ts';
import type { Shot, ThreeCushionGame, Verdict } from './types.ts';

/** The shooter's own ball: the first player plays the white, the second the yellow (UMB). */
export function caromCueBall(g: ThreeCushionGame, player: string): 'white' | 'yellow' {
  return g.players[0] === player ? 'white' : 'yellow';
}

export interface CaromCount {
  /** Time the cue ball first met each object ball (absent: never). */
  firstContact: Map<string, number>;
  /** The object ball met second, if both were met. */
  second: string | null;
  /** Cushions the cue ball met before its first contact with the second object ball. */
  cushionsBeforeSecond: number;
  /** The first object ball met, if any. */
  first: string | null;
}

/**
 * Count a shot (UMB three-cushion: the cue ball must contact both object balls and, before it
 * contacts the second, at least three cushions; cushions met before the first object ball count).
 * Every cushion contact counts, also two on the same cushion. A cushion contact at the same
 * instant as the second ball contact does not come before it.
 */
export function countCarom(f: ShotFacts, cue: string): CaromCount {
  const firstContact = new Map<string, number>();
  let first: string | null = null;
  let second: string | null = null;
  for (const e of f.events) {
    if (e.kind !== 'ball' || !e.balls.includes(cue)) continue;
    const other = e.balls.find((id) => id !== cue);
    if (other === undefined || firstContact.has(other)) continue;
    firstContact.set(other, e.t);
    if (first === null) first = other;
    else {
      second = other;
      break;
    }
  }
  let cushionsBeforeSecond = 0;
  if (second !== null) {
    const t2 = firstContact.get(second) as number;
    for (const e of f.events) if (e.kind === 'cushion' && e.balls.includes(cue) && e.t < t2) cushionsBeforeSecond += 1;
  }
  return { firstContact, second, cushionsBeforeSecond, first };
}

export function judgeThreeCushion(g: ThreeCushionGame, shot: Shot, f: ShotFacts, v: Verdict): void {
  const shooter = shot.player;
  const other = opponent(g, shooter);
  const opening = g.shots === 0;
  const c = countCarom(f, shot.ball);
  g.balls = f.remaining;
  g.shots += 1;
  // UMB: on the opening shot the cue ball must meet the red first; otherwise it is a foul.
  if (opening && c.first !== 'red') addFoul(v, c.first === null ? 'no-contact' : 'break-red-first');
  if (f.pots.length > 0) {
    // Carom tables have no pockets: a ball reported gone has left the table, a foul.
    addFoul(v, 'ball-off-table');
    respotCarom(g, f.pots.map((p) => p.id), v);
  }
  const point = !v.foul && c.second !== null && c.cushionsBeforeSecond >= 3;
  if (point) {
    g.scores[shooter] = (g.scores[shooter] ?? 0) + 1;
    v.points[shooter] = 1;
    g.run += 1;
    g.highRun[shooter] = Math.max(g.highRun[shooter] ?? 0, g.run);
    v.continues = true;
    v.next = shooter;
    v.message = `point for ${shooter} (${c.cushionsBeforeSecond} cushions before the second ball; run ${g.run})`;
    if ((g.scores[shooter] ?? 0) >= g.raceTo) {
      g.winner = shooter;
      v.rackWinner = shooter;
      v.message += `; ${shooter} reaches ${g.raceTo} and wins`;
    }
    return;
  }
  // No point (or a foul): the inning ends and the opponent begins one (UMB: innings are counted).
  g.run = 0;
  g.turn = other;
  g.innings[other] = (g.innings[other] ?? 0) + 1;
  v.next = other;
  const why = v.foul
    ? `foul (${v.fouls.join(', ')})`
    : c.second === null
      ? c.first === null ? 'no object ball met' : 'only one object ball met'
      : `only ${c.cushionsBeforeSecond} cushion${c.cushionsBeforeSecond === 1 ? '' : 's'} before the second ball`;
  v.message = `no point for ${shooter}: ${why}; ${other} to play`;
}

/**
 * Put back the balls that left the table (UMB: a ball that leaves the table is spotted, the red on
 * the top spot and a cue ball on the head spot; when that spot is taken, the other spot, then the
 * centre spot; failing all three, the nearest free place).
 */
function respotCarom(g: ThreeCushionGame, ids: readonly string[], v: Verdict): void {
  const spec = specOfGame(g);
  const m = caromMarks(spec);
  const centre = { x: 0, y: 0 };
  for (const id of ids) {
    const order = id === 'red' ? [m.topSpot, m.headSpot, centre] : [m.headSpot, m.topSpot, centre];
    const spot = order.find((p) => overlapping(spec, g.balls, p, id) === null) ?? freeSpot(spec, g.balls, id, 'anywhere', m.headSpot);
    g.balls = [...g.balls.filter((b) => b.id !== id), { id, x: spot.x, y: spot.y }];
    v.spotted.push(id);
  }
}
