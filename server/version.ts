import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { ROOT } from './config.ts';

/** The version in package.json, reported by /healthz. */
export const VERSION: string = (JSON.parse(readFileSync(resolve(ROOT, 'package.json'), 'utf8')) as { version: string }).version;
