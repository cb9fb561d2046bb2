// A simple bot strategy. The "sound" mode plays a game to its end through the real simulate(): for
// each shot it tries a short, fixed list of candidate shots (for pool and snooker the ghost-ball aim
// of each legal target into each pocket, for carom a fan of headings with side), simulates each,
// asks the referee what it would be worth, and plays the best. The "quick" mode, for load tests,
// simulates nothing: one ghost-ball aim (or one carom heading) that the referee accepts as legal.
// Deterministic: the same game gives the same shots.
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
  type Point,
  type Shot,
  type StrikeParams,
  type TableName,
} from '../shared/rules/index.ts';
import { tableSpec } from '../shared/physics/index.ts';

export type Simulate = (scene: { table: TableName; balls: Ball[] }, shot: StrikeParams) => Outcome;

/** The referee's verdict on a candidate, as one number: winning, points, keeping the table, no foul. */
function worth(g: Game, next: Game): number {
  const me = g.turn;
  if (next.winner !== null) return next.winner === me ? 1e6 : -1e6;
  const gained = (next.scores[me] ?? 0) - (g.scores[me] ?? 0);
  const lost = Object.entries(next.scores).reduce((s, [p, v]) => (p === me ? s : s + v - (g.scores[p] ?? 0)), 0);
  const foul = next.verdict?.foul ? 1 : 0;
  return 100 * gained - 100 * lost + (next.turn === me ? 10 : 0) - 20 * foul;
}

function declarations(g: Game, targetId: string | undefined, pocket: PocketId | undefined, shot: Shot): Shot {
  if (g.kind === 'eightball' && targetId === '8' && g.groups !== null) shot.calledPocket = pocket ?? 'TL';
  if (g.kind === 'snooker' && targetId !== undefined) {
    const onRed = g.on === 'red' && targetId.startsWith('red');
    const onIt = onRed || g.on === targetId;
    if (g.on === 'colour' || (g.freeBall && !onIt)) shot.nominated = targetId;
  }
  return shot;
}

/** The heading that sends the cue ball to the ghost ball: touching `b` on the far side from the pocket. */
function ghostBallHeading(cue: Point, b: Point, p: Point, R: number): number {
  const dx = p.x - b.x;
  const dy = p.y - b.y;
  const d = Math.hypot(dx, dy);
  const gx = b.x - (2 * R * dx) / d;
  const gy = b.y - (2 * R * dy) / d;
  return Math.atan2(gy - cue.y, gx - cue.x);
}

/** The candidate shots for the player on turn. */
export function candidates(g: Game): Shot[] {
  const t = tableSpec(g.table);
  const R = t.ballRadius;
  const cueId = cueBallId(g);
  const cue = g.balls.find((b) => b.id === cueId)!;
  const base = { player: g.turn, ball: cueId, side: 0, top: 0 };
  const out: Shot[] = [];
  if (g.kind === 'threecushion') {
    // A fan of headings at two speeds with running side: some go round the table.
    for (let i = 0; i < 24; i++) {
      const heading = (2 * Math.PI * (i + 0.5 * (g.shots % 2))) / 24;
      out.push({ ...base, heading, speed: 3.5, side: i % 2 ? 0.3 : -0.3 });
    }
    return out;
  }
  const targets = legalTargets(g).slice(0, 3);
  for (const id of targets) {
    const b = g.balls.find((x) => x.id === id);
    if (!b) continue;
    for (const p of t.pockets) {
      const heading = ghostBallHeading(cue, b, p, R);
      for (const speed of [1.6, 3]) out.push(declarations(g, id, p.id as PocketId, { ...base, heading, speed }));
    }
    out.push(declarations(g, id, undefined, { ...base, heading: Math.atan2(b.y - cue.y, b.x - cue.x), speed: 2 }));
  }
  if (out.length === 0) out.push({ ...base, heading: (g.shots % 12) * (Math.PI / 6), speed: 2 });
  return out;
}

export function botShot(g: Game, simulate: Simulate): { shot: Shot; outcome: Outcome } {
  let best: { shot: Shot; outcome: Outcome; value: number } | undefined;
  const scene = sceneOf(g);
  for (const shot of candidates(g)) {
    let outcome: Outcome;
    let next: Game;
    try {
      outcome = simulate(scene, strikeOf(shot));
      next = applyShot(g, shot, outcome);
    } catch {
      continue; // a candidate the referee refuses (say, a declaration that does not apply)
    }
    const value = worth(g, next);
    if (!best || value > best.value) best = { shot, outcome, value };
  }
  if (!best) throw new Error(`bot found no playable shot at shot ${g.shots}`);
  return best;
}

