// The published model outputs of Mathavan, Jackson and Parkin (2010), their Figs. 9 and 12
// (paper constants), reproduced within their stated accuracy: the values carry their source's
// discretisation error, about 0.05° (speeds to about 1e-3 m/s). The cases: shared/scenes.
import { describe, expect, it } from 'vitest';
import { cushionRebound } from '../../shared/physics/index.ts';
import { PAPER, paperState, PUBLISHED } from '../../shared/scenes/index.ts';

describe('published values (paper constants)', () => {
  it.each(PUBLISHED.map((p) => [p.label, p] as const))('%s', (_, p) => {
    const out = cushionRebound(paperState(p.V0, p.alpha, p.kT, p.kS, PAPER.R), PAPER);
    expect(Math.abs(Math.hypot(out.vx, out.vy) - p.speed)).toBeLessThan(p.speedTol);
    expect(Math.abs((Math.atan2(-out.vy, out.vx) * 180) / Math.PI - p.angle)).toBeLessThan(p.angleTol);
  });
});
