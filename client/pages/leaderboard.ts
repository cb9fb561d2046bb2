// The leaderboard of each game kind, from the HTTP API.
import { h, KIND_NAMES, link } from '../dom.ts';
import { api } from '../net/api.ts';

interface Board {
  total: number;
  entries: { rank: number; player: { id: string; name: string }; rating: number; rd: number; games: number; wins: number }[];
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
  root.append(h('section', { 'aria-label': 'Leaderboard' }, h('h2', {}, 'Leaderboard'), tabs, h('div', { className: 'scroll-x' }, table), h('p', {}, prev, ' ', next), info));
  let live = true;
  const load = (k: string, o: number) => {
    kind = k;
    offset = o;
    tabs.replaceChildren(...Object.entries(KIND_NAMES).map(([v, t]) => h('button', { type: 'button', 'aria-pressed': v === kind ? 'true' : 'false', onclick: () => load(v, 0) }, t)));
    history.replaceState(null, '', `/leaderboard?kind=${k}${o ? `&offset=${o}` : ''}`);
    api<Board>(`/api/leaderboard?kind=${k}&limit=20&offset=${o}`).then(
      (b) => {
        if (!live) return;
        body.replaceChildren(
          ...b.entries.map((e) =>
            h('tr', {}, h('td', {}, e.rank), h('td', {}, link(`/player/${e.player.id}`, e.player.name)), h('td', {}, Math.round(e.rating)), h('td', {}, Math.round(e.rd)), h('td', {}, e.games), h('td', {}, e.wins)),
          ),
        );
        // Provisional ratings (RD 110 or more) are not listed: a player's own page shows theirs.
        info.textContent = `${b.total === 0 ? 'Nobody is ranked yet' : `${b.total} ranked players`}: a player is listed once their rating is established (RD under 110).`;
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