/** Play until someone wins or maxShots shots were played; returns the final game and every game on the way. */
export function playToEnd(start: Game, simulate: Simulate, maxShots = 1500): { game: Game; history: Game[] } {
  let g = start;
  const history: Game[] = [g];
  for (let i = 0; i < maxShots && g.winner === null; i++) {
    const { shot, outcome } = botShot(g, simulate);
    g = applyShot(g, shot, outcome);
    history.push(g);
  }
  return { game: g, history };
}

/** "sound": simulate the candidates and play the best; "quick": one legal aim, nothing simulated. */
export type BotMode = 'sound' | 'quick';

/** A cut steeper than this rarely pots: such a pocket is tried only after the others. */
const STEEP_CUT = (75 * Math.PI) / 180;

/** Whether the referee takes the shot (turn, ball struck, declarations), judged against a stroke that moves nothing. */
function acceptable(g: Game, shot: Shot): boolean {
  const still = { balls: g.balls.map((b) => ({ id: b.id, x: b.x, y: b.y, pocketed: false })), events: [] };
  try {
    applyShot(g, shot, still);
    return true;
  } catch {
    return false;
  }
}

/**
 * The quick mode's candidates, most promising first, none simulated: for pool and snooker each
 * legal target into its pockets, nearest first (steep cuts last), or straight at it on a break; for
 * three-cushion a half-ball hit on each object ball, the red first (it must be first on the opening).
 */
export function quickCandidates(g: Game): Shot[] {
  const t = tableSpec(g.table);
  const R = t.ballRadius;
  const cueId = cueBallId(g);
  const cue = g.balls.find((b) => b.id === cueId)!;
  const base = { player: g.turn, ball: cueId, side: 0, top: 0 };
  const targets = legalTargets(g)
    .map((id) => g.balls.find((b) => b.id === id))
    .filter((b): b is Ball => b !== undefined);
  if (g.kind === 'threecushion') {
    targets.sort((a, b) => Number(b.id === 'red') - Number(a.id === 'red'));
    return targets.map((b) => {
      const d = Math.hypot(b.x - cue.x, b.y - cue.y);
      const heading = Math.atan2(b.y - cue.y, b.x - cue.x) + Math.asin(Math.min(1, R / d));
      return { ...base, heading, speed: 3.5, side: 0.3 };
    });
  }
  const out: Shot[] = [];
  const breaking = (g.kind === 'nineball' || g.kind === 'eightball') && g.phase === 'break';
  for (const b of targets) {
    const straight = Math.atan2(b.y - cue.y, b.x - cue.x);
    if (breaking) {
      out.push({ ...base, heading: straight, speed: 8 });
      continue;
    }
    const pockets = t.pockets
      .map((p) => {
        const heading = ghostBallHeading(cue, b, p, R);
        const toPocket = Math.atan2(p.y - b.y, p.x - b.x);
        const cut = Math.abs(Math.atan2(Math.sin(toPocket - heading), Math.cos(toPocket - heading)));
        return { p, heading, rank: Math.hypot(p.x - b.x, p.y - b.y) + (cut > STEEP_CUT ? 100 : 0) };
      })
      .sort((a, b2) => a.rank - b2.rank);
    for (const { p, heading } of pockets) out.push(declarations(g, b.id, p.id as PocketId, { ...base, heading, speed: 2.5 }));
    out.push(declarations(g, b.id, undefined, { ...base, heading: straight, speed: 2 }));
  }
  return out;
}

/**
 * The quick mode's shot: the first candidate the referee accepts, starting at `attempt` (a retry
 * after the server refused one moves on to the next). Falls back to a plain stroke round the table.
 */
export function quickShot(g: Game, attempt = 0): Shot {
  const list = quickCandidates(g);
  for (let i = 0; i < list.length; i++) {
    const shot = list[(attempt + i) % list.length]!;
    if (acceptable(g, shot)) return shot;
  }
  return { player: g.turn, ball: cueBallId(g), heading: ((g.shots + attempt) % 12) * (Math.PI / 6), speed: 2, side: 0, top: 0 };
}

/** The shot the bot plays in the given mode; a retry (attempt > 0) goes to the quick candidates, as the sound pick was refused. */
export function chooseShot(g: Game, mode: BotMode, simulate: Simulate, attempt = 0): Shot {
  if (mode === 'quick' || attempt > 0) return quickShot(g, attempt);
  return botShot(g, simulate).shot;
}
