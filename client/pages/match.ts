// A match replayed in the browser from its record (GET /api/matches/:id) with the shared rules and
// physics: a shot list with share links, play and pause, speed. Each shot's hash is checked
// against the one the server broadcast.
import { replayMatch, playShot, type Game, type MatchAction, type MatchRecord } from '../../shared/rules/index.ts';
import { h, KIND_NAMES } from '../dom.ts';
import { api, ApiRefusal } from '../net/api.ts';
import { Animator } from '../table/animator.ts';
import { Tray } from '../table/tray.ts';
import { TableView } from '../table/view.ts';
import { verdictSentence } from '../verdict.ts';
import { count } from '../words.ts';

interface MatchBody extends MatchRecord {
  kind: string;
  players: { id: string; name: string }[];
  result: { winner: string; reason: string } | null;
}

export function mountMatch(root: HTMLElement, _ctx: unknown, id: string): () => void {
  const section = h('section', { 'aria-label': 'Replay' }, h('h2', {}, `Match ${id}`));
  const info = h('p', { role: 'status' });
  root.append(section);
  let live = true;
  let animator: Animator | null = null;
  let view: TableView | null = null;
  api<MatchBody>(`/api/matches/${encodeURIComponent(id)}`).then(
    (m) => {
      if (!live) return;
      const names = (pid: string) => m.players.find((p) => p.id === pid)?.name ?? pid;
      let replayed;
      try {
        replayed = replayMatch(m);
      } catch (err) {
        info.textContent = `The record does not replay: ${(err as Error).message}`;
        section.append(info);
        return;
      }
      const bad = replayed.shots.filter((s) => s.recorded !== undefined && s.recorded !== s.hash).length;
      const tableBox = h('div', { className: 'table-box' });
      const speed = h('select', { 'aria-label': 'Speed' }, ...['0.5', '1', '2', '4'].map((v) => h('option', { value: v, selected: v === '1' }, `${v}×`)));
      const play = h('button', { type: 'button' }, 'Play');
      const list = h('ol', { className: 'shots', 'aria-label': 'Shots' });
      const tray = new Tray();
      section.replaceChildren(
        h('h2', {}, `${KIND_NAMES[m.kind] ?? m.kind}: ${m.players.map((p) => p.name).join(' v ')}`),
        h('p', {}, m.result ? `${names(m.result.winner)} won (${m.result.reason}).` : 'In play.', ` ${count(replayed.shots.length, 'shot')}; ${bad === 0 ? 'every hash matches the server\'s' : bad === 1 ? '1 hash differs from the server\'s' : `${bad} hashes differ from the server's`}.`),
        tableBox,
        tray.element,
        h('p', {}, play, ' ', h('label', {}, 'Speed ', speed)),
        info,
        list,
      );
      view = new TableView(tableBox, m.start.table, 'Replay table');
      animator = new Animator(view);
      const before: Game[] = [m.start, ...replayed.games];
      view.draw(m.start.balls);
      tray.update(m.start);
      let current = 0;
      let playing = false;
      const shotIndexes = m.actions.map((a, i) => (a.type === 'shot' ? i : -1)).filter((i) => i >= 0);
      const links: HTMLAnchorElement[] = [];
      // Each shot played once, kept: the tray's order at shot k is every pot of the shots before it,
      // so a jump to a shot shows the tray of the game there, in the order the balls went down.
      const playedShots: ReturnType<typeof playShot>[] = [];
      const playedAt = (k: number) => {
        const i = shotIndexes[k]!;
        const a = m.actions[i] as Extract<MatchAction, { type: 'shot' }>;
        return (playedShots[k] ??= playShot(before[i]!, { ...a.shot, player: a.player } as never, a.cueBall));
      };
      const potsBefore = (k: number) =>
        Array.from({ length: k }, (_, j) => playedAt(j).outcome.events.filter((e) => e.kind === 'pocket').map((e) => e.balls[0]!)).flat();
      /** The shot shown last: a shot's tray is set after its drops only if no other was picked meanwhile. */
      let showing = 0;
      const show = async (k: number) => {
        const token = ++showing;
        links.forEach((a, j) => (j === k ? a.setAttribute('aria-current', 'step') : a.removeAttribute('aria-current')));
        const i = shotIndexes[k]!;
        const a = m.actions[i] as Extract<MatchAction, { type: 'shot' }>;
        const played = playedAt(k);
        tray.update(before[i]!, potsBefore(k));
        view!.canvas.dataset.outcomeHash = played.outcome.hash;
        const v = played.game.verdict;
        info.textContent = `Shot ${k + 1}: ${v ? verdictSentence(played.game, v, names, { shot: a.shot as { pushOut?: boolean; calledPocket?: string }, before: before[i]! }) : ''}`;
        await animator!.play(played.outcome, Number(speed.value));
        // The balls have dropped: they show in the tray (the game after this shot).
        if (token === showing) tray.update(played.game, potsBefore(k + 1));
      };
      const run = async () => {
        playing = true;
        play.textContent = 'Pause';
        while (playing && current < shotIndexes.length && live) await show(current++);
        playing = false;
        play.textContent = 'Play';
      };
      play.addEventListener('click', () => {
        if (playing) {
          playing = false;
          animator?.stop();
        } else {
          if (current >= shotIndexes.length) current = 0; // from the start again
          void run();
        }
      });
      // The shots, each a link; between them what else decided the match (the clock, a
      // concession, a claim), so that the list ends where the result says.
      const others: Partial<Record<MatchAction['type'], string>> = { clock: 'ran out of time', concede: 'conceded', claim: 'claimed the game' };
      list.append(
        ...m.actions.flatMap((a, i) => {
          if (a.type !== 'shot') {
            const what = others[a.type];
            return what && 'player' in a ? [h('li', { className: 'event' }, `${names(a.player)} ${what}`)] : [];
          }
          const k = shotIndexes.indexOf(i);
          const link = h('a', { href: `/match/${id}#shot=${k + 1}`, onclick: (e: Event) => {
            e.preventDefault();
            history.replaceState(null, '', `/match/${id}#shot=${k + 1}`);
            // A shot picked while the replay plays: the replay stops there.
            playing = false;
            animator?.stop();
            current = k;
            void show(current++);
          } }, `${names(a.player)}: ${a.shot.speed.toFixed(1)} m/s`);
          links.push(link);
          return [h('li', {}, link)];
        }),
      );
      const linked = /#shot=(\d+)/.exec(location.hash);
      if (linked) {
        current = Math.max(0, Math.min(shotIndexes.length - 1, Number(linked[1]) - 1));
        void show(current++);
      }
    },
    // A malformed id (400) or an unknown one (404): said in words, not the API's parameter check.
    (err: Error) => section.append(h('p', { role: 'status' }, err instanceof ApiRefusal && (err.status === 400 || err.status === 404) ? 'No such match.' : err.message)),
  );
  return () => {
    live = false;
    animator?.stop();
    view?.destroy();
  };
}
