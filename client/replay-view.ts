// The debug view: any shot of the golden corpus simulated here, in the browser, with the same
// shared module the server runs, animated from its closed-form paths, with its hash shown so it
// can be compared with the server's.
import { sampleOutcome, simulate, tableSpec, type Outcome } from '../shared/physics/index.ts';
import { CORPUS } from '../shared/scenes/index.ts';
import { drawTable } from './table-view.ts';

export function mountReplay(select: HTMLSelectElement, button: HTMLButtonElement, canvas: HTMLCanvasElement, info: HTMLElement): void {
  CORPUS.forEach((c, i) => {
    const option = document.createElement('option');
    option.value = String(i);
    option.textContent = c.name;
    select.append(option);
  });
  let frame = 0;
  button.addEventListener('click', () => {
    const c = CORPUS[Number(select.value)];
    if (!c) return;
    cancelAnimationFrame(frame);
    const table = tableSpec(c.scene.table);
    let outcome: Outcome;
    try {
      outcome = simulate(c.scene, c.shot);
    } catch (err) {
      info.textContent = `error: ${(err as Error).message}`;
      return;
    }
    info.dataset.hash = outcome.hash;
    info.textContent = `${c.name}: ${outcome.events.length} events, ${outcome.duration.toFixed(2)} s, hash ${outcome.hash}`;
    const start = performance.now();
    const draw = (now: number) => {
      const t = Math.min(outcome.duration, (now - start) / 1000);
      drawTable(canvas, table, sampleOutcome(outcome, t).filter((b) => b.motion !== 'pocketed'));
      if (t < outcome.duration) frame = requestAnimationFrame(draw);
      else info.dataset.done = 'true';
    };
    delete info.dataset.done;
    frame = requestAnimationFrame(draw);
  });
}
