// Side spin in whole shots, against what real english does (Alciatore, "The Illustrated Principles
// of Pool and Billiards", 2004, chapters on english, throw and running english): side > 0 is right
// english, its spin ω_z > 0 (counter-clockwise seen from above), and left english mirrors it.
import { describe, expect, it } from 'vitest';
import { sampleOutcome, simulate, type Outcome } from '../../../shared/physics/index.ts';
import { corpusCase } from '../../support/corpus.ts';

function run(name: string): Outcome {
  const c = corpusCase(name);
  return simulate(c.scene, c.shot);
}

/** Velocity of a ball just after its first event of a kind (sampling at an event's time gives the state after it). */
function after(o: Outcome, kind: 'cushion' | 'ball', id: string): { vx: number; vy: number; wz: number } {
  const e = o.events.find((x) => x.kind === kind && x.balls.includes(id));
  if (!e) throw new Error(`no ${kind} event for ${id}`);
  return sampleOutcome(o, e.t).find((b) => b.id === id)!;
}

describe('english (side spin) in whole shots', () => {
  it('right english spins the ball counter-clockwise seen from above, left english clockwise', () => {
    for (const [name, sign] of [['right', 1], ['left', -1], ['no', 0]] as const) {
      const o = run(`${name} english straight into a rail`);
      expect(Math.sign(sampleOutcome(o, 0).find((b) => b.id === 'cue')!.wz), name).toBe(sign);
    }
  });

  it('straight into a rail, right english comes back to the shooter\'s right and left english to the left', () => {
    // The shooter faces +x, so the right is -y.
    const right = after(run('right english straight into a rail'), 'cushion', 'cue');
    const none = after(run('no english straight into a rail'), 'cushion', 'cue');
    const left = after(run('left english straight into a rail'), 'cushion', 'cue');
    expect(right.vx).toBeLessThan(0);
    expect(right.vy).toBeLessThan(-0.05);
    expect(Math.abs(none.vy)).toBe(0);
    expect(left.vy).toBeGreaterThan(0.05);
    // The ball keeps going that way: it comes to rest on the shooter's right.
    const rest = run('right english straight into a rail').balls.find((b) => b.id === 'cue')!;
    expect(rest.y).toBeLessThan(0);
  });

  it('on a full hit, right english throws the object ball to the left and left english to the right', () => {
    const right = after(run('right english full hit on an object ball'), 'ball', '1');
    const none = after(run('no english full hit on an object ball'), 'ball', '1');
    const left = after(run('left english full hit on an object ball'), 'ball', '1');
    expect(right.vx).toBeGreaterThan(0.5);
    // Throw of a degree or two: vy / vx between 0.005 and 0.06 (Alciatore's measured throw curves).
    expect(right.vy / right.vx).toBeGreaterThan(0.005);
    expect(right.vy / right.vx).toBeLessThan(0.06);
    expect(Math.abs(none.vy)).toBe(0);
    expect(left.vy / left.vx).toBeLessThan(-0.005);
  });

  it('angling to the right into a rail, right english runs (wider and faster) and left english checks', () => {
    const rebound = (name: string) => {
      const v = after(run(`${name} english angling right into a rail`), 'cushion', 'cue');
      expect(v.vy, name).toBeLessThan(0); // off the top rail
      expect(v.vx, name).toBeGreaterThan(0); // still going right along it
      return { angle: Math.atan2(v.vx, -v.vy), speed: Math.hypot(v.vx, v.vy) };
    };
    const right = rebound('right');
    const none = rebound('no');
    const left = rebound('left');
    expect(right.angle).toBeGreaterThan(none.angle + 0.05);
    expect(left.angle).toBeLessThan(none.angle - 0.01);
    expect(right.speed).toBeGreaterThan(none.speed);
    expect(none.speed).toBeGreaterThan(left.speed);
  });

  it('left english is the bit-exact mirror image of right english', () => {
    for (const kind of ['straight into a rail', 'full hit on an object ball']) {
      const r = run(`right english ${kind}`);
      const l = run(`left english ${kind}`);
      expect(l.events.length).toBe(r.events.length);
      r.balls.forEach((b, i) => {
        expect(l.balls[i]!.x).toBe(b.x);
        expect(l.balls[i]!.y).toBe(b.y === 0 ? 0 : -b.y);
      });
    }
    // Right english angling right into a rail mirrors left english angling left.
    const c = corpusCase('right english angling right into a rail');
    const a = simulate(c.scene, c.shot);
    const m = simulate({ ...c.scene, balls: c.scene.balls.map((b) => ({ ...b, y: -b.y })) }, { ...c.shot, heading: -c.shot.heading, side: -c.shot.side });
    a.balls.forEach((b, i) => {
      expect(m.balls[i]!.x).toBe(b.x);
      expect(m.balls[i]!.y).toBe(-b.y);
    });
  });
});
