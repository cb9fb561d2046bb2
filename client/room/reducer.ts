// The room page's reducer: the server's messages and the player's input (with the time they came
// at, when it matters) make the next RoomPageState. Pure: no DOM, no clock, no sending; the page
// runs what a new state implies (pages/room.ts).
import type { RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import type { Game, PlayerId } from '../../shared/rules/index.ts';
import { concedeArmed, howOf, myTurn, seated, type RoomPageState } from './state.ts';

export type ShotMessage = Extract<ServerMessage, { type: 'shot' }>;

export type RoomAction =
  /** The server's messages the page handles (a shot here is another page's, broadcast). */
  | Extract<ServerMessage, { type: 'room' | 'shot' | 'chat' | 'error' }>
  | { readonly type: 'session'; readonly me: PlayerId | undefined; readonly reconnecting: boolean }
  /** This page's shot: struck, answered (null: no answer), and played out on the table. */
  | { readonly type: 'shot-sent' }
  | { readonly type: 'shot-reply'; readonly message: ServerMessage | null }
  | { readonly type: 'shot-done'; readonly refused?: string }
  /** Broadcast shots being animated, and all of them played. */
  | { readonly type: 'animating' }
  | { readonly type: 'animated' }
  | { readonly type: 'concede'; readonly now: number }
  | { readonly type: 'chat-sent'; readonly id?: string }
  | { readonly type: 'notice'; readonly text: string }
  | { readonly type: 'rating'; readonly match: number; readonly player: PlayerId; readonly when: 'before' | 'after'; readonly rating: number };

/** A broadcast shot that does not follow the state held here: the server's state is taken as it is. */
export const isGap = (s: RoomPageState, m: ShotMessage): boolean => !s.game || m.stateId !== s.stateId + 1;

export function reduce(s: RoomPageState, a: RoomAction): RoomPageState {
  return settle(step(s, a));
}

function step(s: RoomPageState, a: RoomAction): RoomPageState {
  switch (a.type) {
    case 'session':
      return a.me === s.me && a.reconnecting === s.reconnecting ? s : { ...s, me: a.me, reconnecting: a.reconnecting };
    case 'room': {
      if (a.room.id !== s.id) return s;
      // A shot is playing on this page: its end (a frame or the match won, a rematch asked) shows
      // once its balls have stopped.
      if (s.busy && s.room !== null) return { ...s, pendingRoom: a.room };
      let n: RoomPageState = { ...s, pendingRoom: null, room: a.room, deadline: a.room.deadline, notice: '' };
      if (!s.busy && a.room.stateId >= s.stateId) n = a.room.game ? adopt(n, a.room.game, a.room.stateId) : { ...n, game: null, stateId: a.room.stateId };
      return n;
    }
    case 'shot': {
      if (a.room !== s.id || a.re !== undefined) return s;
      const n = { ...s, deadline: a.deadline };
      return isGap(s, a) ? adopt(n, a.game, a.stateId) : adopt(n, a.game, a.stateId, a.shot);
    }
    case 'shot-sent':
      return myTurn(s) ? { ...s, busy: true, notice: '' } : s;
    case 'shot-reply': {
      const m = a.message;
      return m?.type === 'shot' ? adopt({ ...s, deadline: m.deadline }, m.game, m.stateId, m.shot) : s;
    }
    case 'shot-done':
      // Refused: the table is back at the state the server holds; say why.
      return { ...s, busy: false, notice: a.refused === undefined ? s.notice : `The server refused the shot: ${a.refused}` };
    case 'animating':
      return { ...s, busy: true };
    case 'animated':
      return { ...s, busy: false };
    case 'concede':
      // Conceding loses the match: a second click within a few seconds confirms it.
      if (s.room?.status !== 'playing' || !seated(s)) return s;
      return concedeArmed(s, a.now) ? { ...s, concededAt: a.now } : { ...s, concedeArmedAt: a.now };
    case 'chat-sent':
      return { ...s, chatNote: '', chatSent: a.id === undefined ? s.chatSent : [...s.chatSent, a.id] };
    case 'chat':
      return a.room === s.id ? { ...s, chat: [...s.chat, { from: a.from.name, text: a.text }] } : s;
    case 'error': {
      const re = a.re === undefined ? undefined : String(a.re);
      if (re !== undefined && s.chatSent.includes(re)) {
        // A chat line refused (too fast, or not allowed here): said to its sender by the chat box.
        return { ...s, chatSent: s.chatSent.filter((c) => c !== re), chatNote: `${a.message.charAt(0).toUpperCase()}${a.message.slice(1)}.` };
      }
      return a.code === 'no-room' && s.room === null ? { ...s, missing: true } : s;
    }
    case 'notice':
      return { ...s, notice: a.text };
    case 'rating':
      if (a.match !== s.ratedMatch) return s;
      return { ...s, ratings: { ...s.ratings, [a.player]: { ...s.ratings[a.player], [a.when]: a.rating } } };
  }
}

/** The game `g` at `sid` (never an older one), and what made its verdict. */
function adopt(s: RoomPageState, g: Game, sid: number, shot?: ShotMessage['shot']): RoomPageState {
  if (sid < s.stateId) return s;
  let how = s.how;
  if (sid > s.stateId) {
    const loser = g.verdict?.player;
    const claimed = g.verdict?.loss === 'concession' && !!s.room?.players.some((p) => p.id === loser && !p.connected);
    how = howOf(s.game, g, shot, claimed) ?? s.how;
  }
  return { ...s, game: g, stateId: sid, how, notice: sid > s.stateId ? '' : s.notice };
}

/** Once no shot plays: a room held meanwhile applies, and a newer game in the room is taken. */
function settle(s: RoomPageState): RoomPageState {
  let n = s;
  if (!n.busy && n.pendingRoom) n = { ...n, room: n.pendingRoom, deadline: n.pendingRoom.deadline, pendingRoom: null, notice: '' };
  if (!n.busy && n.room && n.room.stateId > n.stateId && n.room.game) n = adopt(n, n.room.game, n.room.stateId);
  return n.room ? track(n, n.room) : n;
}

/** Ratings before the match (as it starts) and after it (once over and rated). */
function track(s: RoomPageState, r: RoomView): RoomPageState {
  if (r.match === undefined) return s;
  let n = s;
  // A new match (or a page opened on one): the ratings before it, when it is still in play.
  if (r.match !== n.ratedMatch && r.status !== 'waiting') n = { ...n, ratedMatch: r.match, ratings: {}, ...(r.status === 'playing' ? { ratedBefore: r.match } : {}) };
  if (r.status === 'over' && r.rated === true && n.ratedAfter !== r.match) n = { ...n, ratedAfter: r.match };
  return n;
}
