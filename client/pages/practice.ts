// Practice, all in the browser (it plays with the network off once loaded): free practice on any
// game's layout with free placement and undo, and verified runs (snooker break building, a
// nine-ball run-out from the break, a three-cushion run) whose shots the server replays to score.
// A run to submit starts from a seed the server issues; offline, a run plays from a seed of its
// own and cannot be submitted.
import {
  cueBallId,
  decide,
  newGame,
  placeBall,
  playShot,
  practiceStart,
  PRACTICE_OPPONENT,
  undo,
  type Game,
  type PracticeKind,
  type PracticeLayout,
  type PracticeShot,
} from '../../shared/rules/index.ts';
import type { Outcome } from '../../shared/physics/index.ts';
import { h, KIND_NAMES } from '../dom.ts';
import type { PageContext } from '../main.ts';
import { ApiRefusal, practiceSeed, submitPractice } from '../net/api.ts';
import { storedToken } from '../net/session.ts';
import { Aim } from '../table/aim.ts';
import { Animator } from '../table/animator.ts';
import { spaceShoots, strokeControls } from '../table/controls.ts';
import { Pace } from '../table/pace.ts';
import { SoundPlayer, soundToggle } from '../table/sound.ts';
import { Tray } from '../table/tray.ts';
import { TableView } from '../table/view.ts';
import { verdictSentence } from '../verdict.ts';
import { ComputerMind, preloadComputer } from '../computer/mind.ts';
import { Declarations } from '../room/declarations.ts';
import type { Decision, Level } from '../../shared/ai/index.ts';

const ME = 'me';
/** The computer's id in a game against it here. */
const CPU = 'computer';
/** The least pause before the computer's move once the balls have stopped (ms), as on the server. */
const COMPUTER_PAUSE_MS = 800;
const VERSUS_KINDS = ['nineball', 'eightball', 'snooker', 'threecushion'] as const;

/** A seed of this browser's own, for a run played offline (never submitted). */
const localSeed = () => Math.floor(Math.random() * 2 ** 32);

