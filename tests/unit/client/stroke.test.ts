// The stroke's pure parts: a drag's pull back along the aim gives the power, a short one cancels,
// a ball in hand is stroked only by a drag straight back; the pace steps x2, x4, the end; the
// spin reads in words.
import { describe, expect, it } from 'vitest';
import { spinWords } from '../../../client/table/controls.ts';
import { fullPull, goesBack, MAX_PULL, MAX_SPEED, MIN_SPEED, onStick, powerWords, pullBack, pullToSpeed, speedToGap } from '../../../client/table/cue.ts';
import { nextPace } from '../../../client/table/pace.ts';

describe('the stroke', () => {
  it('takes the power from the pull, proportional, from MIN_SPEED to MAX_SPEED at MAX_PULL', () => {
    expect(pullToSpeed(MAX_PULL)).toBe(MAX_SPEED);
    expect(pullToSpeed(MAX_PULL * 2)).toBe(MAX_SPEED);
    expect(pullToSpeed(MAX_PULL / 2)).toBe(MAX_SPEED / 2);
    expect(pullToSpeed(0.1)).toBe(2.5);
    expect(pullToSpeed(0.001)).toBe(MIN_SPEED);
    // The drawn gap is the pull that gives the speed.
    for (const v of [0.5, 2.5, 7, MAX_SPEED]) expect(pullToSpeed(speedToGap(v))).toBeCloseTo(v, 9);
  });

  it('takes full power at 40 cm of table, or 150 px where the table is drawn small', () => {
    expect(fullPull(400)).toBe(MAX_PULL);
    expect(fullPull(150)).toBe(1);
    expect(pullToSpeed(0.5, 0, fullPull(150))).toBe(MAX_SPEED / 2);
    expect(speedToGap(MAX_SPEED / 2, 1)).toBe(0.5);
  });

  it('cancels a pull no longer than the cancel distance, or none', () => {
    expect(pullToSpeed(0)).toBeNull();
    expect(pullToSpeed(0.02, 0.025)).toBeNull();
    expect(pullToSpeed(0.03, 0.025)).toBe(0.75);
  });

  it('measures the pull back along the line behind the ball, not sideways or forward', () => {
    const from = { x: 0, y: 0 };
    expect(pullBack(0, from, { x: -0.2, y: 0 })).toBeCloseTo(0.2, 12);
    expect(pullBack(0, from, { x: -0.2, y: 0.5 })).toBeCloseTo(0.2, 12);
    expect(pullBack(0, from, { x: 0.2, y: 0 })).toBe(0);
    expect(pullBack(Math.PI / 2, from, { x: 0, y: -0.3 })).toBeCloseTo(0.3, 12);
  });

  it('on a ball in hand, strokes only a drag within 30° of straight back', () => {
    const from = { x: 0, y: 0 };
    expect(goesBack(0, from, { x: -0.1, y: 0 })).toBe(true);
    expect(goesBack(0, from, { x: -0.1, y: 0.05 })).toBe(true); // 26.6°
    expect(goesBack(0, from, { x: -0.1, y: 0.06 })).toBe(false); // 31°
    expect(goesBack(0, from, { x: 0.1, y: 0 })).toBe(false);
    expect(goesBack(0, from, { x: 0, y: 0.1 })).toBe(false);
    expect(goesBack(0, from, from)).toBe(false);
  });

  it('grabs the stick behind the ball, not in front of it or beside it', () => {
    const cue = { x: 0, y: 0 };
    const R = 0.028575;
    expect(onStick({ x: -0.3, y: 0 }, cue, 0, R, 0.1, 0.03)).toBe(true);
    expect(onStick({ x: -0.3, y: 0.05 }, cue, 0, R, 0.1, 0.03)).toBe(false);
    expect(onStick({ x: 0.3, y: 0 }, cue, 0, R, 0.1, 0.03)).toBe(false);
    expect(onStick({ x: -2, y: 0 }, cue, 0, R, 0.1, 0.03)).toBe(false);
  });

  it('says the power in words', () => {
    expect(powerWords(MIN_SPEED)).toBe('Very soft, 0%');
    expect(powerWords(2.5)).toBe('Soft, 23%');
    expect(powerWords(MAX_SPEED)).toBe('Full power, 100%');
  });

  it('says where the tip strikes', () => {
    expect(spinWords(0, 0)).toBe('Centre ball');
    expect(spinWords(-0.1, 0.2)).toBe('Top (follow) 20%, left side 10%');
    expect(spinWords(0.3, -0.35)).toBe('Bottom (draw) 35%, right side 30%');
  });

  it('steps the pace x1 → x2 → x4 → the end', () => {
    expect(nextPace(1)).toBe(2);
    expect(nextPace(2)).toBe(4);
    expect(nextPace(4)).toBe('end');
  });
});
