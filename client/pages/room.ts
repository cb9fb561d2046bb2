// A room: the table, the players and scores, the shot clock, the referee's words, the rules'
// declarations and choices, chat. A shot is simulated here the instant it is struck (the
// shooter's page) or the instant it is broadcast (every other page), from the same state and with
// the same physics the server ran; each page compares its hash with the server's.
import { simulate, type Outcome } from '../../shared/physics/index.ts';
import type { RoomView, ServerMessage } from '../../shared/protocol/index.ts';
import { cueBallId, legalTargets, placeCueBall, playShot, POCKETS, sceneOf, strikeOf, type Game, type Shot } from '../../shared/rules/index.ts';
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
import { howOf, type RoomRatings } from '../room/state.ts';
import { resultContent, renderResult } from '../room/result.ts';
import { renderScoreboard } from '../room/scoreboard.ts';
import { contactWarning, drawTargetRings, firstBallAlong } from '../room/targets.ts';
import { POCKET_NAMES, verdictSentence, type VerdictHow } from '../verdict.ts';

/** Hash mismatches with the server on this page (there should be none). */
const stats = { mismatches: 0 };
(globalThis as { baizeMismatches?: typeof stats }).baizeMismatches = stats;

type ShotMessage = Extract<ServerMessage, { type: 'shot' }>;

/** How long a first click on "Concede" waits for the second (ms). */
const CONFIRM_MS = 4000;

