// What the room page shows, from its state (state.ts) alone: the title, the players, the
// referee's words, the actions, the shot clock and the result dialog. The words are plain
// functions; the elements are built fresh, with the page's handlers for their clicks.
import { cueBallId } from '../../shared/rules/index.ts';
import { h, KIND_NAMES } from '../dom.ts';
import { verdictSentence } from '../verdict.ts';
import { renderResult, resultContent, type ResultContent } from './result.ts';
import { renderScoreboard } from './scoreboard.ts';
import { concedeArmed, nameOf, seated, type RoomPageState } from './state.ts';

/** What the page's buttons do (sending, navigating: the page's effects). */
export interface RoomHandlers {
  join(): void;
  /** Copies the invite link (undefined: no clipboard here). */
  copy(invite: string): Promise<unknown> | undefined;
  close(): void;
  concede(): void;
  claim(): void;
  rematch(): void;
  lobby(): void;
}

export function titleText(s: RoomPageState): string {
  const r = s.room;
  return r ? `${KIND_NAMES[r.kind] ?? r.kind}, race to ${r.raceTo}${r.private ? ' (private)' : ''}` : 'Room';
}

/** The referee's words on the game shown. */
function said(s: RoomPageState): string {
  const g = s.game;
  return g?.verdict ? verdictSentence(g, g.verdict, nameOf(s), s.how) : '';
}

/** Once over: who won, with the last verdict when it does not say so already. */
export function endText(s: RoomPageState): string {
  const winner = s.room?.winner ? nameOf(s)(s.room.winner) : 'Nobody';
  const words = said(s);
  return words.includes(winner) && / wins?\b/.test(words) ? words : `${winner} wins. ${words}`.trim();
}

/** The line under the table: a notice, else the referee's words (and whether an ended match was rated). */
export function verdictText(s: RoomPageState): string {
  const r = s.room;
  if (!r) return '';
  if (s.notice) return s.notice;
  if (r.status === 'over') return `${endText(s)}${r.rated === false ? (r.unrated ? ` Not rated: ${r.unrated}.` : ' Not rated.') : ''}`;
  if (r.status === 'waiting') return 'Waiting for an opponent.';
  return s.game?.verdict ? said(s) : `${nameOf(s)(s.game?.turn ?? '')} to break.`;
}

export function playerItems(s: RoomPageState): HTMLElement[] {
  const r = s.room;
  const g = s.game;
  if (!r) return [];
  return r.players.map((p) =>
    h(
      'li',
      { className: g?.turn === p.id && r.status === 'playing' ? 'on-turn' : '' },
      `${p.name}${p.id === s.me ? ' (you)' : ''}: ${g ? (g.scores[p.id] ?? 0) : 0}`,
      g?.kind === 'eightball' && g.groups ? ` · ${g.groups[p.id]}` : '',
      // Three-cushion: whose cue ball is whose (the player on turn strikes theirs).
      g?.kind === 'threecushion' && g.turn === p.id && r.status === 'playing' ? ` · plays ${cueBallId(g)}` : '',
      r.frames ? ` (frames ${r.frames[p.id] ?? 0})` : '',
      p.connected ? '' : ' · disconnected',
    ),
  );
}

export function scoreboardOf(s: RoomPageState): HTMLElement {
  return renderScoreboard(s.room?.status === 'playing' ? s.game : null, nameOf(s));
}

/** The buttons under the table: join, invite, concede (armed by a first click), claim; or "Watching". */
export function actionItems(s: RoomPageState, now: number, origin: string, on: RoomHandlers): HTMLElement[] {
  const r = s.room;
  if (!r) return [];
  const items: HTMLElement[] = [];
  const sits = seated(s);
  if (r.status === 'waiting' && !sits) items.push(h('button', { type: 'button', onclick: on.join }, 'Join'));
  if (r.status === 'waiting' && sits) {
    const invite = `${origin}/room/${r.id}`;
    const copied = h('span', { className: 'note', role: 'status' });
    items.push(
      h('span', { className: 'invite' }, 'Invite a player: ', h('a', { href: invite, 'aria-label': 'Invite link' }, invite)),
      h('button', { type: 'button', onclick: () => void on.copy(invite)?.then(() => (copied.textContent = 'Copied.')) }, 'Copy invite link'),
      h('button', { type: 'button', onclick: on.close }, 'Close table'),
      copied,
    );
  }
  if (r.status === 'playing' && sits) items.push(h('button', { type: 'button', onclick: on.concede }, concedeArmed(s, now) ? 'Really concede? Click again' : 'Concede'));
  if (r.status === 'playing' && r.players.some((p) => !p.connected && p.heldUntil !== undefined && p.heldUntil <= now) && sits)
    items.push(h('button', { type: 'button', onclick: on.claim }, 'Claim the game'));
  if (!sits) items.push(h('span', { className: 'note' }, `Watching · ${r.spectators} watching`));
  return items;
}

/** The shot clock's seconds left, or null when there is none. */
export function clockLeft(s: RoomPageState, now: number): number | null {
  const r = s.room;
  // While the last shot's balls still roll the deadline is further off than the clock's length:
  // the clock shows full until they stop.
  return s.deadline && r?.status === 'playing' ? Math.max(0, Math.min(r.shotClock, Math.ceil((s.deadline - now) / 1000))) : null;
}

export function renderClock(clock: HTMLElement, s: RoomPageState, now: number): void {
  const left = clockLeft(s, now);
  clock.textContent = left === null ? '' : `${left} s`;
  // The bar beside the seconds (no text of its own: the timer's text stays "N s").
  if (left !== null && s.room) clock.append(clockBar(left / s.room.shotClock));
}

/** The shot clock's bar: the time left as a fraction of the clock. */
function clockBar(fraction: number): HTMLElement {
  const bar = h('span', { className: 'clock-bar', 'aria-hidden': 'true' }, h('span', {}));
  const fill = bar.firstChild as HTMLElement;
  fill.style.width = `${Math.round(Math.max(0, Math.min(1, fraction)) * 100)}%`;
  if (fraction <= 0.25) bar.classList.add('low');
  return bar;
}

export interface ResultView {
  /** Changes only when the dialog says something new (so that focus and clicks stay put). */
  readonly key: string;
  readonly content: ResultContent;
  readonly end: string;
  readonly note: string;
  readonly asked: boolean;
  readonly seated: boolean;
}

/** The result dialog once the match is over, else null. */
export function resultView(s: RoomPageState): ResultView | null {
  const r = s.room;
  if (r?.status !== 'over') return null;
  const name = nameOf(s);
  const me = s.me;
  const asking = r.rematch?.find((pid) => pid !== me);
  const asked = r.rematch?.includes(me ?? '') ?? false;
  const content = resultContent(r, s.game, name, s.ratings, me);
  const end = endText(s);
  const note = asking !== undefined ? `${name(asking)} asks for a rematch.` : asked ? 'Rematch asked: waiting for the other player.' : '';
  const sits = seated(s);
  return { key: JSON.stringify([content, end, note, asked, sits]), content, end, note, asked, seated: sits };
}

export function renderResultView(v: ResultView, on: RoomHandlers): HTMLElement {
  return renderResult(v.content, v.end, v.seated ? { asked: v.asked, onClick: on.rematch, note: v.note } : null, on.lobby);
}
