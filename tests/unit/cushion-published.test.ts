// The published model outputs of Mathavan, Jackson and Parkin (2010), their Figs. 9 and 12
// (paper constants), reproduced within their stated accuracy: the values
// carry their source's discretisation error, about 0.05° (speeds to about 1e-3 m/s).
import { describe, expect, it } from 'vitest';
import { cushionRebound } from '../../shared/physics/index.ts';
import { PAPER, paperState } from '../support/cushion-cases.ts';

function rebound(V0: number, alpha: number, kT: number, kS: number): { speed: number; angle: number } {
  const out = cushionRebound(paperState(V0, alpha, kT, kS, PAPER.R), PAPER);
  return { speed: Math.hypot(out.vx, out.vy), angle: (Math.atan2(-out.vy, out.vx) * 180) / Math.PI };
}

describe('published values (paper constants)', () => {
  it.each([
    [15, 0.9175, 15.913],
    [30, 0.8614, 34.001],
    [45, 0.8476, 52.678],
    [60, 0.8672, 68.824],
    [75, 0.8976, 80.03],
  ])('natural roll, V0 = 1 m/s, incidence %d°: %f m/s at %f°', (alpha, speed, angle) => {
    const r = rebound(1, alpha, 1, 0);
    expect(Math.abs(r.speed - speed)).toBeLessThan(1e-3);
    expect(Math.abs(r.angle - angle)).toBeLessThan(0.05);
  });

  it('no spin at 45°: 0.7564 m/s at 56.220°', () => {
    const r = rebound(1, 45, 0, 0);
    expect(Math.abs(r.speed - 0.7564)).toBeLessThan(1e-3);
    expect(Math.abs(r.angle - 56.22)).toBeLessThan(0.05);
  });

  it('the Fig. 12 case (V0 = 2 m/s, 45°, ω_S = 2 V0/R, ω_T = 1.5 V0/R): 2.2179 m/s at 38.017°', () => {
    const r = rebound(2, 45, 1.5, 2);
    expect(Math.abs(r.speed - 2.2179)).toBeLessThan(2e-3);
    expect(Math.abs(r.angle - 38.017)).toBeLessThan(0.05);
  });
});
