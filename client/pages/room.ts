// A room: the table, the players and scores, the shot clock, the referee's words, the rules'
// declarations and choices, chat. A shot is simulated here the instant it is struck (the
// shooter's page) or the instant it is broadcast (every other page), from the same state and with
// the same physics the server ran; each page compares its hash with the server's.
//
// This is the page's mount: it makes the elements, turns server messages and input into actions
// for the reducer (room/reducer.ts), runs their effects (sending, animating, fetching ratings) and
// draws the state (room/render.ts).
import { simulate, type Outcome } from '../../shared/physics/index.ts';
import type { RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import { cueBallId, legalTargets, placeCueBall, playShot, sceneOf, strikeOf, type Game } from '../../shared/rules/index.ts';
import { h, KIND_NAMES, link } from '../dom.ts';
import type { PageContext } from '../main.ts';
import { Aim, type Guidance } from '../table/aim.ts';
import { Animator } from '../table/animator.ts';
import { spaceShoots, strokeControls } from '../table/controls.ts';
import { Pace } from '../table/pace.ts';
import { SoundPlayer, soundToggle } from '../table/sound.ts';
import { Tray } from '../table/tray.ts';
import { TableView } from '../table/view.ts';
import { api } from '../net/api.ts';
import { Declarations } from '../room/declarations.ts';
import { isGap, reduce, type RoomAction, type ShotMessage } from '../room/reducer.ts';
import { actionItems, playerItems, renderClock, renderResultView, resultView, scoreboardOf, titleText, verdictText, type RoomHandlers } from '../room/render.ts';
import { CONFIRM_MS, initialRoomState, myTurn, seated, type RoomPageState } from '../room/state.ts';
import { contactWarning, drawTargetRings, firstBallAlong } from '../room/targets.ts';

/** Hash mismatches with the server on this page (there should be none). */
const stats = { mismatches: 0 };
(globalThis as { baizeMismatches?: typeof stats }).baizeMismatches = stats;

export function mountRoom(root: HTMLElement, ctx: PageContext, id: string): () => void {
  const { session } = ctx;
  let state = initialRoomState(id, session.player?.id);
  let closed = false;
  let view: TableView | null = null;
  let aim: Aim | null = null;
  let animator: Animator | null = null;
  /** Broadcast shots simulated here, waiting for their turn on the table. */
  const animations: Outcome[] = [];
  /** What the result dialog shows ('' while there is none), and the chat lines shown. */
  let resultKey = '';
  let chatShown = 0;

  const title = h('h2', {}, 'Room');
  const players = h('ol', { className: 'players', 'aria-label': 'Players' });
  const clock = h('p', { className: 'clock', role: 'timer', 'aria-label': 'Shot clock' });
  const verdict = h('p', { className: 'verdict', role: 'status', 'aria-label': 'Referee' });
  const tableBox = h('div', { className: 'table-box' });
  const tray = new Tray();
  const actions = h('div', { className: 'actions' });
  const declarations = new Declarations();
  const chatLog = h('ul', { className: 'chat', 'aria-label': 'Chat' });
  const chatText = h('input', { maxlength: 200, 'aria-label': 'Message' });
  const chatNote = h('p', { className: 'note chat-note', role: 'status' });
  const chat = h('form', { className: 'chat-form' }, chatText, h('button', { type: 'submit' }, 'Send'), chatNote);
  const banner = h('p', { className: 'banner', role: 'status' });
  const scoreboard = h('div', { className: 'scoreboard-box' });
  const result = h('div', { className: 'result-box' });
  const warning = h('p', { className: 'warning', role: 'status', 'aria-label': 'Aim warning' });
  chat.addEventListener('submit', (e) => {
    e.preventDefault();
    const sent = chatText.value.trim() ? session.send({ type: 'chat', room: id, text: chatText.value }) : undefined;
    chatText.value = '';
    dispatch({ type: 'chat-sent', ...(sent !== undefined ? { id: sent } : {}) }, true);
    renderChat();
  });
  // The chat shows once the room is known (an unknown room has none).
  chatLog.hidden = true;
  chat.hidden = true;
  const section = h('section', { className: 'room', 'aria-label': 'Room' }, title, banner, players, scoreboard, clock, tableBox, tray.element, declarations.element, warning, actions, verdict, result, chatLog, chat);
  root.append(section);
  // Every shot animates through the pace (fast forward) with its sounds.
  const sound = new SoundPlayer();
  const pace = new Pace({ play: (o, speed, from) => animator!.play(o, speed, from) }, sound);
  tableBox.before(h('div', { className: 'table-bar' }, soundToggle(), pace.button));

  /** The state with the session as it is now (its player, whether it is reconnecting). */
  const current = (): RoomPageState => (state = reduce(state, { type: 'session', me: session.player?.id, reconnecting: session.status === 'reconnecting' }));

  /** The next state from `a`, its effects run, and drawn unless `quiet` (a shot playing shows its end once it has). */
  function dispatch(a: RoomAction, quiet = false): void {
    if (closed) return;
    const before = current();
    state = reduce(before, a);
    effects(before, state);
    if (!quiet) render();
  }

  function effects(before: RoomPageState, after: RoomPageState): void {
    if (after.concededAt !== before.concededAt) session.send({ type: 'concede', room: id });
    else if (after.concedeArmedAt !== before.concedeArmedAt) setTimeout(() => !closed && render(), CONFIRM_MS);
    if (after.room && after.ratedBefore !== undefined && after.ratedBefore !== before.ratedBefore) fetchRatings(after.room, after.ratedBefore, 'before');
    if (after.room && after.ratedAfter !== undefined && after.ratedAfter !== before.ratedAfter) fetchRatings(after.room, after.ratedAfter, 'after');
    if (after.missing && !before.missing) section.replaceChildren(h('h2', {}, 'No such room'), h('p', {}, 'This room does not exist or has closed. ', link('/', 'Back to the lobby'), '.'));
  }

  /** The players' ratings in this kind (a new player starts at 1500: docs/api.md). */
  function fetchRatings(r: RoomView, match: number, when: 'before' | 'after'): void {
    for (const p of r.players) {
      void api<{ ratings?: Record<string, { rating: number }> }>(`/api/players/${encodeURIComponent(p.id)}`).then(
        // Shown in the result dialog: nothing to draw before the match is over.
        (body) => dispatch({ type: 'rating', match, player: p.id, when, rating: body.ratings?.[r.kind]?.rating ?? 1500 }, state.room?.status !== 'over'),
        () => undefined,
      );
    }
  }

  const handlers: RoomHandlers = {
    join: () => void session.request({ type: 'join', room: id }),
    copy: (invite) => navigator.clipboard?.writeText(invite),
    close: () => void session.request({ type: 'leave', room: id }).then(() => ctx.navigate('/')),
    concede: () => dispatch({ type: 'concede', now: Date.now() }),
    claim: () => session.send({ type: 'claim', room: id }),
    rematch: () => session.send({ type: 'rematch', room: id }),
    lobby: () => ctx.navigate('/'),
  };

  let controls: ReturnType<typeof strokeControls> | null = null;
  const redraw = () => {
    if (!view || !aim || animator?.playing) return;
    view.draw(aim.balls());
  };

  const ensureTable = (g: Game) => {
    if (view && view.spec.name === g.table) return;
    view?.destroy();
    view = new TableView(tableBox, g.table, `${KIND_NAMES[state.room?.kind ?? ''] ?? ''} table`);
    aim = new Aim(view, guidanceOf(state.room));
    view.setOverlay((c, v) => {
      // The balls on, ringed while the table is at rest (not during a shot's animation).
      const { game, busy, room } = state;
      if (game && !busy && !animator?.playing && room?.status === 'playing' && game.winner === null) drawTargetRings(c, v, aim?.balls() ?? game.balls, legalTargets(game));
      aim?.draw(c);
    });
    animator = new Animator(view);
    controls?.element.remove();
    controls = strokeControls(aim, shoot);
    tableBox.after(controls.element);
    controls.element.after(warning);
  };

  /** The chat's new lines and its note (drawn apart: a line never waits for a shot to end). */
  function renderChat(): void {
    const s = state;
    chatNote.textContent = s.chatNote;
    for (const line of s.chat.slice(chatShown)) chatLog.append(h('li', {}, h('strong', {}, line.from), ': ', line.text));
    if (s.chat.length > chatShown) chatLog.scrollTop = chatLog.scrollHeight;
    chatShown = s.chat.length;
  }

  function render(): void {
    const s = current();
    renderChat();
    const room = s.room;
    if (!room || s.missing) return;
    const now = Date.now();
    title.textContent = titleText(s);
    players.replaceChildren(...playerItems(s));
    chatLog.hidden = false;
    chat.hidden = false;
    scoreboard.replaceChildren(scoreboardOf(s));
    verdict.textContent = verdictText(s);
    const rv = resultView(s);
    if (rv) {
      // Drawn again only when it says something new, so that focus and clicks stay put.
      if (rv.key !== resultKey) {
        const first = resultKey === '';
        resultKey = rv.key;
        const dialog = renderResultView(rv, handlers);
        result.replaceChildren(dialog);
        if (first) dialog.focus();
      }
    } else {
      resultKey = '';
      result.replaceChildren();
    }
    actions.replaceChildren(...actionItems(s, now, location.origin, handlers));
    const turn = myTurn(s);
    declarations.update(s.game, turn, (choice) => session.send({ type: 'decide', room: id, stateId: state.stateId, choice }));
    const g = s.game;
    if (g) {
      ensureTable(g);
      aim!.set(g, cueBallId(g), turn, guidanceOf(room), () => {
        controls?.sync();
        warn();
        redraw();
      });
      controls!.enable(turn);
      // No cue for a spectator, nor while it is the other player's turn or the game is over.
      controls!.element.hidden = !seated(s) || room.status !== 'playing' || g.winner !== null || g.turn !== s.me;
      warn();
      if (!s.busy) tray.update(g, animator!.pocketOrder);
      redraw();
    }
  }

  /** This page's shot: simulated here at once and animated while the server confirms it. */
  function shoot(): void {
    const s = current();
    if (!myTurn(s) || !s.game || !aim) return;
    const g = s.game;
    if (declarations.missingCall(g)) return dispatch({ type: 'notice', text: 'Call a pocket for the 8 first.' });
    const a = aim.state;
    const shot = declarations.declare(g, { ball: cueBallId(g), heading: a.heading, speed: a.speed, side: a.side, top: a.top });
    const cueBall = a.cueBall;
    let played;
    try {
      played = playShot(g, { ...shot, player: s.me! }, cueBall);
    } catch (err) {
      return dispatch({ type: 'notice', text: (err as Error).message });
    }
    view!.canvas.dataset.outcomeHash = played.outcome.hash;
    dispatch({ type: 'shot-sent' }, true);
    aim.disable();
    controls?.enable(false);
    // The server's answer is taken as soon as it comes; the table shows it once the shot has played.
    const reply = session.request({ type: 'shot', room: id, stateId: s.stateId, shot, ...(cueBall ? { cueBall } : {}) }).then(
      (m) => {
        if (m.type === 'shot') {
          report(m, played.outcome.hash);
          if (m.outcome.hash !== played.outcome.hash) mismatch(m, played.outcome.hash);
        }
        dispatch({ type: 'shot-reply', message: m }, true);
        return m;
      },
      () => null,
    );
    const shown = pace.play(played.outcome);
    void Promise.all([reply, shown]).then(([m]) => {
      dispatch({ type: 'shot-done', ...(m?.type === 'error' ? { refused: m.message } : {}) });
      void animate();
    });
  }

  /**
   * Another page's shot, broadcast: simulated here at once from the same state and checked against
   * the server's hash; its animation waits for the ones before it.
   */
  function replay(m: ShotMessage): void {
    const s = current();
    if (isGap(s, m)) {
      console.warn(`baize: shot ${m.stateId} in room ${m.room} follows state ${s.stateId} here: taking the server's state`);
      report(m, `gap after ${s.stateId}`);
      return dispatch(m); // a gap: take the server's state as it is
    }
    const from = m.cueBall ? placeCueBall(s.game!, m.shot.player, m.cueBall) : s.game!;
    const outcome = simulate(sceneOf(from), strikeOf(m.shot));
    view!.canvas.dataset.outcomeHash = outcome.hash;
    report(m, outcome.hash);
    if (outcome.hash !== m.outcome.hash) mismatch(m, outcome.hash);
    dispatch(m, true);
    animations.push(outcome);
    void animate();
  }

  async function animate(): Promise<void> {
    if (state.busy || animations.length === 0) return;
    dispatch({ type: 'animating' }, true);
    aim?.disable();
    while (animations.length > 0) await pace.play(animations.shift()!);
    dispatch({ type: 'animated' });
  }

  /** A page opened with ?report=URL posts each hash it computed there (how a browser without a driver is checked). */
  const reportTo = new URLSearchParams(location.search).get('report');
  function report(m: ShotMessage, mine: string): void {
    if (reportTo) void fetch(reportTo, { method: 'POST', body: JSON.stringify({ room: m.room, stateId: m.stateId, hash: mine, server: m.outcome.hash, userAgent: navigator.userAgent }) });
  }

  function mismatch(m: ShotMessage, mine: string): void {
    stats.mismatches++;
    console.warn(`baize: shot ${m.stateId} in room ${m.room}: this page computed ${mine}, the server ${m.outcome.hash}; taking the server's state`);
  }

  /** The warning under the stroke controls: the aim's first ball is not a ball on. */
  function warn(): void {
    const s = state;
    const g = s.game;
    const cue = aim?.cuePosition();
    const on = g && myTurn(s) && guidanceOf(s.room) !== 'none' && cue ? legalTargets(g) : [];
    warning.textContent = on.length && cue && aim && g ? contactWarning(firstBallAlong(cue, aim.state.heading, aim.balls(), cueBallId(g), view!.spec.ballRadius), on) : '';
  }

  const stop = session.onMessage((m: ServerMessage) => {
    // A room that comes while a shot plays on this page is held (and drawn) until the shot has played.
    if (m.type === 'room' && m.room.id === id) dispatch(m, state.busy && state.room !== null);
    else if (m.type === 'shot' && m.room === id && m.re === undefined) replay(m);
    else if (m.type === 'chat' || m.type === 'error') {
      dispatch(m, true);
      renderChat();
    }
  });
  const stopStatus = session.onStatus((s) => {
    banner.textContent = s === 'reconnecting' ? 'Connection lost: reconnecting…' : '';
    dispatch({ type: 'session', me: session.player?.id, reconnecting: s === 'reconnecting' });
  });
  const stopSpace = spaceShoots(shoot);
  const tick = setInterval(() => renderClock(clock, state, Date.now()), 250);
  session.keep(`room:${id}`, { type: 'watch', room: id });
  return () => {
    closed = true;
    stop();
    stopStatus();
    stopSpace();
    clearInterval(tick);
    pace.destroy();
    sound.destroy();
    animator?.stop();
    view?.destroy();
    session.forget(`room:${id}`);
    if (!seated(current())) session.send({ type: 'leave', room: id });
  };
}

function guidanceOf(room: RoomView | null): Guidance {
  const g = (room as { guidance?: string } | null)?.guidance;
  return g === 'none' || g === 'path' ? g : 'contact';
}
