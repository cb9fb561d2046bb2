// Looks up golden-corpus cases by name for the tests.
import { CORPUS, type CorpusCase } from '../../shared/scenes/index.ts';

export function corpusCase(name: string): CorpusCase {
  const c = CORPUS.find((x) => x.name === name);
  if (!c) throw new Error(`no corpus case named "${name}"`);
  return c;
}