export function mountPractice(root: HTMLElement, ctx: PageContext): () => void {
  const mode = h(
    'select',
    { 'aria-label': 'Practice' },
    h('option', { value: 'free' }, 'Free practice'),
    h('option', { value: 'run' }, 'Verified run'),
    h('option', { value: 'computer' }, 'Against the computer'),
  );
  const versusKind = h('select', { 'aria-label': 'Game' }, ...VERSUS_KINDS.map((k) => h('option', { value: k }, KIND_NAMES[k])));
  const level = h('select', { 'aria-label': 'Level' }, ...[1, 2, 3, 4, 5].map((n) => h('option', { value: String(n) }, `Level ${n}`)));
  level.value = '3';
  // Against the computer: the room's declarations and choices (push-out, the 8's pocket, snooker's
  // nomination, pass or re-rack), made by the player as in a room.
  const declarations = new Declarations();
  const versusButton = h('button', { type: 'button', onclick: () => ((mode.value = 'computer'), reset()) }, 'Play the computer');
  // The computer's worker script is fetched now, so that it can be played with the network off.
  void preloadComputer().then(
    () => (versusButton.dataset.ready = 'true'),
    () => undefined,
  );
  const mind = new ComputerMind();
  const layout = h('select', { 'aria-label': 'Layout' }, ...['nineball', 'eightball', 'snooker', 'threecushion', 'empty'].map((l) => h('option', { value: l }, KIND_NAMES[l] ?? 'Empty table')));
  const runKind = h('select', { 'aria-label': 'Run' }, ...(['snooker', 'nineball', 'threecushion'] as const).map((k) => h('option', { value: k }, KIND_NAMES[k])));
  const placing = h('input', { type: 'checkbox', 'aria-label': 'Place balls' });
  const info = h('p', { role: 'status', className: 'verdict' });
  const tableBox = h('div', { className: 'table-box' });
  const undoButton = h('button', { type: 'button', onclick: () => doUndo() }, 'Undo');
  const replayButton = h('button', { type: 'button', onclick: () => last && void pace.play(last) }, 'Replay');
  const submit = h('button', { type: 'button', onclick: () => void send() }, 'Submit run');
  const start = h('button', { type: 'button', onclick: () => reset() }, 'New table');
  const tray = new Tray();
  root.append(
    h(
      'section',
      { className: 'practice', 'aria-label': 'Practice' },
      h('h2', {}, 'Practice'),
      h('p', {}, mode, ' ', layout, ' ', runKind, ' ', start, ' ', h('label', {}, placing, ' Place balls')),
      h('p', {}, versusKind, ' ', h('label', {}, 'Level ', level), ' ', versusButton),
      declarations.element,
      tableBox,
      tray.element,
      h('p', {}, undoButton, ' ', replayButton, ' ', submit),
      info,
    ),
  );

  let view: TableView | null = null;
  let aim: Aim | null = null;
  let animator!: Animator;
  // Every shot animates through the pace (fast forward) with its sounds.
  const sound = new SoundPlayer();
  const pace = new Pace({ play: (o, speed, from) => animator.play(o, speed, from) }, sound);
  tableBox.before(h('div', { className: 'table-bar' }, soundToggle(), pace.button));
  let controls: ReturnType<typeof strokeControls> | null = null;
  let game: Game;
  let last: Outcome | null = null;
  let busy = false;
  /** A run waits for its seed from the server. */
  let waiting = false;
  /** Counts the runs started, so that a seed arriving for an earlier one is dropped. */
  let started = 0;
  /** `issued`: the seed came from the server, so the run can be submitted (once). */
  let run: { kind: PracticeKind; seed: number; issued: boolean; submitted: boolean; shots: PracticeShot[]; score: number } | null = null;
  /** A game against the computer: its level, the seed its decisions derive from, its moves so far. */
  let versus: { level: Level; seed: number; moves: number } | null = null;
  const nameOf = (id: string) => (id === PRACTICE_OPPONENT ? 'the table' : id === CPU && versus ? `Computer (level ${versus.level})` : id);

  const setup = (g: Game) => {
    game = g;
    if (!view || view.spec.name !== g.table) {
      view?.destroy();
      controls?.element.remove();
      view = new TableView(tableBox, g.table, 'Practice table');
      aim = new Aim(view, 'path');
      view.setOverlay((c) => aim?.draw(c));
      animator = new Animator(view);
      controls = strokeControls(aim, shoot);
      tableBox.after(controls.element);
      view.canvas.addEventListener('pointerdown', placeDown);
      view.canvas.addEventListener('pointerup', placeUp);
      view.canvas.addEventListener('pointermove', placeMove);
    }
    refresh();
  };

  const refresh = () => {
    const active = !busy && !waiting && !run?.submitted && !(placing.checked && !versus) && game.winner === null && game.turn === ME;
    aim!.set(game, cueBallId(game), active, 'path', () => {
      controls?.sync();
      if (!animator.playing) view!.draw(aim!.balls());
    });
    controls!.enable(active);
    view!.draw(aim!.balls());
    tray.update(game, animator.pocketOrder);
    layout.hidden = mode.value !== 'free';
    runKind.hidden = mode.value !== 'run';
    submit.hidden = mode.value !== 'run';
    undoButton.hidden = mode.value !== 'free';
    declarations.update(versus ? game : null, !busy && game.winner === null && game.turn === ME, (choice) => humanChoice(choice));
    submit.disabled = !run || !run.issued || run.submitted || run.shots.length === 0;
  };

  function reset(): void {
    last = null;
    const mine = ++started;
    waiting = false;
    run = null;
    versus = null;
    mind.stop();
    if (mode.value === 'computer') {
      const lv = Number(level.value) as Level;
      versus = { level: lv, seed: localSeed(), moves: 0 };
      const kind = versusKind.value as (typeof VERSUS_KINDS)[number];
      setup(newGame(kind, [ME, CPU], { seed: versus.seed, ...(kind === 'threecushion' ? { raceTo: 5 } : {}) }));
      info.textContent = `${KIND_NAMES[kind]} against the computer (level ${lv}), thinking in this browser: you break.`;
      return;
    }
    if (mode.value === 'free') {
      setup(newGame('practice', [ME], { layout: layout.value as PracticeLayout }));
      info.textContent = 'Free practice: aim with the mouse (a click holds the aim) or the arrow keys, Space or Shoot to play.';
      return;
    }
    const kind = runKind.value as PracticeKind;
    const begin = (seed: number, issued: boolean, note: string) => {
      waiting = false;
      run = { kind, seed, issued, submitted: false, shots: [], score: 0 };
      setup(practiceStart(kind, ME, seed));
      info.textContent = note;
    };
    const unsubmittable = 'you can play this run, but it will not be submitted. Runs started while connected to the server can be submitted.';
    const token = storedToken();
    if (!token) {
      begin(localSeed(), false, `Not connected to the server yet: ${unsubmittable}`);
      return;
    }
    waiting = true;
    setup(practiceStart(kind, ME, 0));
    info.textContent = 'Asking the server to set up the run…';
    practiceSeed(token, kind).then(
      (seed) => mine === started && begin(seed, true, 'Verified run: play while you stay at the table, then submit. Score 0.'),
      (err: Error) => mine === started && begin(localSeed(), false, err instanceof ApiRefusal ? `The server did not set up the run (${err.message}): ${unsubmittable}` : `Offline: ${unsubmittable}`),
    );
  }

  function shoot(): void {
    if (busy || waiting || run?.submitted || (placing.checked && !versus) || game.winner !== null || game.turn !== ME || !aim) return;
    const s = aim.state;
    const stroke: PracticeShot['shot'] = { ball: cueBallId(game), heading: s.heading, speed: s.speed, side: s.side, top: s.top };
    if (versus && declarations.missingCall(game)) {
      info.textContent = 'Call a pocket for the 8 first.';
      return;
    }
    const shot = versus ? declarations.declare(game, stroke) : stroke;
    let played;
    try {
      played = playShot(game, { ...shot, player: ME }, s.cueBall);
    } catch (err) {
      info.textContent = (err as Error).message;
      return;
    }
    view!.canvas.dataset.outcomeHash = played.outcome.hash;
    last = played.outcome;
    busy = true;
    aim.disable();
    controls?.enable(false);
    const v = played.game.verdict!;
    if (run) {
      run.shots.push({ shot: stroke, ...(s.cueBall ? { cueBall: s.cueBall } : {}) });
      if (!v.foul) run.score += run.kind === 'nineball' ? v.potted.length : (v.points[ME] ?? 0);
    }
    void pace.play(played.outcome).then(() => {
      busy = false;
      game = played.game;
      const over = run && (game.turn !== ME || game.winner !== null);
      const end = !over ? '' : run?.issued ? ' The run is over: submit it.' : ' The run is over (offline: not submitted).';
      const said = verdictSentence(played.game, v, nameOf, { me: ME, shot, before: played.from });
      info.textContent = `${said}${run ? ` Score ${run.score}.${end}` : ''}${versusEnd()}`;
      refresh();
      computerTurn();
    });
  }

  /** The player's answer to a choice the rules offer (pass, re-rack), then the computer's turn if it is on. */
  function humanChoice(choice: Game['choices'][number]): void {
    if (busy || !versus || game.turn !== ME) return;
    choose(ME, choice);
  }

  /** A choice the rules offer (pass, re-rack), made by either side; then the computer's turn if it is on. */
  function choose(player: string, choice: Game['choices'][number]): void {
    try {
      game = decide(game, player, choice);
    } catch (err) {
      info.textContent = (err as Error).message;
      return;
    }
    info.textContent = verdictSentence(game, game.verdict!, nameOf, { me: ME });
    refresh();
    computerTurn();
  }

  const versusEnd = () => (versus && game.winner !== null ? (game.winner === ME ? ' You win.' : ' The computer wins.') : '');

  /** The computer's move when it is on turn: thought out in the worker, played after a pause. */
  function computerTurn(): void {
    const v = versus;
    if (!v || game.winner !== null || game.turn !== CPU) return;
    const from = game;
    const mine = started;
    busy = true;
    refresh();
    const pause = new Promise((r) => setTimeout(r, COMPUTER_PAUSE_MS));
    const seed = (v.seed + Math.imul(from.shots + 1, 0x9e3779b1)) >>> 0;
    void Promise.all([mind.think(from, v.level, seed), pause]).then(
      ([d]) => mine === started && game === from && playComputer(d),
      (err: Error) => {
        if (mine !== started) return;
        busy = false;
        info.textContent = `The computer could not play: ${err.message}`;
        refresh();
      },
    );
  }

  function playComputer(d: Decision): void {
    const v = versus!;
    v.moves++;
    if ('choice' in d) {
      busy = false;
      choose(CPU, d.choice);
      return;
    }
    let played;
    try {
      played = playShot(game, d.shot, d.cueBall);
    } catch (err) {
      busy = false;
      info.textContent = `The computer's shot was refused: ${(err as Error).message}`;
      refresh();
      return;
    }
    view!.canvas.dataset.outcomeHash = played.outcome.hash;
    view!.canvas.dataset.computerMoves = String(v.moves);
    last = played.outcome;
    void pace.play(played.outcome).then(() => {
      busy = false;
      game = played.game;
      info.textContent = `${verdictSentence(played.game, played.game.verdict!, nameOf, { me: ME, before: played.from })}${versusEnd()}`;
      refresh();
      computerTurn();
    });
  }

  function doUndo(): void {
    try {
      setup(undo(game));
      info.textContent = 'Shot undone.';
    } catch (err) {
      info.textContent = (err as Error).message;
    }
  }

  let picked: string | null = null;
  function placeDown(e: PointerEvent): void {
    if (!placing.checked || mode.value !== 'free' || !view) return;
    const w = view.toWorld(e.clientX, e.clientY);
    const near = game.balls.find((b) => Math.hypot(b.x - w.x, b.y - w.y) < view!.spec.ballRadius * 1.5);
    picked = near?.id ?? null;
  }
  /** The picked ball follows the pointer until it is let go. */
  function placeMove(e: PointerEvent): void {
    if (!picked || !view) return;
    const w = view.toWorld(e.clientX, e.clientY);
    view.draw(game.balls.map((b) => (b.id === picked ? { id: b.id, x: w.x, y: w.y } : b)));
  }
  function placeUp(e: PointerEvent): void {
    if (!picked || !view) return;
    const w = view.toWorld(e.clientX, e.clientY);
    try {
      setup(placeBall(game, ME, { id: picked, x: w.x, y: w.y }));
      info.textContent = '';
    } catch {
      // (The rules' reason is in metres and table names; the player needs the gist.)
      info.textContent = `The ${picked === 'cue' ? 'cue' : picked} ball cannot go there: it must lie on the cloth, clear of the other balls.`;
      refresh(); // back where it was
    }
    picked = null;
  }

  async function send(): Promise<void> {
    const token = storedToken();
    const r = run;
    if (!r || !r.issued || r.submitted || !token) {
      info.textContent = 'Only a run started while connected to the server can be submitted, and only once.';
      return;
    }
    submit.disabled = true;
    try {
      const res = await submitPractice({ token, kind: r.kind, seed: r.seed, shots: r.shots });
      r.submitted = true;
      const best = res.records.some((x) => x.standing) ? ' A new personal practice record.' : '';
      info.textContent = `The server replayed your run: score ${res.score} (run ${res.id}).${best} Start a new run for another.`;
    } catch (err) {
      // A run the server did not take keeps its seed: it can be sent again once online. A seed
      // used or expired cannot.
      const code = err instanceof ApiRefusal ? err.code : null;
      if (code === 'seed-used' || code === 'seed-not-issued') r.submitted = true;
      info.textContent =
        code === 'seed-used'
          ? 'Not submitted: this run was submitted already. Start a new run for another.'
          : code === 'seed-not-issued'
            ? 'Not submitted: the run was started too long ago (over 6 hours, or 20 runs since). Start a new run.'
            : err instanceof ApiRefusal
              ? `Not submitted: ${err.message}`
              : 'Not submitted: the server cannot be reached. Try again once online.';
    }
    if (run === r) refresh();
  }

  mode.addEventListener('change', reset);
  layout.addEventListener('change', reset);
  runKind.addEventListener('change', reset);
  placing.addEventListener('change', () => {
    info.textContent = placing.checked ? 'Drag a ball to move it; untick "Place balls" to play.' : '';
    refresh();
  });
  const stopSpace = spaceShoots(shoot);
  reset();
  void ctx;
  return () => {
    started++; // a seed still on its way is dropped
    mind.stop();
    stopSpace();
    pace.destroy();
    sound.destroy();
    animator?.stop();
    view?.destroy();
  };
}
