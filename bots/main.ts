// `npm run bots -- --url ws://127.0.0.1:PORT/ws --rooms N --seconds S ...`: N rooms of two bots
// each play for S seconds (a room starts a new game when one ends), then one JSON line sums it up.
// Exits 0, or 1 when no socket could be opened at all.
import { parseBotsArgs, USAGE, type BotsArgs } from './args.ts';
import { ProtocolClient } from './client.ts';
import { Fleet } from './fleet.ts';
import { summarize } from './summary.ts';

/** Interval of the yardstick's requests (ms). */
const PROBE_MS = 250;

/**
 * The yardstick, measured beside the shots: the round trip of a request the server refuses at once
 * (leave a room that does not exist): the socket, the parser and the service, with no simulation
 * and no write. Returns the round trips and the function that stops it.
 */
async function probe(url: string): Promise<{ times: number[]; stop(): void }> {
  const times: number[] = [];
  const client = await ProtocolClient.connect(url);
  await client.request({ type: 'hello' });
  const timer = setInterval(() => {
    const t0 = performance.now();
    client.request({ type: 'leave', room: '-' }).then(
      () => times.push(performance.now() - t0),
      () => times.push(performance.now() - t0),
    );
  }, PROBE_MS);
  return {
    times,
    stop() {
      clearInterval(timer);
      void client.close(500);
    },
  };
}

/** Time after the end of play for leaving the rooms and closing the sockets. */
const LEAVE_GRACE_MS = 3000;

async function run(args: BotsArgs): Promise<number> {
  const started = performance.now();
  const fleet = new Fleet({ urls: args.urls, mode: args.mode, thinkMs: args.thinkMs, raceTo: args.raceTo });
  let timer: NodeJS.Timeout | undefined;
  const playEnds = new Promise<void>((r) => (timer = setTimeout(r, args.seconds * 1000)));
  let over = false;
  void playEnds.then(() => (over = true));

  // Rooms come up in batches, each batch once the previous one has been seated, so that the
  // server never sees thousands of connects at once.
  const setUp = (async () => {
    for (let i = 0; i < args.rooms && !over; i += args.batch) {
      const batch = [];
      for (let j = i; j < Math.min(i + args.batch, args.rooms); j++) batch.push(fleet.addRoom(j, args.kind));
      await Promise.all(batch);
      if (fleet.sockets === 0) return false; // nothing to talk to: no use waiting out the clock
    }
    return true;
  })();
  const yardstick = await probe(args.url).catch(() => null);
  const reachable = await Promise.race([setUp, playEnds.then(() => true)]);
  if (reachable) await playEnds;
  clearTimeout(timer);

  fleet.stop();
  yardstick?.stop();
  const seconds = (performance.now() - started) / 1000;
  if (fleet.sockets === 0) {
    console.error(`bots: could not connect to ${args.url}`);
    return 1;
  }
  // The summary first: whoever reads it may take its measurements now, before the rooms are left.
  process.stdout.write(
    `${JSON.stringify(summarize(fleet.stats, { rooms: fleet.rooms, sockets: fleet.sockets, seconds, setupFailures: fleet.setupFailures, yardstickMs: yardstick?.times ?? [] }))}\n`,
  );
  // Leaving concedes the games in play, so that a server that outlives this run keeps no rooms of it.
  await fleet.leaveAll(LEAVE_GRACE_MS);
  return 0;
}

let args: BotsArgs;
try {
  args = parseBotsArgs(process.argv.slice(2));
} catch (err) {
  console.error(`bots: ${(err as Error).message}\n${USAGE}`);
  process.exit(2);
}
run(args).then(
  (code) => process.exit(code),
  (err: unknown) => {
    console.error(`bots: ${err instanceof Error ? err.stack : String(err)}`);
    process.exit(1);
  },
);
