// The tray of pocketed balls: a list named "Pocketed" of the object balls down, in the order they
// went, each drawn small in its colour with its number and carrying its id (data-ball). What is down
// comes from the game's state (so it is right after a reconnect); the order from the pots seen here.
import { POOL_OBJECT_BALLS, SNOOKER_COLOURS, SNOOKER_REDS, type Game } from '../../shared/rules/index.ts';
import { h } from '../dom.ts';
import { ballLook, IVORY } from './ball-look.ts';

/** The object balls a game's rack starts with (pocketed ones are those of these not on the table). */
export function rackOf(game: Game): readonly string[] {
  const layout = game.kind === 'practice' ? game.layout : game.kind;
  if (layout === 'nineball') return POOL_OBJECT_BALLS.slice(0, 9);
  if (layout === 'eightball') return POOL_OBJECT_BALLS;
  if (layout === 'snooker') return [...SNOOKER_REDS, ...SNOOKER_COLOURS];
  return [];
}

/**
 * The game's pocketed balls, in the order of `order` (ids as they went down, latest last) where it
 * knows them, then in rack order. A ball back on the table (spotted, a new rack) is not pocketed.
 */
export function pocketedBalls(game: Game, order: readonly string[] = []): string[] {
  const on = new Set(game.balls.map((b) => b.id));
  const down = rackOf(game).filter((id) => !on.has(id));
  const at = (id: string) => {
    const k = order.lastIndexOf(id);
    return k < 0 ? -1 : k;
  };
  // Stable: balls the order does not know (down before this page opened) keep rack order, first.
  return down.map((id, i) => ({ id, i, k: at(id) })).sort((a, b) => a.k - b.k || a.i - b.i).map((x) => x.id);
}

export class Tray {
  readonly element: HTMLUListElement = h('ul', { className: 'tray', 'aria-label': 'Pocketed' });
  private shown = '';

  /** Shows these balls (ids in order); hidden where the game pockets nothing. */
  set(ids: readonly string[], pockets = true): void {
    this.element.hidden = !pockets;
    const key = ids.join(',');
    if (key === this.shown) return;
    this.shown = key;
    this.element.replaceChildren(...ids.map(trayBall));
  }

  /** From the game's state, ordered as the animator saw the balls go down. */
  update(game: Game, order: readonly string[] = []): void {
    this.set(pocketedBalls(game, order), rackOf(game).length > 0);
  }
}

function trayBall(id: string): HTMLLIElement {
  const look = ballLook(id);
  const face = look.stripe
    ? `linear-gradient(${IVORY} 0 22%, ${look.colour} 22% 78%, ${IVORY} 78%)`
    : look.colour;
  const ball = h('span', { className: 'tray-ball', 'aria-hidden': 'true' }, look.number !== null ? h('span', {}, look.number) : null);
  ball.style.background = `radial-gradient(circle at 35% 30%, rgba(255,255,255,0.55), rgba(255,255,255,0) 45%, rgba(0,0,0,0.35) 100%), ${face}`;
  return h('li', { 'data-ball': id, 'aria-label': id, title: id }, ball);
}
