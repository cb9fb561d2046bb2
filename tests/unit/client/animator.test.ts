// The animator with a stand-in view and a hand-cranked display clock: the last frame is the
// outcome's end exactly; the rate changes without a jump; skipping ends at once; a pocketed ball
// drops into its pocket; the balls turn with their spin.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { sampleOutcome, simulate, tableSpec, type Outcome } from '../../../shared/physics/index.ts';
import { Animator, DROP_TIME } from '../../../client/table/animator.ts';
import type { DrawnBall } from '../../../client/table/draw.ts';
import { IDENTITY, Orientations } from '../../../client/table/orientation.ts';
import type { TableView } from '../../../client/table/view.ts';

let now = 0;
let pending: ((t: number) => void) | null = null;
/** Advances the display clock by ms and runs the frame waiting for it. */
const frame = (ms: number) => {
  now += ms;
  const f = pending;
  pending = null;
  f?.(now);
};

beforeEach(() => {
  now = 1000;
  vi.stubGlobal('document', { hidden: false });
  vi.stubGlobal('requestAnimationFrame', (f: (t: number) => void) => ((pending = f), 1));
  vi.stubGlobal('cancelAnimationFrame', () => (pending = null));
  vi.spyOn(performance, 'now').mockImplementation(() => now);
});
afterEach(() => {
  vi.unstubAllGlobals();
  vi.restoreAllMocks();
});

function fakeView(): { view: TableView; frames: DrawnBall[][] } {
  const frames: DrawnBall[][] = [];
  const view = { spec: tableSpec('pool-9ft'), orientations: new Orientations(), draw: (b: readonly DrawnBall[]) => frames.push([...b]) };
  return { view: view as unknown as TableView, frames };
}

// A straight pot into the top right corner (TL at +x, +y): the 1 a little off the pocket, the cue behind it.
const spec = tableSpec('pool-9ft');
const TL = spec.pockets.find((p) => p.id === 'TL')!;
const dir = Math.atan2(TL.y - 0.35, TL.x - 0.9);
const potting: Outcome = simulate(
  { table: 'pool-9ft', balls: [{ id: 'cue', x: 0.9 - 0.3 * Math.cos(dir), y: 0.35 - 0.3 * Math.sin(dir) }, { id: '1', x: 0.9, y: 0.35 }] },
  { ball: 'cue', heading: dir, speed: 2, side: 0, top: 0 },
);
const endBalls = (o: Outcome) => sampleOutcome(o, o.duration).filter((b) => b.motion !== 'pocketed').map((b) => ({ id: b.id, x: b.x, y: b.y }));
const pos = (f: readonly DrawnBall[]) => f.map((b) => ({ id: b.id, x: b.x, y: b.y }));

describe('Animator', () => {
  it('pots the 1 (the fixture)', () => {
    expect(potting.events.some((e) => e.kind === 'pocket' && e.balls[0] === '1')).toBe(true);
  });

  it('plays to the outcome\'s end exactly, the pocketed ball dropping into its pocket on the way', async () => {
    const { view, frames } = fakeView();
    const a = new Animator(view);
    let done = false;
    void a.play(potting).then(() => (done = true));
    while (a.playing) frame(1000 / 60);
    await Promise.resolve();
    expect(done).toBe(true);
    expect(pos(frames.at(-1)!)).toEqual(endBalls(potting));
    expect(a.time).toBe(potting.duration);
    const drop = potting.events.find((e) => e.kind === 'pocket')!;
    const sinking = frames.flatMap((f) => f.filter((b) => b.sink !== undefined));
    expect(sinking.length).toBeGreaterThan(5);
    expect(sinking.every((b) => b.id === '1' && b.sink! >= 0 && b.sink! < 1)).toBe(true);
    // It ends nearer the pocket's centre than it began, and the animation lasts until it has gone.
    const d = (b: DrawnBall) => Math.hypot(b.x - TL.x, b.y - TL.y);
    expect(d(sinking.at(-1)!)).toBeLessThan(d(sinking[0]!));
    expect(frames.length).toBeGreaterThanOrEqual(Math.floor(Math.max(potting.duration, drop.t + DROP_TIME) * 60) - 1);
    expect(a.pocketOrder).toEqual(['1']);
    // The cue ball rolled: it is turned.
    expect(view.orientations.get('cue')).not.toEqual(IDENTITY);
  });

  it('changes speed from the time shown, without a jump', () => {
    const { view } = fakeView();
    const a = new Animator(view);
    void a.play(potting);
    frame(16);
    frame(500);
    const t = a.time;
    expect(t).toBeCloseTo(0.516, 6);
    a.setSpeed(4);
    expect(a.speed).toBe(4);
    frame(100);
    expect(a.time).toBeCloseTo(t + 0.4, 6);
    a.setSpeed(1);
    frame(100);
    expect(a.time).toBeCloseTo(t + 0.5, 6);
  });

  it('skips to the end at once: the final frame is the outcome\'s end and the promise resolves', async () => {
    const { view, frames } = fakeView();
    const a = new Animator(view);
    let done = false;
    void a.play(potting).then(() => (done = true));
    frame(16);
    frame(16);
    a.skipToEnd();
    await Promise.resolve();
    expect(done).toBe(true);
    expect(a.playing).toBe(false);
    expect(a.time).toBe(potting.duration);
    expect(pos(frames.at(-1)!)).toEqual(endBalls(potting));
    frame(16); // no frame left waiting
    expect(pos(frames.at(-1)!)).toEqual(endBalls(potting));
  });
});
