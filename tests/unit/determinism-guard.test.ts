import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { scanSource, scanTree } from '../support/determinism-scan.ts';
import { ROOT } from '../support/server-process.ts';

describe('the determinism guard', () => {
  it('finds nothing in shared/: only exact arithmetic, no clock, no chance', () => {
    const findings = scanTree(join(ROOT, 'shared'));
    expect(findings.map((f) => `shared/${f.file}:${f.line}: ${f.text} (${f.why})`)).toEqual([]);
  });

  it.each([
    ['const a = Math.sin(x);', 'Math.sin'],
    ['const a = Math.atan2(y, x);', 'Math.atan2'],
    ['return Math . exp(-k * t);', 'Math . exp'],
    ['const h = Math.hypot(x, y);', 'Math.hypot'],
    ['const c = Math.cbrt(v); const l = Math.log1p(v);', 'Math.cbrt'],
    ['const p = x ** 2;', '**'],
    ['v **= 0.5;', '**='],
    ['const r = Math.random();', 'Math.random'],
    ['const f = Math["sin"];', 'Math['],
    ['const t = Date.now();', 'Date.'],
    ['const d = new Date();', 'new Date'],
    ['const t = performance.now();', 'performance.now'],
    ['const t = process.hrtime.bigint();', 'process.hrtime'],
    ['crypto.getRandomValues(buf);', 'crypto.getRandomValues'],
  ])('flags %s', (source, text) => {
    const findings = scanSource(`// header\n${source}\n`);
    expect(findings.length).toBeGreaterThan(0);
    expect(findings[0]).toMatchObject({ line: 2, text });
  });

  it('passes exact arithmetic and comments that merely mention banned calls', () => {
    const source = [
      '/** Uses no Math.sin: a polynomial instead (see ** below). */',
      'const s = Math.sqrt(x * x + y * y); // not Math.hypot',
      'const m = Math.max(Math.abs(a), Math.floor(b), Math.fround(c), Math.imul(d, 3));',
      "const url = 'http://example.org/a'; // a URL is no comment start",
      '/* x ** 2 */ const q = x * x;',
    ].join('\n');
    expect(scanSource(source)).toEqual([]);
  });
});
