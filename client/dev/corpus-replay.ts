// The debug view (a dev page, not the game's bundle): any shot of the golden corpus simulated
// here, in the browser, with the same shared module the server runs, animated from its
// closed-form paths, with its hash shown so it can be compared with the server's.
import { simulate, type Outcome } from '../../shared/physics/index.ts';
import { CORPUS } from '../../shared/scenes/index.ts';
import { Animator } from '../table/animator.ts';
import { TableView } from '../table/view.ts';

export function mountCorpusReplay(select: HTMLSelectElement, button: HTMLButtonElement, box: HTMLElement, info: HTMLElement): void {
  CORPUS.forEach((c, i) => {
    const option = document.createElement('option');
    option.value = String(i);
    option.textContent = c.name;
    select.append(option);
  });
  let view: TableView | null = null;
  let animator: Animator | null = null;
  button.addEventListener('click', () => {
    const c = CORPUS[Number(select.value)];
    if (!c) return;
    if (!view || view.spec.name !== c.scene.table) {
      view?.destroy();
      view = new TableView(box, c.scene.table, 'Corpus shot');
      animator = new Animator(view);
    }
    let outcome: Outcome;
    try {
      outcome = simulate(c.scene, c.shot);
    } catch (err) {
      info.textContent = `error: ${(err as Error).message}`;
      return;
    }
    info.dataset.hash = outcome.hash;
    info.textContent = `${c.name}: ${outcome.events.length} events, ${outcome.duration.toFixed(2)} s, hash ${outcome.hash}`;
    delete info.dataset.done;
    void animator!.play(outcome).then(() => (info.dataset.done = 'true'));
  });
}
