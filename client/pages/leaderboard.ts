// The leaderboard of each game kind, from the HTTP API, and its records: those set in matches and
// those set in practice runs apart (a practice run can be planned by a computer).
import { h, KIND_NAMES, link } from '../dom.ts';
import { api } from '../net/api.ts';
import { count } from '../words.ts';

interface Board {
  total: number;
  entries: { rank: number; player: { id: string; name: string }; rating: number; rd: number; games: number; wins: number }[];
}

interface Records {
  entries: { rank: number; value: number; player: { id: string; name: string }; match?: number; practice?: number }[];
}

/** The kinds with records: what is recorded and in what unit. */
const RECORDS: Readonly<Record<string, { title: string; unit: string }>> = {
  snooker: { title: 'Highest breaks', unit: 'Points' },
  threecushion: { title: 'Highest runs', unit: 'Points' },
  nineball: { title: 'Break-and-runs (fewest shots)', unit: 'Shots' },
};

/** A table of records from one source, filled from the API. */
function recordsTable(label: string): { element: HTMLElement; show: (kind: string, live: () => boolean) => void } {
  const body = h('tbody');
  const head = h('tr');
  const status = h('p', { role: 'status' });
  const element = h('div', {}, h('h4', {}, label), h('div', { className: 'scroll-x' }, h('table', { className: 'board', 'aria-label': label }, h('thead', {}, head), body)), status);
  const source = label.startsWith('Practice') ? 'practice' : 'match';
  return {
    element,
    show(kind, live) {
      head.replaceChildren(...['#', 'Player', RECORDS[kind]!.unit, 'From'].map((t) => h('th', {}, t)));
      api<Records>(`/api/records?kind=${kind}&source=${source}&limit=10`).then(
        (r) => {
          if (!live()) return;
          body.replaceChildren(
            ...r.entries.map((e) =>
              h('tr', {}, h('td', {}, e.rank), h('td', {}, link(`/player/${e.player.id}`, e.player.name)), h('td', {}, e.value), h('td', {}, e.match ? link(`/match/${e.match}`, 'match') : `practice run ${e.practice}`)),
            ),
          );
          status.textContent = r.entries.length === 0 ? 'None yet.' : '';
        },
        (err: Error) => live() && (status.textContent = err.message),
      );
    },
  };
}

export function mountLeaderboard(root: HTMLElement): () => void {
  const params = new URLSearchParams(location.search);
  let kind = params.get('kind') ?? 'nineball';
  let offset = Number(params.get('offset') ?? 0) || 0;
  const body = h('tbody');
  const info = h('p', { role: 'status' });
  const tabs = h('nav', { className: 'tabs', 'aria-label': 'Game' });
  const table = h('table', { className: 'board', 'aria-label': 'Leaderboard' }, h('thead', {}, h('tr', {}, ...['#', 'Player', 'Rating', 'RD', 'Games', 'Wins'].map((t) => h('th', {}, t)))), body);
  const prev = h('button', { type: 'button', onclick: () => load(kind, Math.max(0, offset - 20)) }, 'Previous');
  const next = h('button', { type: 'button', onclick: () => load(kind, offset + 20) }, 'Next');
  const fromMatches = recordsTable('Match records');
  const fromPractice = recordsTable('Practice records');
  const recordsTitle = h('h3', {});
  const records = h(
    'section',
    { 'aria-label': 'Records' },
    recordsTitle,
    fromMatches.element,
    fromPractice.element,
    h('p', {}, 'The server replays every practice run from a rack it dealt, but a computer can still plan a run once it is dealt: practice records are listed apart from those set in matches, one per player.'),
  );
  root.append(h('section', { 'aria-label': 'Leaderboard' }, h('h2', {}, 'Leaderboard'), tabs, h('div', { className: 'scroll-x' }, table), h('p', {}, prev, ' ', next), info), records);
  let live = true;
  let recordsShown: string | null = null;
  const showRecords = (k: string) => {
    recordsShown = k;
    records.hidden = !Object.hasOwn(RECORDS, k);
    if (records.hidden) return;
    recordsTitle.textContent = `Records: ${RECORDS[k]!.title.toLowerCase()}`;
    fromMatches.show(k, () => live && kind === k);
    fromPractice.show(k, () => live && kind === k);
  };
  const load = (k: string, o: number) => {
    kind = k;
    offset = o;
    tabs.replaceChildren(...Object.entries(KIND_NAMES).map(([v, t]) => h('button', { type: 'button', 'aria-pressed': v === kind ? 'true' : 'false', onclick: () => load(v, 0) }, t)));
    history.replaceState(null, '', `/leaderboard?kind=${k}${o ? `&offset=${o}` : ''}`);
    if (k !== recordsShown) showRecords(k);
    api<Board>(`/api/leaderboard?kind=${k}&limit=20&offset=${o}`).then(
      (b) => {
        if (!live) return;
        body.replaceChildren(
          ...b.entries.map((e) =>
            h('tr', {}, h('td', {}, e.rank), h('td', {}, link(`/player/${e.player.id}`, e.player.name)), h('td', {}, Math.round(e.rating)), h('td', {}, Math.round(e.rd)), h('td', {}, e.games), h('td', {}, e.wins)),
          ),
        );
        // Provisional ratings (RD 110 or more) are not listed: a player's own page shows theirs.
        info.textContent = `${b.total === 0 ? 'Nobody is ranked yet' : count(b.total, 'ranked player')}: a player is listed once their rating is established (RD under 110).`;
        prev.disabled = o === 0;
        next.disabled = o + 20 >= b.total;
      },
      (err: Error) => (info.textContent = err.message),
    );
  };
  load(kind, offset);
  return () => {
    live = false;
  };
}
