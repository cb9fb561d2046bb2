// Who the computer is at the table: its name per level, the seed of each decision, and the simple
// legal stroke it plays when its search fails (a worker too slow or crashed).
import { detAtan2 } from '../../shared/physics/index.ts';
import { cueBallId, legalTargets, type Game, type Shot } from '../../shared/rules/index.ts';
import type { Decision, Level } from '../../shared/ai/index.ts';

/** The stored player's name at a level: "Computer (level 3)". */
export function computerName(level: Level): string {
  return `Computer (level ${level})`;
}

/** Names a person may not take: the computer's, in any case or spacing. */
export function looksLikeComputer(name: string): boolean {
  return /^\s*computer\s*\(\s*level\s*\d+\s*\)\s*$/i.test(name);
}

/**
 * The seed of the decision at a room's state: FNV-1a of the room id, the match and the state id,
 * so that a replayed position gets the same decision and no two rooms share their draws.
 */
export function decisionSeed(roomId: string, matchId: number | null, stateId: number): number {
  let h = 0x811c9dc5;
  for (const c of `${roomId}:${matchId ?? 0}:${stateId}`) {
    h ^= c.charCodeAt(0);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h >>> 0;
}

/**
 * A legal stroke without search: straight at the first ball the rules allow, at a moderate pace,
 * with the declarations the rules ask for. The server still validates and simulates it.
 */
export function fallbackDecision(game: Game): Decision {
  if (game.choices.includes('pass') && game.kind === 'nineball') return { choice: 'pass' };
  const cueId = cueBallId(game);
  const cue = game.balls.find((b) => b.id === cueId)!;
  const targets = legalTargets(game);
  const target = game.balls.find((b) => targets.includes(b.id) && b.id !== cueId) ?? game.balls.find((b) => b.id !== cueId);
  const heading = target ? detAtan2(target.y - cue.y, target.x - cue.x) : 0;
  const shot: Omit<Shot, 'player'> & { player: string } = { player: game.turn, ball: cueId, heading, speed: 2, side: 0, top: 0 };
  if (game.kind === 'eightball' && target?.id === '8') return { shot: { ...shot, calledPocket: 'TL', calledBall: '8' } };
  if (game.kind === 'snooker' && target && target.id !== 'red' && !target.id.startsWith('red')) return { shot: { ...shot, nominated: target.id } };
  return { shot };
}
