// The computer on the server, piece by piece: the pause's default, the worker pool (the same
// decision as chooseShot in-process, no file left behind, a budget that gives up, practice runs
// scored as in-process), the fallback stroke (legal), the seed (deterministic), and the service
// playing a fallback when the thinker fails.
import fc from 'fast-check';
import { readdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { afterEach, describe, expect, it } from 'vitest';
import { COMPUTER_PAUSE_MS, readConfig } from '../../../server/config.ts';
import { IN_PROCESS, WorkerPool } from '../../../server/workers/pool.ts';
import { RefusedTask } from '../../../server/workers/tasks.ts';
import { decisionSeed, fallbackDecision } from '../../../server/computer/player.ts';
import type { Delivery } from '../../../server/game/service.ts';
import { chooseShot } from '../../../shared/ai/index.ts';
import type { ServerMessage } from '../../../shared/protocol/index.ts';
import { newGame, playShot, practiceStart, type PracticeShot } from '../../../shared/rules/index.ts';
import { last, openHarness, type Harness } from '../../support/service-harness.ts';

const KINDS = ['nineball', 'eightball', 'snooker', 'threecushion'] as const;

let pool: WorkerPool | undefined;
let harness: Harness | undefined;
afterEach(async () => {
  await pool?.close();
  pool = undefined;
  harness?.close();
  harness = undefined;
});

describe('the computer on the server', () => {
  it('pauses at least 0.8 s by default; the settings are read and checked', async () => {
    expect(COMPUTER_PAUSE_MS).toBeGreaterThanOrEqual(800);
    const config = readConfig({});
    expect(config.computerPauseMs).toBeGreaterThanOrEqual(800);
    expect(config.computerWorkers).toBeGreaterThanOrEqual(1);
    expect(config.computerWorkers).toBeLessThanOrEqual(2);
    expect(readConfig({ BAIZE_COMPUTER_WORKERS: '3', BAIZE_COMPUTER_PAUSE_MS: '50', BAIZE_COMPUTER_THINK_MS: '2000' })).toMatchObject({ computerWorkers: 3, computerPauseMs: 50, computerThinkMs: 2000 });
    for (const bad of [{ BAIZE_COMPUTER_WORKERS: '0' }, { BAIZE_COMPUTER_PAUSE_MS: '-1' }, { BAIZE_COMPUTER_THINK_MS: 'soon' }]) expect(() => readConfig(bad)).toThrow(RangeError);
  });

  it('thinks in worker threads to the same decision as chooseShot in-process, and gives up past its budget', async () => {
    const temporary = () => readdirSync(tmpdir()).filter((f) => f.startsWith('baize-computer-')).sort();
    const before = temporary();
    pool = new WorkerPool({ size: 2, budgetMs: 20_000, log: () => {} });
    const games = KINDS.map((k) => newGame(k, ['a', 'b'], { seed: 5 }));
    const decisions = await Promise.all(games.map((game) => pool!.think({ game, level: 1, seed: 9 })));
    expect(decisions).toEqual(games.map((game) => JSON.parse(JSON.stringify(chooseShot(game, { level: 1, seed: 9 })))));
    // The worker's bundle is held in memory: a process killed now leaves no file behind.
    expect(temporary()).toEqual(before);
    await pool.close();
    const logged: string[] = [];
    pool = new WorkerPool({ size: 1, budgetMs: 1, log: (l) => logged.push(l) });
    await expect(pool.think({ game: newGame('snooker', ['a', 'b'], { seed: 1 }), level: 5, seed: 1 })).rejects.toThrow(/longer than 1 ms/);
    // A refused question (a finished game) is an error, not a crash, and the pool answers on.
    const over = { ...newGame('nineball', ['a', 'b'], { seed: 1 }), winner: 'a' };
    await expect(pool.think({ game: over, level: 1, seed: 1 })).rejects.toThrow();
    expect(logged.join('\n')).toMatch(/longer than 1 ms/);
  }, 60_000);

  it('replays practice runs in the same workers: the in-process score, and a bad shot refused', async () => {
    pool = new WorkerPool({ size: 1, budgetMs: 20_000, log: () => {} });
    // A snooker run from the computer's own strokes: the break-off and on while it stays at the table.
    let game = practiceStart('snooker', 'me', 7);
    const shots: PracticeShot[] = [];
    for (let i = 0; i < 3 && game.winner === null && game.turn === 'me'; i++) {
      const d = chooseShot(game, { level: 2, seed: i });
      if (!('shot' in d)) break;
      const { player: _, ...shot } = d.shot;
      shots.push(d.cueBall ? { shot, cueBall: d.cueBall } : { shot });
      game = playShot(game, d.shot, d.cueBall).game;
    }
    const task = { kind: 'snooker' as const, player: 'me', seed: 7, shots };
    const local = await IN_PROCESS.scorePractice(task);
    expect(await pool.scorePractice(task)).toEqual(local);
    expect(local.shots).toBe(shots.length);
    // A shot after the run ended, or one the physics refuses: the task is refused, not a crash.
    const late = [...shots, ...shots, ...shots, ...shots];
    await expect(pool.scorePractice({ ...task, shots: late })).rejects.toBeInstanceOf(RefusedTask);
    await expect(pool.scorePractice({ ...task, shots: [{ shot: { ball: 'cue', heading: 0, speed: 1e9, side: 0, top: 0 } }] })).rejects.toBeInstanceOf(RefusedTask);
    // And the pool thinks on after them.
    expect(await pool.think({ game: newGame('nineball', ['a', 'b'], { seed: 2 }), level: 1, seed: 3 })).toBeDefined();
  }, 60_000);

  it('seeds each decision from the room and the state: the same inputs, the same seed', async () => {
    fc.assert(
      fc.property(fc.string({ maxLength: 12 }), fc.nat(), fc.nat(), (room, match, state) => {
        const s = decisionSeed(room, match, state);
        expect(s).toBe(decisionSeed(room, match, state));
        expect(Number.isInteger(s) && s >= 0 && s < 2 ** 32).toBe(true);
      }),
    );
    expect(decisionSeed('r', 1, 2)).not.toBe(decisionSeed('r', 1, 3));
  });

  it('falls back on a stroke the rules take, from the start of any game', async () => {
    fc.assert(
      fc.property(fc.constantFrom(...KINDS), fc.nat(), (kind, seed) => {
        const game = newGame(kind, ['a', 'b'], { seed });
        const d = fallbackDecision(game);
        expect('shot' in d).toBe(true);
        if ('shot' in d) expect(() => playShot(game, d.shot, d.cueBall)).not.toThrow();
      }),
      { numRuns: 20 },
    );
  });

  it('plays a fallback when the thinker fails, through the person\'s path, and the service carries on', async () => {
    const out: Delivery[] = [];
    harness = await openHarness({ service: { computer: { thinker: { think: () => Promise.reject(new Error('boom')), close: async () => {} }, pauseMs: 0 } } });
    harness.service.attach((d) => out.push(...d));
    await harness.send(1, { type: 'hello', name: 'Solo' });
    await harness.send(1, { type: 'create', kind: 'threecushion', raceTo: 2, computer: 2 });
    const room = last(harness, 1, 'room').room;
    expect(room.players[1]).toMatchObject({ name: 'Computer (level 2)', connected: true });
    // A soft stroke that meets nothing: no point, the computer's turn.
    await harness.send(1, { type: 'shot', room: room.id, stateId: room.stateId, shot: { ball: 'white', heading: Math.PI / 2, speed: 0.3, side: 0, top: 0 } });
    expect(last(harness, 1, 'shot').game.turn).toBe(room.players[1]!.id);
    await expect.poll(() => out.some((d) => d.message.type === 'shot'), { timeout: 5000 }).toBe(true);
    const delivery = out.find((d) => d.message.type === 'shot')!;
    const its = delivery.message as Extract<ServerMessage, { type: 'shot' }>;
    expect(delivery.to).toEqual([1]);
    expect(its.shot.player).toBe(room.players[1]!.id);
    expect(its.re).toBeUndefined();
    // Recorded like a person's shot; the service answers on.
    expect((await harness.store.matchActions(its.match)).filter((a) => (a.action as { type: string }).type === 'shot')).toHaveLength(2);
    await harness.send(1, { type: 'lobby' });
    expect(last(harness, 1, 'lobby').rooms.map((r) => r.id)).toContain(room.id);
  });

  it('takes up its turn again after a restart, from the stored room', async () => {
    const never = { think: () => new Promise<never>(() => {}), close: async () => {} };
    const first = await openHarness({ service: { computer: { thinker: never, pauseMs: 0 } } });
    await first.send(1, { type: 'hello', name: 'Again' });
    await first.send(1, { type: 'create', kind: 'threecushion', raceTo: 2, computer: 1 });
    const room = last(first, 1, 'room').room;
    await first.send(1, { type: 'shot', room: room.id, stateId: room.stateId, shot: { ball: 'white', heading: Math.PI / 2, speed: 0.3, side: 0, top: 0 } });
    expect(last(first, 1, 'shot').game.turn).toBe(room.players[1]!.id);
    await first.close();
    const out: Delivery[] = [];
    const answers = { think: async ({ game }: { game: Parameters<typeof fallbackDecision>[0] }) => fallbackDecision(game), close: async () => {} };
    harness = await openHarness({ dbPath: first.dbPath, service: { computer: { thinker: answers, pauseMs: 0 } } });
    harness.service.attach((d) => out.push(...d));
    await harness.tick();
    // Nobody is connected to be told: the stroke shows in the match's log.
    const shots = async () => (await harness!.store.matchActions(room.match!)).filter((a) => (a.action as { type: string }).type === 'shot').length;
    await expect.poll(shots, { timeout: 5000 }).toBe(2);
  });
});
