// The browser client's entry point: one page per path, a guest session over the WebSocket, and
// links handled here so the page never reloads.
import { pageOf, type PageName } from '../shared/protocol/pages.ts';
import { h } from './dom.ts';
import { Session } from './net/session.ts';
import { mountHelp } from './pages/help.ts';
import { mountLab } from './pages/lab.ts';
import { mountLeaderboard } from './pages/leaderboard.ts';
import { mountLobby } from './pages/lobby.ts';
import { mountMatch } from './pages/match.ts';
import { mountPlayer } from './pages/player.ts';
import { mountPractice } from './pages/practice.ts';
import { mountRoom } from './pages/room.ts';

export interface PageContext {
  readonly session: Session;
  readonly navigate: (path: string) => void;
}
type Page = (root: HTMLElement, ctx: PageContext, param: string) => () => void;

/** Each page's mount; the paths are in shared/protocol/pages.ts, which the server serves too. */
const MOUNTS: Readonly<Record<PageName, Page>> = {
  lobby: mountLobby,
  room: mountRoom,
  practice: mountPractice,
  leaderboard: mountLeaderboard,
  player: mountPlayer,
  match: mountMatch,
  lab: mountLab,
  help: mountHelp,
};

const root = document.getElementById('app')!;
const session = new Session();
let unmount: (() => void) | undefined;

function route(): void {
  unmount?.();
  root.replaceChildren();
  const page = pageOf(location.pathname);
  if (page) {
    unmount = MOUNTS[page.name](root, { session, navigate }, decodeURIComponent(page.param));
    return;
  }
  root.append(h('p', {}, 'No such page. '), h('a', { href: '/', 'data-link': true }, 'Back to the lobby'));
  unmount = undefined;
}

function navigate(path: string): void {
  history.pushState(null, '', path);
  route();
}

document.addEventListener('click', (e) => {
  const a = (e.target as Element | null)?.closest?.('a[data-link]') as HTMLAnchorElement | null;
  if (!a || e.ctrlKey || e.metaKey || e.shiftKey) return;
  e.preventDefault();
  navigate(a.getAttribute('href')!);
});
window.addEventListener('popstate', route);

const status = document.getElementById('server-status')!;
session.onStatus((s) => {
  status.textContent = s === 'online' ? `Playing as ${session.player?.name ?? ''}` : s === 'connecting' ? 'Connecting…' : 'Reconnecting…';
  status.className = s === 'online' ? 'ok' : 'warn';
});
session.onMessage((m) => {
  if (m.type === 'player' && session.status === 'online') status.textContent = `Playing as ${m.player.name}`;
  // A hello the server refused (say, too many tabs open): its reason, until the next try.
  if (m.type === 'error' && m.re === 'hello' && m.code !== 'bad-token') status.textContent = m.message;
});
route();
