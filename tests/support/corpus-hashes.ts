// The hash of every golden-corpus case, as computed here; the same function runs bundled in the
// browsers (tests/browser/corpus-entry.ts), so the two can be compared bit for bit.
import { simulate } from '../../shared/physics/index.ts';
import { CORPUS } from '../../shared/scenes/index.ts';

export function corpusHashes(): Record<string, string> {
  const out: Record<string, string> = {};
  for (const c of CORPUS) {
    try {
      out[c.name] = simulate(c.scene, c.shot).hash;
    } catch (err) {
      out[c.name] = `error: ${(err as Error).message}`;
    }
  }
  return out;
}
