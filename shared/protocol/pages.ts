// The client's page paths, listed once: the server answers each with the client's document and
// the client's router (client/main.ts) shows the page of the path. Pure: no DOM, no Node.

export type PageName = 'lobby' | 'room' | 'practice' | 'leaderboard' | 'player' | 'match' | 'lab' | 'help';

/** Each page and its path; a page with a parameter (an id) captures it as group 1. */
export const PAGES: readonly { readonly name: PageName; readonly path: RegExp }[] = [
  { name: 'lobby', path: /^\/$/ },
  { name: 'room', path: /^\/room\/([A-Za-z0-9_-]{1,64})$/ },
  { name: 'practice', path: /^\/practice$/ },
  { name: 'leaderboard', path: /^\/leaderboard$/ },
  { name: 'player', path: /^\/player\/([A-Za-z0-9_-]{1,64})$/ },
  { name: 'match', path: /^\/match\/([A-Za-z0-9_-]{1,64})$/ },
  { name: 'lab', path: /^\/lab$/ },
  { name: 'help', path: /^\/help$/ },
];

/** The page a path (without its query) shows, with its parameter ('' when none). */
export function pageOf(path: string): { readonly name: PageName; readonly param: string } | undefined {
  for (const p of PAGES) {
    const m = p.path.exec(path);
    if (m) return { name: p.name, param: m[1] ?? '' };
  }
  return undefined;
}
