// Hostile and random client frames for property tests: wrong types, huge numbers, NaN strings,
// deep nesting, unknown rooms and other players' rooms. Each frame is built so that no sender it is
// meant for could legally act with it: it must be refused, and change nothing.
import fc from 'fast-check';

/** A value of any kind a hostile client could put in a field. */
export const junk: fc.Arbitrary<unknown> = fc.oneof(
  fc.string({ maxLength: 40 }),
  fc.integer(),
  fc.double(),
  fc.constantFrom('NaN', 'Infinity', '-Infinity', '1e999', 1e308, -1e308, Number.MAX_SAFE_INTEGER + 2, -0, 0, '', ' ', '\u0000', '<script>', '__proto__'),
  fc.boolean(),
  fc.constant(null),
  fc.array(fc.integer(), { maxLength: 5 }),
  fc.dictionary(fc.string({ maxLength: 8 }), fc.integer(), { maxKeys: 4 }),
  fc.jsonValue({ maxDepth: 4 }),
);

/** Mostly plausible numbers, sometimes junk. */
const num = fc.oneof(fc.double({ min: -10, max: 10, noNaN: true }), fc.integer({ min: -5, max: 50 }), junk);

const shot = fc.record(
  {
    ball: fc.oneof(fc.constantFrom('cue', '1', '9', 'white', 'red', 'nope'), junk),
    heading: num,
    speed: num,
    side: num,
    top: num,
    pushOut: fc.oneof(fc.boolean(), junk),
    calledPocket: fc.oneof(fc.constantFrom('TL', 'BR', 'XX'), junk),
    nominated: fc.oneof(fc.constantFrom('red1', 'black'), junk),
  },
  { requiredKeys: [] },
);

/** A well-formed move at the room's current state: legal but for whose turn it is. */
function wellFormedMove(room: string, stateId: number): fc.Arbitrary<unknown> {
  const n = (limit: number) => fc.double({ min: -limit, max: limit, noNaN: true });
  return fc.record({
    type: fc.constantFrom('shot', 'place', 'decide'),
    room: fc.constant(room),
    stateId: fc.constant(stateId),
    shot: fc.record({ ball: fc.constant('cue'), heading: n(7), speed: fc.double({ min: 0, max: 12, noNaN: true }), side: n(0.4), top: n(0.4) }),
    cueBall: fc.record({ x: n(1.2), y: n(0.6) }),
    choice: fc.constantFrom('pass', 'rerack'),
  });
}

function frame(type: fc.Arbitrary<unknown>, rooms: readonly string[], stateId: fc.Arbitrary<unknown>): fc.Arbitrary<unknown> {
  return fc.record(
    {
      type,
      id: fc.oneof(fc.string({ maxLength: 70 }), fc.integer(), junk),
      room: fc.oneof(fc.constantFrom(...rooms), fc.string({ maxLength: 70 }), junk),
      stateId,
      shot: fc.oneof(shot, junk),
      cueBall: fc.oneof(fc.record({ x: num, y: num }), junk),
      choice: fc.oneof(fc.constantFrom('pass', 'rerack', 'rerack-other', 'none'), junk),
      text: fc.oneof(fc.string({ maxLength: 300 }), junk),
      name: fc.oneof(fc.string({ maxLength: 40 }), junk),
      token: fc.oneof(fc.string({ maxLength: 140 }), junk),
      kind: fc.oneof(fc.constantFrom('nineball', 'snooker', 'pool'), junk),
      raceTo: num,
    },
    { requiredKeys: [] },
  );
}

/** Frames that are not even messages: broken JSON, deep nesting (within the 8 KiB a frame may have), huge literals, non-objects. */
export const rawJunk: fc.Arbitrary<string> = fc.oneof(
  fc.string({ maxLength: 200 }),
  fc.integer({ min: 1, max: 4000 }).map((n) => '['.repeat(n) + ']'.repeat(n)),
  fc.integer({ min: 1, max: 1600 }).map((n) => '{"a":'.repeat(n) + '1' + '}'.repeat(n)),
  fc.jsonValue().map((v) => JSON.stringify(v) ?? 'null'),
  fc.constantFrom('{"type":"shot","speed":1e999}', '{"type":"hello",', 'null', '"hello"', '{"__proto__":{"type":"lobby"}}', '{"type":"lobby","id":NaN}'),
);

export interface Targets {
  /** The room in play, where A is on turn and B is not. */
  readonly playing: string;
  readonly playingStateId: number;
  /** A room waiting for a second player. */
  readonly waiting: string;
}

export type Sender = 'stranger' | 'outsider' | 'waiter' | 'onTurn';

/**
 * A frame and who sends it: a socket that never said hello (anything but hello); a welcomed player
 * seated nowhere (moves in other players' rooms); the player not on turn (moves at any stateId);
 * the player on turn (moves at a stale stateId). Plus raw junk from anyone.
 */
export function hostileFrames(t: Targets): fc.Arbitrary<{ sender: Sender; text: string }> {
  const rooms = [t.playing, t.waiting, 'nowhere', '__proto__', 'constructor'];
  const anyStateId = fc.oneof(fc.integer({ min: -3, max: 10 }), junk);
  const stale = fc.oneof(fc.integer({ min: -3, max: 10 }).filter((n) => n !== t.playingStateId), junk);
  const moves = fc.constantFrom('shot', 'place', 'decide');
  const text = (a: fc.Arbitrary<unknown>) => a.map((v) => JSON.stringify(v) ?? 'null');
  return fc.oneof(
    text(frame(fc.oneof(fc.constantFrom('lobby', 'create', 'join', 'watch', 'leave', 'shot', 'chat', 'concede'), junk), rooms, anyStateId)).map((s) => ({ sender: 'stranger' as const, text: s })),
    text(frame(fc.constantFrom('shot', 'place', 'decide', 'concede', 'claim', 'rematch', 'chat', 'leave', 'hello'), [t.playing, 'nowhere', '__proto__'], anyStateId)).map((s) => ({ sender: 'outsider' as const, text: s })),
    text(frame(fc.constantFrom('join'), [t.playing, 'nowhere'], anyStateId)).map((s) => ({ sender: 'outsider' as const, text: s })),
    text(frame(fc.oneof(moves, fc.constant('hello')), rooms, anyStateId)).map((s) => ({ sender: 'waiter' as const, text: s })),
    text(frame(moves, rooms, stale)).map((s) => ({ sender: 'onTurn' as const, text: s })),
    text(wellFormedMove(t.playing, t.playingStateId)).map((s) => ({ sender: 'waiter' as const, text: s })),
    fc.tuple(fc.constantFrom<Sender>('stranger', 'outsider', 'waiter', 'onTurn'), rawJunk).map(([sender, s]) => ({ sender, text: s })),
  );
}
