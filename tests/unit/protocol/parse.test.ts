// The protocol's parser: every message type in its contract form, and the refusals that keep bad
// input out of the game service (bad JSON, wrong types, infinities, out-of-range numbers, markup
// is text but control characters are not, oversized text).
import { describe, expect, it } from 'vitest';
import { CHAT_MAX, NAME_MAX, parseClientMessage, SHOT_CLOCK_MAX_S } from '../../../shared/protocol/index.ts';

const ok = (m: object) => parseClientMessage(JSON.stringify(m));
const shot = { ball: 'cue', heading: 1.2, speed: 3, side: 0.1, top: -0.2 };

describe('parseClientMessage', () => {
  it('takes every message of the contract, with request ids, and drops extra fields', () => {
    const messages = [
      { type: 'hello' },
      { type: 'hello', name: 'Ann', token: 'abc' },
      { type: 'lobby' },
      { type: 'create', kind: 'nineball', raceTo: 3, private: true, shotClock: 30 },
      { type: 'join', room: 'r1' },
      { type: 'watch', room: 'r1' },
      { type: 'leave', room: 'r1' },
      { type: 'shot', room: 'r1', stateId: 4, shot, cueBall: { x: -0.9, y: 0.1 } },
      { type: 'shot', room: 'r1', stateId: 4, shot: { ...shot, pushOut: true, calledPocket: 'TL', calledBall: '8', nominated: 'blue' } },
      { type: 'place', room: 'r1', stateId: 4, cueBall: { x: 0, y: 0 } },
      { type: 'decide', room: 'r1', stateId: 4, choice: 'pass' },
      { type: 'concede', room: 'r1' },
      { type: 'claim', room: 'r1' },
      { type: 'rematch', room: 'r1' },
      { type: 'chat', room: 'r1', text: 'good shot' },
    ];
    for (const [i, m] of messages.entries()) {
      const r = ok({ ...m, id: i, extra: { deep: [1, 2] } });
      expect(r.ok, JSON.stringify(m)).toBe(true);
      if (r.ok) expect(r.message).toEqual({ ...m, id: i });
    }
  });

  it('refuses what is not a message, naming the field, and carries the request id back', () => {
    expect(parseClientMessage('{"type":"hello"')).toMatchObject({ ok: false, code: 'bad-json' });
    expect(parseClientMessage('[1,2]')).toMatchObject({ ok: false, code: 'bad-message' });
    expect(ok({ type: 'warp', id: 'x1' })).toMatchObject({ ok: false, code: 'bad-message', re: 'x1' });
    const bad = [
      { type: 'shot', room: 'r1', stateId: 1, shot: { ...shot, speed: 'NaN' } },
      { type: 'shot', room: 'r1', stateId: 1, shot: { ...shot, speed: -1 } },
      { type: 'shot', room: 'r1', stateId: 1, shot: { ...shot, heading: 1e308 } },
      { type: 'shot', room: 'r1', stateId: 1.5, shot },
      { type: 'shot', room: 'r1', stateId: 1 },
      { type: 'place', room: 'r1', stateId: 1, cueBall: { x: 0 } },
      { type: 'create', kind: 'pool' },
      { type: 'create', kind: 'nineball', raceTo: 0 },
      { type: 'create', kind: 'nineball', shotClock: -5 },
      { type: 'decide', room: 'r1', stateId: 1, choice: 'win' },
      { type: 'hello', name: '' },
      { type: 'hello', name: 'x'.repeat(NAME_MAX + 1) },
      { type: 'hello', name: 'Ann\u0000' },
      { type: 'chat', room: 'r1', text: 'y'.repeat(CHAT_MAX + 1) },
      { type: 'chat', room: 'r1', text: 'line\nbreak' },
      { type: 'join', room: 42 },
    ];
    for (const m of bad) expect(ok(m).ok, JSON.stringify(m)).toBe(false);
    expect(parseClientMessage('{"type":"shot","room":"r","stateId":1,"shot":{"ball":"cue","heading":1e999,"speed":1,"side":0,"top":0}}')).toMatchObject({
      ok: false,
      message: expect.stringContaining('shot.heading'),
    });
  });

  it('takes a shot clock of 0 (none) or 10 to 600 s, and names shotClock when refusing any other', () => {
    for (const shotClock of [0, 10, 45.5, SHOT_CLOCK_MAX_S]) expect(ok({ type: 'create', kind: 'nineball', shotClock }).ok, String(shotClock)).toBe(true);
    for (const shotClock of [0.001, 1, 9.99, -1, SHOT_CLOCK_MAX_S + 1]) {
      expect(ok({ type: 'create', kind: 'snooker', shotClock }), String(shotClock)).toMatchObject({ ok: false, code: 'bad-message', message: expect.stringMatching(/^shotClock: must be 0 \(no clock\) or from 10 to 600 seconds/) });
    }
  });

  it('keeps names and chat as plain text: markup is text, trimmed, unchanged', () => {
    const r = ok({ type: 'chat', room: 'r', text: '  <b>hi</b> & <script>x</script> ' });
    expect(r.ok && r.message.type === 'chat' && r.message.text).toBe('<b>hi</b> & <script>x</script>');
  });
});
