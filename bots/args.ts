// The command line of `npm run bots`.
import { parseArgs } from 'node:util';
import { GAME_KINDS, type GameKindName } from '../shared/protocol/index.ts';
import type { BotMode } from './strategy.ts';

export interface BotsArgs {
  /** The first server's URL (the yardstick's). */
  readonly url: string;
  /** Every server's URL (--url a,b,...): room i's maker on urls[i mod n], its opponent on the next. */
  readonly urls: readonly string[];
  readonly rooms: number;
  readonly seconds: number;
  /** One kind for every room, or "mixed": the kinds in turn. */
  readonly kind: GameKindName | 'mixed';
  /** The mean wait before each shot (ms). */
  readonly thinkMs: number;
  readonly mode: BotMode;
  /** The race of each room; the server's default when absent. */
  readonly raceTo: number | undefined;
  /** Rooms set up at once (two sockets each): connects come in batches, not all together. */
  readonly batch: number;
}

export const USAGE =
  'usage: npm run bots -- --url ws://127.0.0.1:PORT/ws[,ws://...] [--rooms N] [--seconds S] ' +
  '[--kind nineball|eightball|snooker|threecushion|mixed] [--think-ms M] [--quick] [--race-to R] [--batch B]';

function count(text: string | undefined, fallback: number, name: string, min: number): number {
  if (text === undefined) return fallback;
  const n = Number(text);
  if (!Number.isFinite(n) || n < min) throw new Error(`--${name} must be a number of at least ${min}, got "${text}"`);
  return n;
}

export function parseBotsArgs(argv: readonly string[]): BotsArgs {
  const { values } = parseArgs({
    args: [...argv],
    options: {
      url: { type: 'string' },
      rooms: { type: 'string' },
      seconds: { type: 'string' },
      kind: { type: 'string' },
      'think-ms': { type: 'string' },
      quick: { type: 'boolean' },
      'race-to': { type: 'string' },
      batch: { type: 'string' },
    },
  });
  const urls = values.url?.split(',').map((u) => u.trim()) ?? [];
  if (urls.length === 0 || urls.some((u) => !/^wss?:\/\//.test(u))) throw new Error('--url ws://host:port/ws is required (several, comma-separated, for several processes)');
  const kind = values.kind ?? 'nineball';
  if (kind !== 'mixed' && !(GAME_KINDS as readonly string[]).includes(kind)) throw new Error(`unknown --kind "${kind}"`);
  return {
    url: urls[0]!,
    urls,
    rooms: Math.floor(count(values.rooms, 1, 'rooms', 1)),
    seconds: count(values.seconds, 30, 'seconds', 0.1),
    kind: kind as GameKindName | 'mixed',
    thinkMs: count(values['think-ms'], 0, 'think-ms', 0),
    mode: values.quick ? 'quick' : 'sound',
    raceTo: values['race-to'] === undefined ? undefined : Math.floor(count(values['race-to'], 1, 'race-to', 1)),
    batch: Math.floor(count(values.batch, 20, 'batch', 1)),
  };
}
