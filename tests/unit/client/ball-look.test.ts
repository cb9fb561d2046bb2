// How a ball is drawn: its look, and a stripe's white cap as the camera above sees it.
import { describe, expect, it } from 'vitest';
import { ballLook, capView } from '../../../client/table/ball-look.ts';

describe('ball look', () => {
  it('stripes 9-15, numbers 1-15, spots the cue balls only (on a carom table the yellow too)', () => {
    expect(ballLook('9')).toMatchObject({ stripe: true, number: 9, spots: null });
    expect(ballLook('1')).toMatchObject({ stripe: false, number: 1, colour: ballLook('9').colour });
    expect(ballLook('cue').spots).not.toBeNull();
    expect(ballLook('white').spots).not.toBeNull();
    expect(ballLook('red7')).toMatchObject({ stripe: false, number: null, spots: null });
    // The yellow is a cue ball on a carom table only.
    expect(ballLook('yellow', 'carom-match').spots).not.toBeNull();
    expect(ballLook('yellow', 'snooker-12ft').spots).toBeNull();
  });
});

describe('capView', () => {
  const h = 0.55;
  const r = Math.sqrt(1 - h * h);
  it('a cap facing up is a whole circle; facing down, hidden', () => {
    const up = capView([0, 0, 1], h);
    expect(up.kind).toBe('whole');
    if (up.kind === 'whole') expect([up.ellipse.rx, up.ellipse.ry]).toEqual([r, r]);
    expect(capView([0, 0, -1], h).kind).toBe('hidden');
  });

  it('a cap tilted up but clear of the rim is a whole ellipse, squashed along its tilt', () => {
    const a = [Math.sin(0.3), 0, Math.cos(0.3)] as const;
    const c = capView(a, h);
    expect(c.kind).toBe('whole');
    if (c.kind !== 'whole') return;
    expect(c.ellipse.cx).toBeCloseTo(h * a[0], 12);
    expect(c.ellipse.rx).toBeCloseTo(r, 12);
    expect(c.ellipse.ry).toBeCloseTo(r * a[2], 12);
  });

  it('a level cap (the stripe upright) is cut by the rim: its outline ends on the rim, the rim arc round its side', () => {
    const c = capView([0, 1, 0], h);
    expect(c.kind).toBe('part');
    if (c.kind !== 'part') return;
    // The cap's near edge is the line y = h seen edge-on; the rim arc runs over the top (+y), from
    // one end of it to the other, the short way.
    const ends = [c.rim.from, c.rim.to].map((t) => [Math.cos(t), Math.sin(t)]);
    for (const [, y] of ends) expect(y).toBeCloseTo(h, 9);
    expect(Math.abs(ends[0]![0]!)).toBeCloseTo(r, 9);
    const mid = (c.rim.from + c.rim.to) / 2;
    expect(Math.sin(mid)).toBeCloseTo(1, 9);
    expect(c.ellipse.ry).toBeCloseTo(0, 12);
  });

  it('a cap tipped past the rim shows a sliver and stays on its side', () => {
    const a = [0.9, 0, -Math.sqrt(1 - 0.81)] as const; // leaning away below the rim
    const c = capView(a, h);
    expect(c.kind).toBe('part');
    if (c.kind !== 'part') return;
    for (const t of [c.rim.from, c.rim.to]) expect(Math.cos(t) * a[0]).toBeGreaterThanOrEqual(h - 1e-9);
    expect(c.ellipse.anticlockwise).toBe(true);
  });
});
