import { describe, expect, it } from 'vitest';
import { MiscueError, simulate, SimulationInputError, tableSpec, type Scene, type Shot } from '../../../shared/physics/index.ts';

const R = tableSpec('pool-9ft').ballRadius;
const scene: Scene = { table: 'pool-9ft', balls: [{ id: 'cue', x: -0.5, y: 0 }, { id: '1', x: 0.3, y: 0.1 }] };
const shot: Shot = { ball: 'cue', heading: 0.1, speed: 2, side: 0, top: 0 };

function rejects(s: Scene, sh: Shot, message: RegExp, type: new (...args: never[]) => Error = SimulationInputError): void {
  const before = JSON.stringify([s, sh]);
  expect(() => simulate(s, sh)).toThrow(type);
  expect(() => simulate(s, sh)).toThrow(message);
  expect(JSON.stringify([s, sh])).toBe(before); // nothing changed
}

describe('simulate rejects bad input before simulating anything', () => {
  it('accepts a sound scene and shot', () => {
    expect(simulate(scene, shot).balls).toHaveLength(2);
  });

  it('names overlapping balls, and accepts balls that merely touch', () => {
    rejects({ table: 'pool-9ft', balls: [{ id: 'a', x: 0, y: 0 }, { id: 'b', x: 2 * R - 1e-6, y: 0 }] }, { ...shot, ball: 'a' }, /balls "a" and "b" overlap by 1\.000e-6 m/);
    expect(() => simulate({ table: 'pool-9ft', balls: [{ id: 'a', x: 0, y: 0 }, { id: 'b', x: 2 * R - 5e-10, y: 0 }] }, { ...shot, ball: 'a' })).not.toThrow();
  });

  it('names a ball off the table', () => {
    rejects({ table: 'pool-9ft', balls: [{ id: 'cue', x: 1.27, y: 0 }] }, shot, /ball "cue" at \(1\.27, 0\) is off the table/);
    rejects({ table: 'pool-9ft', balls: [{ id: 'cue', x: 0.5, y: 0.635 - R + 1e-6 }] }, shot, /off the table/);
    // In a pocket's mouth, beyond the rail line, a ball may rest; over the drop circle it may not.
    expect(() => simulate({ table: 'pool-9ft', balls: [{ id: 'cue', x: 0, y: 0.62 }] }, shot)).not.toThrow();
    rejects({ table: 'pool-9ft', balls: [{ id: 'cue', x: 0, y: 0.66 }] }, shot, /over pocket ML: it would drop/);
    rejects({ table: 'pool-9ft', balls: [{ id: 'cue', x: 0.07, y: 0.64 }] }, shot, /off the table/);
    // Against a corner jaw's rounded nose, a hair beyond the rail line and outside the mouth: where
    // a bots' eight-ball game left its cue ball (the referee could not go on from there).
    expect(() => simulate({ table: 'pool-9ft', balls: [{ id: 'cue', x: -1.1866397102871693, y: 0.6064525258769857 }] }, shot)).not.toThrow();
    // Every nose: a ball touching it from the table's side is on the table.
    for (const name of ['pool-9ft', 'snooker-12ft'] as const) {
      const t = tableSpec(name);
      for (const c of t.cushions) {
        if (c.kind !== 'arc' || !c.name.endsWith('-nose')) continue;
        for (let k = 0; k <= 8; k++) {
          // Directions from the nose's centre toward the table, between its two ends (u, w).
          const f = k / 8;
          const ux = c.ux + f * (c.wx - c.ux);
          const uy = c.uy + f * (c.wy - c.uy);
          const n = Math.hypot(ux, uy);
          const d = c.r + t.ballRadius + 1e-7;
          const ball = { id: 'cue', x: c.cx + (d * ux) / n, y: c.cy + (d * uy) / n };
          expect(() => simulate({ table: name, balls: [ball] }, shot), `${name} ${c.name} ${k}`).not.toThrow();
        }
      }
    }
  });

  it('rejects duplicate ids, unknown balls and tables, empty scenes', () => {
    rejects({ table: 'pool-9ft', balls: [{ id: 'a', x: 0, y: 0 }, { id: 'a', x: 0.5, y: 0 }] }, { ...shot, ball: 'a' }, /duplicate ball id "a"/);
    rejects(scene, { ...shot, ball: '9' }, /shot\.ball "9" is not a ball of the scene/);
    rejects({ ...scene, table: 'pool-7ft' }, shot, /unknown table "pool-7ft"/);
    rejects({ table: 'pool-9ft', balls: [] }, shot, /non-empty array/);
  });

  it.each([
    ['x', { ...scene, balls: [{ id: 'cue', x: Number.NaN, y: 0 }] }, shot, /ball "cue" x must be a finite number, got NaN/],
    ['y', { ...scene, balls: [{ id: 'cue', x: 0, y: Infinity }] }, shot, /ball "cue" y must be a finite number, got Infinity/],
    ['heading', scene, { ...shot, heading: Number.NaN }, /shot\.heading must be a finite number/],
    ['speed NaN', scene, { ...shot, speed: Number.NaN }, /shot\.speed must be a finite number/],
    ['speed 0', scene, { ...shot, speed: 0 }, /shot\.speed must be in \(0, 20\]/],
    ['speed 25', scene, { ...shot, speed: 25 }, /shot\.speed must be in \(0, 20\]/],
    ['side', scene, { ...shot, side: -Infinity }, /shot\.side must be a finite number/],
    ['top', scene, { ...shot, top: Number.NaN }, /shot\.top must be a finite number/],
  ] as const)('rejects a bad %s', (_name, s, sh, message) => {
    rejects(s as Scene, sh as Shot, message);
  });

  it('calls a tip offset beyond half the radius a miscue', () => {
    rejects(scene, { ...shot, side: 0.4, top: 0.35 }, /miscue/, MiscueError);
  });

  it('rejects bad options', () => {
    expect(() => simulate(scene, shot, { rootTolerance: 0 })).toThrow(/options\.rootTolerance/);
    expect(() => simulate(scene, shot, { cushionTolerance: 'sloppy' as never })).toThrow(/options\.cushionTolerance must be one of/);
  });
});
