// The lobby: the rooms as they change, a form to open a table, who is online, and your name.
import type { LobbyRoom, ServerMessage } from '../../shared/protocol/index.ts';
import { NAME_MAX } from '../../shared/protocol/limits.ts';
import { cutGraphemes, graphemeCount } from '../../shared/protocol/text.ts';
import { h, KIND_NAMES, link } from '../dom.ts';
import type { PageContext } from '../main.ts';

export function mountLobby(root: HTMLElement, ctx: PageContext): () => void {
  const { session } = ctx;
  const rooms = h('ul', { className: 'rooms', 'aria-label': 'Rooms' });
  const more = h('p', { className: 'more' });
  const online = h('p', { className: 'online', 'aria-label': 'Online' });
  const note = h('p', { role: 'status', className: 'note' });
  const kind = h('select', { name: 'kind', 'aria-label': 'Game' }, ...Object.entries(KIND_NAMES).map(([v, t]) => h('option', { value: v }, t)));
  const race = h('input', { name: 'raceTo', type: 'number', min: 1, max: 50, value: 1, 'aria-label': 'Race to' });
  const clock = h('input', { name: 'shotClock', type: 'number', min: 0, max: 600, value: 0, title: '0 for no clock, or 10 to 600 seconds', 'aria-label': 'Shot clock (s)' });
  const priv = h('input', { name: 'private', type: 'checkbox', 'aria-label': 'Private' });
  const guidance = h(
    'select',
    { name: 'guidance', 'aria-label': 'Guidance' },
    h('option', { value: 'contact' }, 'Aim to first contact'),
    h('option', { value: 'path' }, 'Full cue-ball path'),
    h('option', { value: 'none' }, 'No guidance'),
  );
  const level = h('select', { name: 'level', 'aria-label': 'Level' }, ...[1, 2, 3, 4, 5].map((n) => h('option', { value: String(n) }, `Level ${n}`)));
  level.value = '3';
  const versus = h('button', { type: 'button' }, 'Play the computer');
  // A kind's usual race, put in unless the player typed their own.
  const usualRace = (k: string) => (k === 'threecushion' ? '15' : '1');
  let kindBefore = kind.value;
  kind.addEventListener('change', () => {
    if (race.value === '' || race.value === usualRace(kindBefore)) race.value = usualRace(kind.value);
    kindBefore = kind.value;
  });
  const create = h(
    'form',
    { className: 'create', 'aria-label': 'New table' },
    h('label', {}, 'Game ', kind),
    h('label', {}, 'Race to ', race),
    h('label', {}, 'Shot clock (s) ', clock),
    h('label', {}, 'Guidance ', guidance),
    h('label', {}, priv, ' Private'),
    h('button', { type: 'submit' }, 'Create table'),
    h('span', { className: 'versus' }, ' or ', h('label', {}, 'Level ', level), ' ', versus),
  );
  // The same table, the computer (thinking on the server) taking the second seat at once.
  const open = (computer?: number) => {
    note.textContent = '';
    void session
      .request({
        type: 'create',
        ...(computer === undefined ? {} : { computer }),
        kind: kind.value as LobbyRoom['kind'],
        // An empty field takes the server's default.
        ...(race.value === '' ? {} : { raceTo: Number(race.value) }),
        ...(clock.value === '' ? {} : { shotClock: Number(clock.value) }),
        private: priv.checked,
        guidance: guidance.value as 'contact',
      })
      .then((m) => {
        if (m.type === 'room') ctx.navigate(`/room/${m.room.id}`);
        else if (m.type === 'error') note.textContent = m.message;
      }, (err: Error) => (note.textContent = err.message));
  };
  create.addEventListener('submit', (e) => {
    e.preventDefault();
    open();
  });
  versus.addEventListener('click', () => open(Number(level.value)));
  // No maxlength: it counts UTF-16 code units and would cut an emoji in half. The limit counts
  // characters as people see them (a flag or a family emoji is one); a longer paste is cut whole.
  const name = h('input', { name: 'name', 'aria-label': 'Your name' });
  const nameNote = h('span', { className: 'note', role: 'status' });
  name.addEventListener('input', () => {
    const n = graphemeCount(name.value);
    nameNote.textContent = n > NAME_MAX ? `A name has at most ${NAME_MAX} characters: cut to the first ${NAME_MAX}.` : '';
    if (n > NAME_MAX) name.value = cutGraphemes(name.value, NAME_MAX);
  });
  const rename = h('form', { className: 'rename', 'aria-label': 'Your name' }, h('label', {}, 'Your name ', name), h('button', { type: 'submit' }, 'Change name'), nameNote);
  rename.addEventListener('submit', (e) => {
    e.preventDefault();
    note.textContent = '';
    nameNote.textContent = '';
    void session.request({ type: 'rename', name: name.value }).then((m) => {
      if (m.type === 'player') name.value = m.player.name;
      note.textContent = m.type === 'error' ? m.message : m.type === 'player' ? `You are ${m.player.name}` : '';
    });
  });

  root.append(
    h('section', { 'aria-label': 'Lobby' }, h('h2', {}, 'Lobby'), rooms, more, note),
    h('section', { 'aria-label': 'Open a table' }, h('h2', {}, 'Open a table'), create),
    h('section', { 'aria-label': 'Players' }, h('h2', {}, 'Online'), online, rename, h('p', {}, link('/practice', 'Practise alone'), ' · ', link('/leaderboard', 'Leaderboard'), ' · ', link('/help', 'How to play'))),
  );

  const render = (list: readonly LobbyRoom[], notListed: number) => {
    // The server lists a few hundred rooms, waiting ones first, and counts the rest.
    more.textContent = notListed > 0 ? `and ${notListed} more` : '';
    rooms.replaceChildren(
      ...(list.length === 0 ? [h('li', { className: 'empty' }, 'No tables yet: open one.')] : []),
      ...list.map((r) => {
        const invite = `${location.origin}/room/${r.id}`;
        return h(
          'li',
          { 'data-room': r.id },
          h('span', { className: 'kind' }, KIND_NAMES[r.kind] ?? r.kind),
          ` race to ${r.raceTo} · `,
          r.players.map((p) => p.name).join(' v ') || 'empty',
          ` · ${r.status}${r.spectators ? ` · ${r.spectators} watching` : ''} `,
          h('a', { href: `/room/${r.id}`, 'data-link': true, className: 'button' }, r.players.some((p) => p.id === session.player?.id) ? 'Open' : r.status === 'waiting' ? 'Join' : 'Watch'),
          h('button', { type: 'button', onclick: () => void navigator.clipboard?.writeText(invite).then(() => (note.textContent = `Invite link copied: ${invite}`)) }, 'Copy invite link'),
        );
      }),
    );
  };
  const stop = session.onMessage((m: ServerMessage) => {
    if (m.type === 'lobby') {
      render(m.rooms, m.more ?? 0);
      const who = m.online ?? [];
      online.textContent = who.length === 0 ? 'Nobody else yet.' : who.map((p) => p.name).join(', ');
    }
    if (m.type === 'welcome' || m.type === 'player') {
      if (document.activeElement !== name) name.value = m.player.name;
      // "You are ..." says the name the server stored, and follows a rename in another tab.
      if (note.textContent?.startsWith('You are ')) note.textContent = `You are ${m.player.name}`;
    }
  });
  if (session.player && document.activeElement !== name) name.value = session.player.name;
  session.keep('lobby', { type: 'lobby' });
  return () => {
    stop();
    session.forget('lobby');
    session.send({ type: 'lobby', watch: false });
  };
}
