// The end of a game: what the result dialog says (pure), and the dialog itself.
import type { RoomView } from '../../shared/protocol/index.ts';
import type { Game, PlayerId } from '../../shared/rules/index.ts';
import { h } from '../dom.ts';

/** A player's rating in this game kind before and after the match (undefined until known). */
export interface RatingChange {
  readonly before?: number;
  readonly after?: number;
}

export interface ResultContent {
  readonly heading: string;
  /** The score, e.g. "Ann 3 – 1 Bob (racks)". */
  readonly score: string;
  /** One line per player when rated ("Ann: 1500 → 1516 (+16)"), else "Not rated: why". */
  readonly rating: readonly string[];
}

/** What the dialog says for a room whose game is over. */
export function resultContent(room: RoomView, game: Game | null, name: (id: PlayerId) => string, ratings: Readonly<Record<PlayerId, RatingChange>> = {}, me?: PlayerId): ResultContent {
  const winner = room.winner ?? game?.winner ?? null;
  const heading = winner === null ? 'Game over' : winner === me ? 'You win' : `${name(winner)} wins`;
  const ids = room.players.map((p) => p.id);
  let score: string;
  if (room.kind === 'snooker' && room.frames) {
    const f = ids.map((id) => room.frames?.[id] ?? 0);
    score = `${name(ids[0]!)} ${f[0]} – ${f[1]} ${name(ids[1]!)} (frames)`;
  } else {
    const unit = room.kind === 'threecushion' ? 'points' : room.kind === 'snooker' ? 'points' : 'racks';
    const s = ids.map((id) => game?.scores[id] ?? 0);
    score = `${name(ids[0]!)} ${s[0]} – ${s[1]} ${name(ids[1]!)} (${unit})`;
  }
  const round = (r: number) => Math.round(r);
  const rating = room.rated === false
    ? [room.unrated ? `Not rated: ${room.unrated}.` : 'Not rated.']
    : ids.map((id) => {
        const r = ratings[id];
        if (r?.after === undefined) return `${name(id)}: rating ${r?.before === undefined ? '…' : `${round(r.before)} → …`}`;
        if (r.before === undefined) return `${name(id)}: rating ${round(r.after)}`;
        const d = round(r.after) - round(r.before);
        return `${name(id)}: ${round(r.before)} → ${round(r.after)} (${d >= 0 ? '+' : '−'}${Math.abs(d)})`;
      });
  return { heading, score, rating };
}

/** The result dialog: a modal-like panel named by its heading, with "Rematch" and "Lobby". */
export function renderResult(content: ResultContent, said: string, rematch: { asked: boolean; note?: string; onClick: () => void } | null, onLobby: () => void): HTMLElement {
  const heading = h('h3', { id: 'result-heading' }, content.heading);
  return h(
    'div',
    { className: 'result', role: 'dialog', 'aria-labelledby': 'result-heading', 'aria-describedby': 'result-said', tabindex: -1 },
    heading,
    h('p', { id: 'result-said' }, said),
    h('p', { className: 'result-score' }, content.score),
    h('ul', { className: 'result-rating', 'aria-label': 'Rating' }, ...content.rating.map((l) => h('li', {}, l))),
    rematch?.note ? h('p', { className: 'note', role: 'status' }, rematch.note) : null,
    h('p', { className: 'result-buttons' },
      // A spectator has no rematch to ask for; a player's ask stays pressed.
      rematch ? h('button', { type: 'button', 'aria-pressed': rematch.asked ? 'true' : 'false', onclick: rematch.onClick }, 'Rematch') : null,
      ' ',
      h('button', { type: 'button', onclick: onLobby }, 'Lobby')),
  );
}
