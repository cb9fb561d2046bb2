// The browser client's entry point: today the lobby's status line and the table view.
import { tableSpec } from '../shared/physics/index.ts';
import { mountReplay } from './replay-view.ts';
import { drawTable } from './table-view.ts';

interface Health {
  ok: boolean;
  version: string;
  schema: number;
}

async function showServerStatus(el: HTMLElement): Promise<void> {
  try {
    const res = await fetch('/healthz', { cache: 'no-store' });
    const health = (await res.json()) as Health;
    if (!res.ok || !health.ok) throw new Error(`server answered ${res.status}`);
    el.textContent = `Server online: baize ${health.version}, schema ${health.schema}`;
    el.className = 'ok';
  } catch (err) {
    el.textContent = `Server unreachable: ${(err as Error).message}`;
    el.className = 'error';
  }
}

const status = document.getElementById('server-status');
if (status) void showServerStatus(status);
const canvas = document.getElementById('table');
if (canvas instanceof HTMLCanvasElement) drawTable(canvas, tableSpec('pool-9ft'));
const replay = {
  select: document.getElementById('replay-case'),
  button: document.getElementById('replay-play'),
  canvas: document.getElementById('replay-table'),
  info: document.getElementById('replay-info'),
};
if (replay.select instanceof HTMLSelectElement && replay.button instanceof HTMLButtonElement && replay.canvas instanceof HTMLCanvasElement && replay.info) {
  mountReplay(replay.select, replay.button, replay.canvas, replay.info);
}
