// Nine-ball, eight-ball and snooker: choices, breaks, the ball in hand's place, then a search over
// geometric candidates (pots with speeds and spins, banks, safeties, kicks) played through the real
// simulation and referee under the level's noise (see docs/ai.md).
import { cueBallId, legalTargets, type Game, type Point } from '../../rules/index.ts';
import { detAtan2 } from '../../physics/index.ts';
import type { Context } from '../context.ts';
import type { Decision } from '../types.ts';
import { isPoolBreak, isSnookerBreakOff, poolBreaks, snookerBreakOffs } from './breaks.ts';
import { pots, potStrokes, pushOutStrokes, safetyStrokes, type Candidate } from './candidates.ts';
import { takeChoice } from './choices.ts';
import { placements } from './placement.ts';
import { search } from './search.ts';
import { positionSigma } from './value.ts';

/** The stroke the search chooses, as aimed (index.ts adds the hand's noise). */
export function choosePocketShot(game: Game, ctx: Context): Decision {
  const sigma = positionSigma(ctx.level.heading);
  const choice = takeChoice(game, sigma, ctx.level.heading);
  if (choice) return { choice };
  const level = ctx.level;
  const candidates: Candidate[] = [];
  if (isPoolBreak(game)) {
    candidates.push(...poolBreaks(game, 7 + 0.4 * (level.samples > 4 ? 4 : level.samples)));
  } else {
    if (isSnookerBreakOff(game)) candidates.push(...snookerBreakOffs(game));
    const cueId = cueBallId(game);
    const here = game.balls.find((b) => b.id === cueId)!;
    const places: (Point | undefined)[] = game.ballInHand === false ? [undefined] : placements(game, sigma, level.spots);
    const rankSigma = Math.max(level.heading, 0.002);
    places.forEach((cueBall, i) => {
      const cue = cueBall ?? here;
      for (const pot of pots(game, cue, rankSigma, level.banks).slice(0, level.pots)) candidates.push(...potStrokes(game, pot, cue, level.variants, cueBall));
      if (i < 2) candidates.push(...safetyStrokes(game, cue, level.safeties, cueBall));
      if (i === 0) candidates.push(...pushOutStrokes(game, cue, Math.ceil(level.safeties / 2), cueBall));
    });
    if (candidates.length === 0) candidates.push(...fallback(game, places[0], here));
  }
  const best = search(game, candidates, ctx);
  const pick = best ?? { shot: candidates[0]!.shot, candidate: candidates[0]! };
  const shot = pick.shot;
  const cueBall = pick.candidate.cueBall;
  return cueBall ? { shot, cueBall } : { shot };
}

/** A plain stroke at the first legal ball: only when nothing else was generated. */
function fallback(game: Game, cueBall: Point | undefined, here: Point): Candidate[] {
  const cue = cueBall ?? here;
  const target = legalTargets(game)
    .map((id) => game.balls.find((b) => b.id === id))
    .find((b) => b !== undefined);
  const heading = target ? detAtan2(target.y - cue.y, target.x - cue.x) : 0;
  return [{ shot: { player: game.turn, ball: cueBallId(game), heading, speed: 2, side: 0, top: 0 }, cueBall, prior: 0 }];
}
