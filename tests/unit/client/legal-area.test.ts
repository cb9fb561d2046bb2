// The drawn area of a ball in hand is the rules' area (inArea): kitchen, D, anywhere.
import { describe, expect, it } from 'vitest';
import { tableSpec } from '../../../shared/physics/index.ts';
import { inArea } from '../../../shared/rules/index.ts';
import { legalShape, type LegalShape } from '../../../client/table/draw.ts';

const inside = (s: LegalShape, x: number, y: number) =>
  s.kind === 'rect' ? x >= s.x0 && x <= s.x1 && y >= s.y0 && y <= s.y1 : x <= s.cx && Math.hypot(x - s.cx, y) <= s.r;

describe('legalShape', () => {
  for (const [table, area] of [['pool-9ft', 'kitchen'], ['pool-9ft', 'anywhere'], ['snooker-12ft', 'D'], ['snooker-12ft', 'anywhere'], ['carom-match', 'anywhere']] as const) {
    it(`${area} on ${table}: the shape holds the points the rules accept and no others`, () => {
      const spec = tableSpec(table);
      const s = legalShape(spec, area);
      let agree = 0;
      // A grid over the whole bed, off the shape's edges (where float slack decides).
      for (let i = 0; i <= 120; i++) {
        for (let j = 0; j <= 60; j++) {
          const x = (i / 120 - 0.5) * spec.length * 1.02 + 1e-4;
          const y = (j / 60 - 0.5) * spec.width * 1.02 + 1e-4;
          expect(inside(s, x, y), `(${x}, ${y})`).toBe(inArea(spec, area, { x, y }));
          agree++;
        }
      }
      expect(agree).toBe(121 * 61);
    });
  }
});
