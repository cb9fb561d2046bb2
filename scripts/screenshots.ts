// npm run screenshots — docs/screenshots/*.png (lobby, table, stroke, ball in hand, result, pot and
// tray, help, phone, leaderboard, lab) from a real server and
// Debian's Chromium: a few rooms and rated matches made by protocol clients, then the pages.
import { mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { ProtocolClient } from '../bots/client.ts';
import type { ServerMessage } from '../shared/protocol/index.ts';
import { launchChromium } from '../tests/support/browser.ts';
import { openDatabase } from '../server/database.ts';
import { Store } from '../server/store/index.ts';
import { hashToken } from '../server/tokens.ts';
import { buildClient } from './build-client.ts';
import { newGame } from '../shared/rules/index.ts';
import { pottingBreak } from '../tests/support/potting-break.ts';
import { tableOnScreen } from '../tests/support/table-screen.ts';
import { ROOT, startServerProcess, tempDir } from '../tests/support/server-process.ts';

const OUT = resolve(ROOT, 'docs/screenshots');
await buildClient();
mkdirSync(OUT, { recursive: true });
const names = ['Ronnie', 'Efren', 'Shane', 'Jasmin', 'Torbjörn', 'Kelly'];
const dbPath = join(tempDir(), 'baize.db');
// The leaderboard ranks established ratings only (RD under 110), which take many real games: the
// players here come with nine-ball ratings as if they had played them.
{
  const { db } = openDatabase(dbPath, join(ROOT, 'migrations'));
  const store = new Store(db);
  names.forEach((name, i) => {
    const p = store.createPlayer(name, hashToken(`screenshot-${name}`));
    db.prepare("INSERT INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES ('nineball', ?, ?, ?, 0.06, ?, ?, 0)").run(
      p.id, 1760 - 61 * i, 62 + 7 * i, 40 - 3 * i, 26 - 3 * i,
    );
  });
  db.close();
}
const server = await startServerProcess({ BAIZE_DB: dbPath });
const ws = `${server.url.replace('http', 'ws')}/ws`;

async function player(name: string): Promise<{ c: ProtocolClient; id: string; last: () => { stateId: number; turn: string } }> {
  const known = names.includes(name);
  const c = await ProtocolClient.connect(ws);
  let state = { stateId: 0, turn: '' };
  c.onMessage((m: ServerMessage) => {
    if (m.type === 'room' && m.room.game) state = { stateId: m.room.stateId, turn: m.room.game.turn };
    if (m.type === 'shot') state = { stateId: m.stateId, turn: m.game.turn };
  });
  const w = await c.request(known ? { type: 'hello', token: `screenshot-${name}` } : { type: 'hello', name });
  return { c, id: w.type === 'welcome' ? w.player.id : '', last: () => state };
}

/** A match between two clients (too short to be rated): each plays two soft fouls, then the loser concedes. */
async function shortMatch(a: Awaited<ReturnType<typeof player>>, b: Awaited<ReturnType<typeof player>>, kind: 'nineball' | 'snooker'): Promise<void> {
  const r = await a.c.request({ type: 'create', kind });
  const room = r.type === 'room' ? r.room.id : '';
  await b.c.request({ type: 'join', room });
  for (let i = 0; i < 4; i++) {
    await new Promise((res) => setTimeout(res, 50));
    const s = a.last();
    const who = s.turn === a.id ? a : b;
    await who.c.request({ type: 'shot', room, stateId: s.stateId, shot: { ball: 'cue', heading: Math.PI, speed: 0.05, side: 0, top: 0 } });
  }
  await b.c.request({ type: 'concede', room });
}

const ps = [];
for (const n of names) ps.push(await player(n));
for (let i = 0; i < 6; i++) await shortMatch(ps[i % 6]!, ps[(i + 1) % 6]!, 'nineball');
await shortMatch(ps[0]!, ps[2]!, 'nineball');
await ps[3]!.c.request({ type: 'create', kind: 'snooker', raceTo: 3 });
await ps[4]!.c.request({ type: 'create', kind: 'threecushion', raceTo: 15 });
const playing = await ps[5]!.c.request({ type: 'create', kind: 'eightball', raceTo: 2 });
await ps[1]!.c.request({ type: 'join', room: playing.type === 'room' ? playing.room.id : '' });

const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: 1100, height: 760 }, deviceScaleFactor: 1 });
  await page.goto(`${server.url}/`);
  await page.waitForSelector('.rooms li[data-room]');
  await page.screenshot({ path: join(OUT, 'lobby.png') });

  // A table mid-game: this page breaks against a protocol client in the other seat.
  await page.getByRole('button', { name: 'Create table' }).click();
  await page.waitForURL(/\/room\//);
  const roomId = page.url().split('/').at(-1)!;
  const opponent = await player('Allison');
  await opponent.c.request({ type: 'join', room: roomId });
  await page.waitForFunction(() => !(document.querySelector('button.shoot') as HTMLButtonElement).disabled);
  // The break from the kitchen: the ball in hand with its legal area drawn.
  await page.screenshot({ path: join(OUT, 'ball-in-hand.png') });
  // The stroke being drawn back: pressed on the cue ball and pulled straight back, not let go.
  const g = newGame('nineball', ['a', 'b'], { seed: 1 });
  const at = (await tableOnScreen(page, g.table)).at(g.balls.find((b) => b.id === 'cue')!);
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) await page.mouse.move(at.x - 12 * i, at.y);
  await page.screenshot({ path: join(OUT, 'stroke.png') });
  await page.mouse.move(at.x, at.y);
  await page.mouse.up();
  await page.getByRole('button', { name: 'Shoot' }).click();
  await page.waitForTimeout(1200);
  await page.screenshot({ path: join(OUT, 'table.png') });
  // The end: the opponent concedes; the result dialog.
  await opponent.c.request({ type: 'concede', room: roomId });
  await page.getByRole('dialog').waitFor({ timeout: 30_000 });
  await page.waitForTimeout(500);
  await page.screenshot({ path: join(OUT, 'result.png') });

  // A pot and the tray: the practice table's first break aimed by the keys to pot two balls or more.
  await page.goto(`${server.url}/practice`);
  await page.waitForSelector('canvas.table');
  await page.locator('canvas.table').focus();
  for (const key of pottingBreak().presses) await page.keyboard.press(key);
  await page.getByRole('button', { name: 'Shoot' }).click();
  await page.getByRole('list', { name: 'Pocketed' }).getByRole('listitem').nth(1).waitFor({ timeout: 30_000 });
  await page.waitForTimeout(300);
  await page.getByRole('list', { name: 'Pocketed' }).scrollIntoViewIfNeeded();
  await page.screenshot({ path: join(OUT, 'pot-tray.png'), fullPage: true });

  await page.goto(`${server.url}/help`);
  await page.getByRole('heading', { name: 'Snooker' }).waitFor();
  await page.screenshot({ path: join(OUT, 'help.png') });

  // A phone on its side, in a room.
  const phoneCtx = await browser.newContext({ viewport: { width: 844, height: 390 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 });
  const phone = await phoneCtx.newPage();
  await phone.goto(`${server.url}/`);
  await phone.getByRole('button', { name: 'Create table' }).click();
  await phone.waitForURL(/\/room\//);
  const other = await player('Karen');
  await other.c.request({ type: 'join', room: phone.url().split('/').at(-1)! });
  await phone.getByRole('button', { name: 'Shoot' }).waitFor();
  await phone.waitForTimeout(500);
  await phone.screenshot({ path: join(OUT, 'phone.png') });
  await phoneCtx.close();

  await page.goto(`${server.url}/leaderboard?kind=nineball`);
  await page.waitForSelector('table.board tbody tr');
  await page.screenshot({ path: join(OUT, 'leaderboard.png') });

  // The physics lab: the controls and the rebound, then Fig. 9 and Fig. 12 with the phases.
  await page.goto(`${server.url}/lab`);
  await page.waitForSelector('#fig12 svg');
  await page.getByRole('table', { name: 'Speed against error' }).locator('tbody tr').first().waitFor();
  await page.screenshot({ path: join(OUT, 'lab.png') });
  await page.locator('#fig9').screenshot({ path: join(OUT, 'lab-fig9.png') });
  await page.locator('#fig12').screenshot({ path: join(OUT, 'lab-fig12.png') });
  console.log(`screenshots written to ${OUT}`);
} finally {
  await browser.close();
  await server.stop('SIGKILL');
  process.exit(0);
}
