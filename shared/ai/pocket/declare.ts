// The declarations a stroke needs to be legal and to count: eight-ball's called pocket for the 8
// (WPA 3), snooker's nominated colour after a red and nominated free ball (WPBSA S3 R4, R12).
import { tableSpec } from '../../physics/index.ts';
import { legalTargets, type Game, type PocketId, type Shot } from '../../rules/index.ts';
import { dist, pocketAims } from './geometry.ts';

function snookerOn(game: Game & { kind: 'snooker' }, id: string): boolean {
  if (game.on === 'red') return id.startsWith('red');
  if (game.on === 'colour') return !id.startsWith('red') && id !== 'cue';
  return game.on === id;
}

/** `shot` with the declarations for playing `target` (into `pocket`, for a pot). */
export function declare(game: Game, target: string, pocket: string | undefined, shot: Shot): Shot {
  if (game.kind === 'eightball' && target === '8' && game.phase === 'play' && game.groups !== null) {
    const t = legalTargets(game);
    if (t.length !== 1 || t[0] !== '8') return shot;
    const eight = game.balls.find((b) => b.id === '8');
    let called = pocket;
    if (called === undefined && eight) {
      // A safety on the 8 still calls the nearest pocket: an 8 that drops uncalled loses.
      let best = Infinity;
      for (const p of pocketAims(tableSpec(game.table))) {
        const d = dist(eight, p.aim);
        if (d < best) {
          best = d;
          called = p.id;
        }
      }
    }
    return called === undefined ? shot : { ...shot, calledPocket: called as PocketId, calledBall: '8' };
  }
  if (game.kind === 'snooker') {
    const on = snookerOn(game, target);
    if (game.freeBall && !on) return { ...shot, nominated: target };
    if (!game.freeBall && game.on === 'colour') return { ...shot, nominated: target };
  }
  return shot;
}
