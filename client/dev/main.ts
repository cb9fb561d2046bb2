// The dev page (/dev.html): the golden corpus replayed in the browser.
import { mountCorpusReplay } from './corpus-replay.ts';

mountCorpusReplay(
  document.getElementById('replay-case') as HTMLSelectElement,
  document.getElementById('replay-play') as HTMLButtonElement,
  document.getElementById('replay-table')!,
  document.getElementById('replay-info')!,
);
