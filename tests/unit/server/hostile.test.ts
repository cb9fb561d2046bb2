// Random and hostile frames through the parser and the game service (a real SQLite file): each is
// refused with an error to its sender alone, never an internal one, and nothing changes, in memory
// or on disk. BAIZE_HOSTILE_RUNS sets the count (default 100,000).
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { parseClientMessage } from '../../../shared/protocol/index.ts';
import { hostileFrames, type Sender } from '../../support/hostile-messages.ts';
import { last, openHarness, type Harness } from '../../support/service-harness.ts';

const RUNS = Number(process.env.BAIZE_HOSTILE_RUNS ?? 100_000);

const CONN: Record<Sender, number> = { stranger: 5, outsider: 3, waiter: 2, onTurn: 1 };

/** Everything the store holds about rooms, matches and players, as text. */
async function snapshot(h: Harness): Promise<string> {
  return JSON.stringify({ rooms: await h.store.openRooms(), results: await h.store.resultCount() });
}

describe('hostile messages through the parser and the game service (property)', () => {
  it(`refuses ${RUNS.toLocaleString('en')} random and hostile frames with an error to the sender, and changes nothing`, async () => {
    const h = await openHarness();
    try {
      await h.send(1, { type: 'hello', name: 'Ann' });
      await h.send(2, { type: 'hello', name: 'Bob' });
      await h.send(3, { type: 'hello', name: 'Cid' });
      await h.send(4, { type: 'hello', name: 'Dee' });
      await h.send(9, { type: 'hello', name: 'Spectator' });
      await h.send(1, { type: 'create', kind: 'nineball' });
      const playing = last(h, 1, 'room').room.id;
      await h.send(2, { type: 'join', room: playing });
      await h.send(4, { type: 'create', kind: 'snooker' });
      const waiting = last(h, 4, 'room').room.id;
      await h.send(9, { type: 'watch', room: playing });
      const viewBefore = last(h, 9, 'room').room;
      const stored = await snapshot(h);
      let tried = 0;
      const codes = new Map<string, number>();

      await fc.assert(
        fc.asyncProperty(hostileFrames({ playing, playingStateId: viewBefore.stateId, waiting }), async ({ sender, text }) => {
          const parsed = parseClientMessage(text);
          // A stranger's well-formed hello would be a legal welcome, not an attack.
          fc.pre(!(sender === 'stranger' && parsed.ok && parsed.message.type === 'hello'));
          const conn = CONN[sender];
          const got = await h.sendText(conn, text);
          tried++;
          expect([...got.keys()]).toEqual([conn]);
          const msgs = got.get(conn)!;
          expect(msgs).toHaveLength(1);
          const m = msgs[0]!;
          expect(m.type, text).toBe('error');
          if (m.type === 'error') {
            expect(m.code, `${m.message} <- ${text}`).not.toBe('internal');
            codes.set(m.code, (codes.get(m.code) ?? 0) + 1);
          }
        }),
        { numRuns: RUNS, seed: 25 },
      );

      expect(tried).toBeGreaterThan(RUNS * 0.99);
      expect(await snapshot(h)).toBe(stored);
      await h.send(9, { type: 'leave', room: playing });
      await h.send(9, { type: 'watch', room: playing });
      expect(last(h, 9, 'room').room).toEqual(viewBefore);
      // The errors cover the protocol's refusals, not one catch-all.
      for (const code of ['bad-json', 'bad-message', 'not-welcomed', 'no-room', 'not-seated', 'room-full', 'stale-state', 'not-your-turn']) {
        expect(codes.get(code) ?? 0, code).toBeGreaterThan(0);
      }
      // And the service still plays: the player on turn breaks.
      await h.send(1, { type: 'shot', room: playing, stateId: viewBefore.stateId, shot: { ball: 'cue', heading: 0, speed: 6, side: 0, top: 0 } });
      expect(last(h, 2, 'shot').stateId).toBe(viewBefore.stateId + 1);
    } finally {
      await h.close();
    }
  }, 600_000);
});
