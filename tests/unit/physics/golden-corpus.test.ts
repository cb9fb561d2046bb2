import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { CORPUS } from '../../../shared/scenes/index.ts';
import { corpusHashes } from '../../support/corpus-hashes.ts';

const GOLDEN = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../golden/corpus-hashes.json'), 'utf8')) as Record<string, string>;

describe('the golden corpus', () => {
  it('has at least 50 cases with unique names: breaks on every table, banks, spin, pockets, hard cases', () => {
    expect(CORPUS.length).toBeGreaterThanOrEqual(50);
    expect(new Set(CORPUS.map((c) => c.name)).size).toBe(CORPUS.length);
    for (const table of ['pool-9ft', 'snooker-12ft', 'carom-match']) {
      expect(CORPUS.some((c) => c.scene.table === table && (c.tags.includes('break') || c.tags.includes('carom')))).toBe(true);
    }
    for (const tag of ['bank', 'spin', 'pocket', 'hard', 'random'] as const) expect(CORPUS.some((c) => c.tags.includes(tag))).toBe(true);
  });

  it('gives the committed hashes, case by case (no case fails)', () => {
    const now = corpusHashes();
    expect(Object.values(now).filter((h) => h.startsWith('error'))).toEqual([]);
    expect(now).toEqual(GOLDEN);
  });

  it('gives the same hashes in a second run in the same process (no hidden state)', () => {
    expect(corpusHashes()).toEqual(corpusHashes());
  });
});
