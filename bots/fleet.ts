// Pairs of bots in rooms: one creates a room, the other joins it, and both play with shared counters.
import type { GameKindName } from '../shared/protocol/index.ts';
import { Bot, newStats, type BotStats } from './bot.ts';
import { ProtocolClient } from './client.ts';
import type { BotMode } from './strategy.ts';

export interface FleetOptions {
  /** Servers of one platform: each room's two bots on two of them in turn (the same one when only one). */
  readonly urls: readonly string[];
  readonly mode: BotMode;
  readonly thinkMs: number;
  readonly raceTo: number | undefined;
}

const KINDS: readonly GameKindName[] = ['nineball', 'eightball', 'snooker', 'threecushion'];

export class Fleet {
  readonly stats: BotStats = newStats();
  readonly bots: Bot[] = [];
  rooms = 0;
  sockets = 0;
  setupFailures = 0;
  private stopped = false;
  /** Names unique to this run: the server keeps every name it has handed out. */
  private readonly tag = Math.random().toString(36).slice(2, 8);

  constructor(private readonly options: FleetOptions) {}

  /** Sets up room number `i` of the given kind ("mixed": the kinds in turn); a failure is counted, not thrown. */
  async addRoom(i: number, kind: GameKindName | 'mixed'): Promise<void> {
    const k = kind === 'mixed' ? KINDS[i % KINDS.length]! : kind;
    const opened: Bot[] = [];
    try {
      const urls = this.options.urls;
      const first = await this.bot(urls[i % urls.length]!, `bot-${this.tag}-${i}a`, true);
      opened.push(first);
      const room = await first.create(k, this.options.raceTo);
      const second = await this.bot(urls[(i + 1) % urls.length]!, `bot-${this.tag}-${i}b`, false);
      opened.push(second);
      await second.join(room);
      this.rooms++;
      if (this.stopped) for (const b of opened) b.stop();
    } catch (err) {
      this.setupFailures++;
      if (this.setupFailures <= 3) console.error(`bots: room ${i}: ${(err as Error).message}`);
      for (const b of opened) void b.leave(1000);
    }
  }

  private async bot(url: string, name: string, countGames: boolean): Promise<Bot> {
    const client = await ProtocolClient.connect(url);
    this.sockets++;
    const bot = new Bot(client, { name, mode: this.options.mode, thinkMs: this.options.thinkMs, rematch: true, stats: this.stats, countGames });
    this.bots.push(bot);
    if (this.stopped) bot.stop();
    await bot.hello();
    return bot;
  }

  /** Stops every bot's play at once (the counters stay as they are from here on). */
  stop(): void {
    this.stopped = true;
    for (const b of this.bots) b.stop();
  }

  /** Every bot leaves its room and closes its socket; gives up after `timeoutMs`. */
  async leaveAll(timeoutMs: number): Promise<void> {
    const all = Promise.all(this.bots.map((b) => b.leave(timeoutMs)));
    let timer: NodeJS.Timeout | undefined;
    await Promise.race([all, new Promise<void>((r) => (timer = setTimeout(r, timeoutMs)))]);
    clearTimeout(timer);
  }
}
