// The computer thinking in a Web Worker (bundled apart as computer.js, loaded only when someone
// plays it), so that the page stays responsive: a game in, chooseShot's decision out.
import { chooseShot, type Level } from '../../shared/ai/index.ts';
import type { Game } from '../../shared/rules/index.ts';

interface Ask {
  readonly id: number;
  readonly game: Game;
  readonly level: Level;
  readonly seed: number;
}

const scope = self as unknown as { onmessage: ((e: MessageEvent<Ask>) => void) | null; postMessage(m: unknown): void };
scope.onmessage = (e) => {
  const { id, game, level, seed } = e.data;
  try {
    scope.postMessage({ id, decision: chooseShot(game, { level, seed }) });
  } catch (err) {
    scope.postMessage({ id, error: (err as Error).message });
  }
};
