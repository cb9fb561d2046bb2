// Defect 4 of issue 37: the lab's legends covered the curves of Figs. 9 and 10. Every legend box
// is checked against every drawn curve (its visible part, inside the plot's clip) and every
// published point, in the SVG the lab draws.
import { describe, expect, it } from 'vitest';
import { fig10, fig12, fig9 } from '../../../client/lab/figures.ts';
import { DEFAULT_STATE } from '../../../client/lab/state.ts';
import { PAPER } from '../../../shared/scenes/index.ts';

interface Box { x: number; y: number; w: number; h: number }
const attr = (tag: string, name: string): number => Number(new RegExp(`\\b${name}="([^"]*)"`).exec(tag)![1]);
const inside = (b: Box, x: number, y: number, pad = 0): boolean => x >= b.x - pad && x <= b.x + b.w + pad && y >= b.y - pad && y <= b.y + b.h + pad;

/** Each panel (a translated group): its plot area, legend boxes, curves and marks, in the group's coordinates. */
function panels(svg: string) {
  return svg.split('<g transform=').slice(1).map((g) => {
    const clip = /<clipPath[^>]*><rect ([^>]*)\/>/.exec(g)![1]!;
    const plot: Box = { x: attr(clip, 'x'), y: attr(clip, 'y'), w: attr(clip, 'width'), h: attr(clip, 'height') };
    const legends = [...g.matchAll(/<rect data-legend="([^"]*)"[^>]*>/g)].map((m) => ({ name: m[1]!, box: { x: attr(m[0], 'x'), y: attr(m[0], 'y'), w: attr(m[0], 'width'), h: attr(m[0], 'height') } }));
    const curves = [...g.matchAll(/<polyline data-series="([^"]*)"[^>]* points="([^"]*)"/g)].map((m) => ({
      name: m[1]!,
      points: m[2]!.split(' ').map((p) => p.split(',').map(Number) as [number, number]),
    }));
    const marks = [...g.matchAll(/<circle [^>]*>/g)].map((m) => [attr(m[0], 'cx'), attr(m[0], 'cy')] as [number, number]);
    return { plot, legends, curves, marks };
  });
}

describe('the lab figures\' legends', () => {
  const figures = {
    'Fig. 9': fig9(PAPER),
    'Fig. 10': fig10(PAPER),
    'Fig. 12': fig12(PAPER, DEFAULT_STATE.ball).svg,
    'Fig. 9, e_e = 0.3': fig9({ ...PAPER, ee: 0.3 }),
    'Fig. 10, μw = 0.05': fig10({ ...PAPER, muW: 0.05 }),
  };

  it.each(Object.entries(figures))('%s: no legend box meets a curve or a published point, and every curve has its entry', (_name, svg) => {
    for (const p of panels(svg)) {
      expect(p.legends.map((l) => l.name).sort()).toEqual(p.curves.map((c) => c.name).sort());
      const hits: string[] = [];
      for (const c of p.curves) {
        for (let i = 1; i < c.points.length; i++) {
          const [x0, y0] = c.points[i - 1]!;
          const [x1, y1] = c.points[i]!;
          // The segment, sampled finely; only what the plot's clip lets through is drawn.
          for (let k = 0; k <= 20; k++) {
            const x = x0 + ((x1 - x0) * k) / 20;
            const y = y0 + ((y1 - y0) * k) / 20;
            if (!inside(p.plot, x, y)) continue;
            for (const l of p.legends) if (inside(l.box, x, y, 1)) hits.push(`${c.name} under the legend "${l.name}" at (${x.toFixed(0)}, ${y.toFixed(0)})`);
          }
        }
      }
      for (const [x, y] of p.marks) for (const l of p.legends) if (inside(l.box, x, y, 5)) hits.push(`a published point under the legend "${l.name}"`);
      expect(hits.slice(0, 5)).toEqual([]);
    }
  });
});
