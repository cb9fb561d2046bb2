// Rewrites tests/golden/corpus-hashes.json from the current engine. Run it only after a change
// that is meant to change results, and say so in the commit.
import { writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { corpusHashes } from '../tests/support/corpus-hashes.ts';

const file = resolve(import.meta.dirname, '../tests/golden/corpus-hashes.json');
const hashes = corpusHashes();
writeFileSync(file, `${JSON.stringify(hashes, null, 2)}\n`);
console.log(`${Object.keys(hashes).length} corpus hashes written to ${file}`);
