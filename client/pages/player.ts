// A player's page: ratings per game, best records, recent matches (more on request, a page at a
// time from GET /api/matches).
import { h, KIND_NAMES, link } from '../dom.ts';
import { api, ApiRefusal } from '../net/api.ts';
import { count } from '../words.ts';

interface MatchSummary {
  id: number;
  kind: string;
  players: { id: string; name: string }[];
  status: string;
  result: { winner: string } | null;
}

/** Matches fetched per "More matches". */
const PAGE = 20;

function matchItem(m: MatchSummary): HTMLElement {
  const outcome = m.result ? ` · won by ${m.players.find((x) => x.id === m.result!.winner)?.name ?? ''}` : ` · ${m.status}`;
  return h('li', {}, link(`/match/${m.id}`, `${KIND_NAMES[m.kind] ?? m.kind}: ${m.players.map((x) => x.name).join(' v ')}`), outcome);
}

interface PlayerPage {
  name: string;
  games: number;
  wins: number;
  ratings: Record<string, { rating: number; rd: number; games: number; wins: number; provisional: boolean }>;
  records: { kind: string; what: string; value: number; match?: number; practice?: number }[];
  recent: MatchSummary[];
}

export function mountPlayer(root: HTMLElement, _ctx: unknown, id: string): () => void {
  const section = h('section', { 'aria-label': 'Player' }, h('h2', {}, 'Player'));
  root.append(section);
  let live = true;
  api<PlayerPage>(`/api/players/${encodeURIComponent(id)}`).then(
    (p) => {
      if (!live) return;
      const matches = h('ul', { 'aria-label': 'Recent matches' }, ...p.recent.map(matchItem));
      // (The player's record lists the 10 newest: fewer means there are no more.)
      const more: HTMLButtonElement = h('button', { type: 'button', hidden: p.recent.length < 10 }, 'More matches');
      more.onclick = () => {
        more.disabled = true;
        const offset = matches.children.length;
        api<{ matches: MatchSummary[] }>(`/api/matches?player=${encodeURIComponent(id)}&limit=${PAGE}&offset=${offset}`).then(
          (page) => {
            if (!live) return;
            matches.append(...page.matches.map(matchItem));
            more.disabled = false;
            if (page.matches.length < PAGE) more.hidden = true;
          },
          (err: Error) => {
            more.disabled = false;
            section.append(h('p', { role: 'status' }, err.message));
          },
        );
      };
      section.replaceChildren(
        h('h2', {}, p.name),
        h('p', {}, `${count(p.games, 'rated game')}, ${p.wins} won.`),
        h('ul', { 'aria-label': 'Ratings' }, ...Object.entries(p.ratings).map(([k, r]) => h('li', {}, `${KIND_NAMES[k] ?? k}: ${Math.round(r.rating)}${r.provisional ? '? (provisional, ' : ' ('}RD ${Math.round(r.rd)}), ${count(r.games, 'game')}, ${r.wins} won`))),
        h('h3', {}, 'Records'),
        h('ul', { 'aria-label': 'Records' }, ...p.records.map((r) => h('li', {}, `${KIND_NAMES[r.kind] ?? r.kind}: ${r.what} ${r.value}${r.practice ? ' (practice)' : ''}`, r.match ? h('span', {}, ' · ', link(`/match/${r.match}`, 'replay')) : ''))),
        h('h3', {}, 'Recent matches'),
        matches,
        more,
      );
    },
    // A malformed id (400) or an unknown one (404): said in words, not the API's parameter check.
    (err: Error) => section.append(h('p', { role: 'status' }, err instanceof ApiRefusal && (err.status === 400 || err.status === 404) ? 'No such player.' : err.message)),
  );
  return () => {
    live = false;
  };
}