export function mountRoom(root: HTMLElement, ctx: PageContext, id: string): () => void {
  const { session } = ctx;
  let room: RoomView | null = null;
  /** A room message that came while a shot played, applied when it has (render). */
  let pendingRoom: RoomView | null = null;
  let view: TableView | null = null;
  let aim: Aim | null = null;
  let animator: Animator | null = null;
  /** The game and stateId this page shows (the server's, or its own prediction of it). */
  let game: Game | null = null;
  let stateId = -1;
  /** A shot of this page's in flight, or shots being animated: no new shot meanwhile. */
  let busy = false;
  const animations: Outcome[] = [];
  /** The shot clock's end, from the last room or shot message (ms since the epoch). */
  let deadline: number | undefined;
  /** When "Concede" was clicked once (ms since the epoch). */
  let concedeArmedAt = -Infinity;
  /** What made the verdict shown (a stroke and its declarations, the clock, a concession...). */
  let how: VerdictHow = {};
  /** The players' ratings in this kind, fetched as the match starts and once it is over. */
  const ratings: RoomRatings = {};
  let ratedMatch: number | undefined;
  let ratedAfter: number | undefined;
  /** Ids of this page's chat lines in flight: a refusal (too fast) is said under the chat box. */
  const chatIds = new Set<string>();
  /** What the result dialog shows ('' while there is none). */
  let resultKey = '';

  const title = h('h2', {}, 'Room');
  const players = h('ol', { className: 'players', 'aria-label': 'Players' });
  const clock = h('p', { className: 'clock', role: 'timer', 'aria-label': 'Shot clock' });
  const verdict = h('p', { className: 'verdict', role: 'status', 'aria-label': 'Referee' });
  const tableBox = h('div', { className: 'table-box' });
  const tray = new Tray();
  const actions = h('div', { className: 'actions' });
  const declarations = h('div', { className: 'declarations' });
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
    chatNote.textContent = '';
    if (chatText.value.trim()) {
      const sent = session.send({ type: 'chat', room: id, text: chatText.value });
      if (sent !== undefined) chatIds.add(sent);
    }
    chatText.value = '';
  });
  // The chat shows once the room is known (an unknown room has none).
  chatLog.hidden = true;
  chat.hidden = true;
  const section = h('section', { className: 'room', 'aria-label': 'Room' }, title, banner, players, scoreboard, clock, tableBox, tray.element, declarations, warning, actions, verdict, result, chatLog, chat);
  root.append(section);
  // Every shot animates through the pace (fast forward) with its sounds.
  const sound = new SoundPlayer();
  const pace = new Pace({ play: (o, speed, from) => animator!.play(o, speed, from) }, sound);
  tableBox.before(h('div', { className: 'table-bar' }, soundToggle(), pace.button));

  const me = () => session.player?.id;
  const seated = () => !!room?.players.some((p) => p.id === me());
  const myTurn = () => !!game && room?.status === 'playing' && game.winner === null && game.turn === me() && seated() && !busy && session.status !== 'reconnecting'; // (the server could not take a shot meanwhile)
  const nameOf = (pid: string) => room?.players.find((p) => p.id === pid)?.name ?? pid;
  const said = (g: Game) => (g.verdict ? verdictSentence(g, g.verdict, nameOf, how) : '');

  let controls: ReturnType<typeof strokeControls> | null = null;
  const redraw = () => {
    if (!view || !aim || animator?.playing) return;
    view.draw(aim.balls());
  };

  const ensureTable = (g: Game) => {
    if (view && view.spec.name === g.table) return;
    view?.destroy();
    view = new TableView(tableBox, g.table, `${KIND_NAMES[room?.kind ?? ''] ?? ''} table`);
    aim = new Aim(view, guidanceOf(room));
    view.setOverlay((c, v) => {
      // The balls on, ringed while the table is at rest (not during a shot's animation).
      if (game && !busy && !animator?.playing && room?.status === 'playing' && game.winner === null) drawTargetRings(c, v, aim?.balls() ?? game.balls, legalTargets(game));
      aim?.draw(c);
    });
    animator = new Animator(view);
    controls?.element.remove();
    controls = strokeControls(aim, shoot);
    tableBox.after(controls.element);
    controls.element.after(warning);
  };

  const render = () => {
    if (!busy && pendingRoom) {
      room = pendingRoom;
      deadline = pendingRoom.deadline;
      pendingRoom = null;
    }
    if (!room) return;
    // A room message that came while a shot played (a new frame, a placement) applies now.
    if (!busy && room.stateId > stateId && room.game) adopt(room.game, room.stateId);
    title.textContent = `${KIND_NAMES[room.kind] ?? room.kind}, race to ${room.raceTo}${room.private ? ' (private)' : ''}`;
    const g = game;
    players.replaceChildren(
      ...room.players.map((p) =>
        h(
          'li',
          { className: g?.turn === p.id && room?.status === 'playing' ? 'on-turn' : '' },
          `${p.name}${p.id === me() ? ' (you)' : ''}: ${g ? (g.scores[p.id] ?? 0) : 0}`,
          g?.kind === 'eightball' && g.groups ? ` · ${g.groups[p.id]}` : '',
          // Three-cushion: whose cue ball is whose (the player on turn strikes theirs).
          g?.kind === 'threecushion' && g.turn === p.id && room?.status === 'playing' ? ` · plays ${cueBallId(g)}` : '',
          room?.frames ? ` (frames ${room.frames[p.id] ?? 0})` : '',
          p.connected ? '' : ' · disconnected',
        ),
      ),
    );
    chatLog.hidden = false;
    chat.hidden = false;
    scoreboard.replaceChildren(renderScoreboard(room.status === 'playing' ? g : null, nameOf));
    verdict.textContent = room.status === 'waiting' ? 'Waiting for an opponent.' : g?.verdict ? said(g) : `${nameOf(g?.turn ?? '')} to break.`;
    trackRatings(room);
    if (room.status === 'over') {
      const winner = room.winner ? nameOf(room.winner) : 'Nobody';
      const words = g ? said(g) : '';
      const end = words.includes(winner) && / wins?\b/.test(words) ? words : `${winner} wins. ${words}`.trim();
      verdict.textContent = `${end}${room.rated === false ? (room.unrated ? ` Not rated: ${room.unrated}.` : ' Not rated.') : ''}`;
      const asking = room.rematch?.find((pid) => pid !== me());
      const asked = room.rematch?.includes(me() ?? '') ?? false;
      const content = resultContent(room, g, nameOf, ratings, me());
      const note = asking !== undefined ? `${nameOf(asking)} asks for a rematch.` : asked ? 'Rematch asked: waiting for the other player.' : '';
      // Drawn again only when it says something new, so that focus and clicks stay put.
      const key = JSON.stringify([content, end, note, asked, seated()]);
      if (key !== resultKey) {
        const first = resultKey === '';
        resultKey = key;
        const dialog = renderResult(content, end, seated() ? { asked, onClick: () => session.send({ type: 'rematch', room: id }), note } : null, () => ctx.navigate('/'));
        result.replaceChildren(dialog);
        if (first) dialog.focus();
      }
    } else {
      resultKey = '';
      result.replaceChildren();
    }
    actions.replaceChildren();
    if (room.status === 'waiting' && !seated()) actions.append(h('button', { type: 'button', onclick: () => void session.request({ type: 'join', room: id }) }, 'Join'));
    if (room.status === 'waiting' && seated()) {
      const invite = `${location.origin}/room/${id}`;
      const copied = h('span', { className: 'note', role: 'status' });
      actions.append(
        h('span', { className: 'invite' }, 'Invite a player: ', h('a', { href: invite, 'aria-label': 'Invite link' }, invite)),
        h('button', { type: 'button', onclick: () => void navigator.clipboard?.writeText(invite).then(() => (copied.textContent = 'Copied.')) }, 'Copy invite link'),
        h('button', { type: 'button', onclick: () => void session.request({ type: 'leave', room: id }).then(() => ctx.navigate('/')) }, 'Close table'),
        copied,
      );
    }
    if (room.status === 'playing' && seated()) {
      // Conceding loses the match: a second click within a few seconds confirms it.
      const armed = Date.now() - concedeArmedAt < CONFIRM_MS;
      actions.append(h('button', { type: 'button', onclick: () => {
        if (armed) session.send({ type: 'concede', room: id });
        else {
          concedeArmedAt = Date.now();
          setTimeout(render, CONFIRM_MS);
        }
        render();
      } }, armed ? 'Really concede? Click again' : 'Concede'));
    }
    if (room.status === 'playing' && room.players.some((p) => !p.connected && p.heldUntil !== undefined && p.heldUntil <= Date.now()) && seated())
      actions.append(h('button', { type: 'button', onclick: () => session.send({ type: 'claim', room: id }) }, 'Claim the game'));
    if (!seated()) actions.append(h('span', { className: 'note' }, `Watching · ${room.spectators} watching`));
    renderDeclarations();
    if (g) {
      ensureTable(g);
      aim!.set(g, cueBallId(g), myTurn(), guidanceOf(room), () => {
        controls?.sync();
        warn();
        redraw();
      });
      controls!.enable(myTurn());
      // No cue for a spectator, nor while it is the other player's turn or the game is over.
      controls!.element.hidden = !seated() || room.status !== 'playing' || g.winner !== null || g.turn !== me();
      warn();
      if (!busy) tray.update(g, animator!.pocketOrder);
      redraw();
    }
  };

  const pushOut = h('input', { type: 'checkbox', 'aria-label': 'Push-out' });
  // No call or nomination is made until the player makes one: a default would be a silent choice.
  const called = h(
    'select',
    { 'aria-label': 'Called pocket' },
    h('option', { value: '' }, 'choose a pocket'),
    ...POCKETS.map((p) => h('option', { value: p }, POCKET_NAMES[p] ?? p)),
  );
  const nominated = h('select', { 'aria-label': 'Nominated ball' });
  /** The shot count the declarations were made for: a new stroke starts with none. */
  let declaredAt = -1;
  const renderDeclarations = () => {
    declarations.replaceChildren();
    const g = game;
    if (!g || !myTurn()) return;
    if (g.shots !== declaredAt) {
      declaredAt = g.shots;
      called.value = '';
      nominated.value = '';
      pushOut.checked = false;
    }
    if (g.kind === 'nineball' && g.phase === 'push-out') declarations.append(h('label', {}, pushOut, ' Push-out'));
    if (g.kind === 'eightball' && g.groups !== null && legalTargets(g).includes('8')) declarations.append(h('label', {}, 'Called pocket for the 8 ', called));
    if (g.kind === 'snooker' && (g.on === 'colour' || g.freeBall)) {
      const options = g.freeBall ? g.balls.filter((b) => b.id !== 'cue').map((b) => b.id) : ['yellow', 'green', 'brown', 'blue', 'pink', 'black'];
      const kept = nominated.value;
      const onTable = options.filter((o) => g.balls.some((b) => b.id === o));
      nominated.replaceChildren(
        h('option', { value: '' }, g.freeBall ? 'no free ball' : 'the colour hit first'),
        ...onTable.map((o) => h('option', { value: o }, o)),
      );
      nominated.value = onTable.includes(kept) ? kept : '';
      declarations.append(h('label', {}, 'Nominate ', nominated));
    }
    for (const choice of g.choices) {
      const label = choice === 'pass' ? 'Pass (opponent plays)' : choice === 'rerack' ? 'Re-rack and break' : 'Re-rack, they break again';
      declarations.append(h('button', { type: 'button', onclick: () => session.send({ type: 'decide', room: id, stateId, choice }) }, label));
    }
  };

  /** The shot as aimed, with this turn's declarations. */
  const aimedShot = (g: Game): Omit<Shot, 'player'> => {
    const s = aim!.state;
    const shot: Omit<Shot, 'player'> = { ball: cueBallId(g), heading: s.heading, speed: s.speed, side: s.side, top: s.top };
    if (g.kind === 'nineball' && g.phase === 'push-out' && pushOut.checked) shot.pushOut = true;
    if (g.kind === 'eightball' && g.groups !== null && legalTargets(g).includes('8') && called.value) shot.calledPocket = called.value as Shot['calledPocket'];
    if (g.kind === 'snooker' && (g.on === 'colour' || g.freeBall) && nominated.value) shot.nominated = nominated.value;
    return shot;
  };

  /** This page's shot: simulated here at once and animated while the server confirms it. */
  function shoot(): void {
    if (!myTurn() || !game || !aim) return;
    const g = game;
    if (g.kind === 'eightball' && g.groups !== null && legalTargets(g).includes('8') && !called.value) {
      verdict.textContent = 'Call a pocket for the 8 first.';
      return;
    }
    const shot = aimedShot(g);
    const cueBall = aim.state.cueBall;
    let played;
    try {
      played = playShot(g, { ...shot, player: me()! }, cueBall);
    } catch (err) {
      verdict.textContent = (err as Error).message;
      return;
    }
    view!.canvas.dataset.outcomeHash = played.outcome.hash;
    busy = true;
    aim.disable();
    controls?.enable(false);
    const sentState = stateId;
    // The server's answer is taken as soon as it comes; the table shows it once the shot has played.
    const reply = session.request({ type: 'shot', room: id, stateId: sentState, shot, ...(cueBall ? { cueBall } : {}) }).then(
      (m) => {
        if (m.type === 'shot') {
          deadline = m.deadline;
          report(m, played.outcome.hash);
          if (m.outcome.hash !== played.outcome.hash) mismatch(m, played.outcome.hash);
          adopt(m.game, m.stateId, m.shot);
        }
        return m;
      },
      () => null,
    );
    const shown = pace.play(played.outcome);
    void Promise.all([reply, shown]).then(([m]) => {
      busy = false;
      render();
      // Refused: the table is back at the state the server holds; say why.
      if (m?.type === 'error') verdict.textContent = `The server refused the shot: ${m.message}`;
      void animate();
    });
  }

  /**
   * Another page's shot, broadcast: simulated here at once from the same state and checked against
   * the server's hash; its animation waits for the ones before it.
   */
  function replay(m: ShotMessage): void {
    deadline = m.deadline;
    if (!game || m.stateId !== stateId + 1) {
      console.warn(`baize: shot ${m.stateId} in room ${m.room} follows state ${stateId} here: taking the server's state`);
      report(m, `gap after ${stateId}`);
      adopt(m.game, m.stateId); // a gap: take the server's state as it is
      render();
      return;
    }
    const from = m.cueBall ? placeCueBall(game, m.shot.player, m.cueBall) : game;
    const outcome = simulate(sceneOf(from), strikeOf(m.shot));
    view!.canvas.dataset.outcomeHash = outcome.hash;
    report(m, outcome.hash);
    if (outcome.hash !== m.outcome.hash) mismatch(m, outcome.hash);
    adopt(m.game, m.stateId, m.shot);
    animations.push(outcome);
    void animate();
  }

  async function animate(): Promise<void> {
    if (busy) return;
    busy = true;
    aim?.disable();
    while (animations.length > 0) await pace.play(animations.shift()!);
    busy = false;
    render();
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

  function adopt(g: Game, sid: number, shot?: ShotMessage['shot']): void {
    if (sid < stateId) return;
    if (sid > stateId) {
      const loser = g.verdict?.player;
      const claimed = g.verdict?.loss === 'concession' && room?.players.some((p) => p.id === loser && !p.connected);
      how = howOf(game, g, shot, claimed) ?? how;
    }
    game = g;
    stateId = sid;
  }

  /** The warning under the stroke controls: the aim's first ball is not a ball on. */
  function warn(): void {
    const g = game;
    const cue = aim?.cuePosition();
    const on = g && myTurn() && guidanceOf(room) !== 'none' && cue ? legalTargets(g) : [];
    warning.textContent = on.length && cue && aim && g ? contactWarning(firstBallAlong(cue, aim.state.heading, aim.balls(), cueBallId(g), view!.spec.ballRadius), on) : '';
  }

  /** Ratings before the match (as it starts) and after it (once over and rated). */
  function trackRatings(r: RoomView): void {
    if (r.match === undefined) return;
    const fetchAll = (when: 'before' | 'after') =>
      r.players.forEach((p) => void api<{ ratings?: Record<string, { rating: number }> }>(`/api/players/${encodeURIComponent(p.id)}`).then((body) => {
        const rating = body.ratings?.[r.kind]?.rating;
        // No rating yet in this kind: a new player starts at 1500 (docs/api.md).
        ratings[p.id] = { ...ratings[p.id], [when]: rating ?? 1500 };
        if (room?.status === 'over') render();
      }, () => undefined));
    if (r.match !== ratedMatch && r.status !== 'waiting') {
      // A new match (or a page opened on one): the ratings before it, when it is still in play.
      ratedMatch = r.match;
      for (const k of Object.keys(ratings)) delete ratings[k];
      if (r.status === 'playing') fetchAll('before');
    }
    if (r.status === 'over' && r.rated === true && ratedAfter !== r.match) {
      ratedAfter = r.match;
      fetchAll('after');
    }
  }

  const stop = session.onMessage((m) => {
    if (m.type === 'room' && m.room.id === id) {
      if (busy && room !== null) {
        // A shot is playing on this page: its end (a frame or the match won, a rematch asked)
        // shows once its balls have stopped.
        pendingRoom = m.room;
        return;
      }
      pendingRoom = null;
      room = m.room;
      deadline = m.room.deadline;
      if (!busy && m.room.stateId >= stateId) {
        if (m.room.game) adopt(m.room.game, m.room.stateId);
        else {
          game = null;
          stateId = m.room.stateId;
        }
      }
      render();
    } else if (m.type === 'shot' && m.room === id && m.re === undefined) {
      replay(m);
    } else if (m.type === 'chat' && m.room === id) {
      chatLog.append(h('li', {}, h('strong', {}, m.from.name), ': ', m.text));
      chatLog.scrollTop = chatLog.scrollHeight;
    } else if (m.type === 'error' && m.re !== undefined && chatIds.delete(String(m.re))) {
      // A chat line refused (too fast, or not allowed here): said to its sender by the chat box.
      chatNote.textContent = `${m.message.charAt(0).toUpperCase()}${m.message.slice(1)}.`;
    } else if (m.type === 'error' && m.code === 'no-room' && room === null) {
      section.replaceChildren(h('h2', {}, 'No such room'), h('p', {}, 'This room does not exist or has closed. ', link('/', 'Back to the lobby'), '.'));
    }
  });
  const stopStatus = session.onStatus((s) => {
    banner.textContent = s === 'reconnecting' ? 'Connection lost: reconnecting…' : '';
    render();
  });
  const stopSpace = spaceShoots(shoot);
  const tick = setInterval(() => {
    // While the last shot's balls still roll the deadline is further off than the clock's length:
    // the clock shows full until they stop.
    const left = deadline && room?.status === 'playing' ? Math.max(0, Math.min(room.shotClock, Math.ceil((deadline - Date.now()) / 1000))) : null;
    clock.textContent = left === null ? '' : `${left} s`;
    // The bar beside the seconds (no text of its own: the timer's text stays "N s").
    if (left !== null && room) clock.append(clockBar(left / room.shotClock));
  }, 250);
  session.keep(`room:${id}`, { type: 'watch', room: id });
  return () => {
    stop();
    stopStatus();
    stopSpace();
    clearInterval(tick);
    pace.destroy();
    sound.destroy();
    animator?.stop();
    view?.destroy();
    session.forget(`room:${id}`);
    if (!seated()) session.send({ type: 'leave', room: id });
  };
}

function guidanceOf(room: RoomView | null): Guidance {
  const g = (room as { guidance?: string } | null)?.guidance;
  return g === 'none' || g === 'path' ? g : 'contact';
}

/** The shot clock's bar: the time left as a fraction of the clock. */
function clockBar(fraction: number): HTMLElement {
  const bar = h('span', { className: 'clock-bar', 'aria-hidden': 'true' }, h('span', {}));
  const fill = bar.firstChild as HTMLElement;
  fill.style.width = `${Math.round(Math.max(0, Math.min(1, fraction)) * 100)}%`;
  if (fraction <= 0.25) bar.classList.add('low');
  return bar;
}
