// Finds code that would compute different bits in different JavaScript engines, or that reads a
// clock or chance. ECMAScript leaves the transcendental Math functions and `**` "implementation-
// approximated" (ECMA-262, sec. 21.3.2), so shared/ may use only + - * /, Math.sqrt and the exact
// Math functions (abs, min, max, floor, ceil, round, trunc, sign, fround, imul, clz32).
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';

const EXACT_MATH = new Set(['sqrt', 'abs', 'min', 'max', 'floor', 'ceil', 'round', 'trunc', 'sign', 'fround', 'imul', 'clz32', 'PI', 'E', 'SQRT2', 'SQRT1_2', 'LN2', 'LN10', 'LOG2E', 'LOG10E']);

const RULES: readonly { pattern: RegExp; why: string }[] = [
  { pattern: /\bMath\s*\.\s*([A-Za-z_$][\w$]*)/g, why: 'Math function not bit-identical across engines' },
  { pattern: /\bMath\s*\[/g, why: 'computed Math access cannot be checked' },
  { pattern: /\*\*=?/g, why: 'the ** operator is not bit-identical across engines' },
  { pattern: /\bDate\s*[.(]|\bnew\s+Date\b/g, why: 'reads a clock' },
  { pattern: /\bperformance\s*\.\s*now\b|\bprocess\s*\.\s*hrtime\b/g, why: 'reads a clock' },
  { pattern: /\bcrypto\s*\.\s*(getRandomValues|randomUUID|randomInt|randomBytes)\b/g, why: 'draws chance' },
];

export interface Finding {
  readonly file: string;
  readonly line: number;
  readonly text: string;
  readonly why: string;
}

/** Blanks out comments (keeping line breaks, so line numbers stay right). */
export function stripComments(source: string): string {
  return source
    .replace(/\/\*[\s\S]*?\*\//g, (c) => c.replace(/[^\n]/g, ' '))
    .replace(/(^|[^:\\'"`])\/\/[^\n]*/g, (_m, before: string) => before);
}

export function scanSource(source: string, file = '<source>'): Finding[] {
  const code = stripComments(source);
  const findings: Finding[] = [];
  for (const { pattern, why } of RULES) {
    for (const match of code.matchAll(pattern)) {
      if (match[1] !== undefined && EXACT_MATH.has(match[1])) continue;
      const line = code.slice(0, match.index).split('\n').length;
      findings.push({ file, line, text: match[0], why: match[1] === 'random' ? 'draws chance' : why });
    }
  }
  return findings.sort((a, b) => a.line - b.line);
}

/** Every .ts file below dir, outside tests. */
export function scanTree(dir: string, root = dir): Finding[] {
  const findings: Finding[] = [];
  for (const name of readdirSync(dir).sort()) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) findings.push(...scanTree(path, root));
    else if (name.endsWith('.ts') && !name.endsWith('.test.ts')) findings.push(...scanSource(readFileSync(path, 'utf8'), relative(root, path)));
  }
  return findings;
}
