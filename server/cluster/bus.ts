// The bus between processes: a command goes to one process (`baize:proc:<id>`, the room's
// owner), a delivery goes to every process (`baize:deliver`), each sending it to its own sockets.
// Messages are JSON envelopes checked with valibot on receipt; a malformed one is logged and
// dropped, never thrown. Subscriptions use their own connection, as Redis requires.
import * as v from 'valibot';
import { KEYS, requireId } from './keys.ts';
import { connectRedis, type RedisClient } from './redis.ts';

const Envelope = v.object({ from: v.pipe(v.string(), v.minLength(1)), body: v.unknown() });
export interface BusMessage {
  /** The sending process. */
  readonly from: string;
  /** What the service/binding put in: a client command or a delivery; checked by its receiver. */
  readonly body: unknown;
}
export type BusHandler = (message: BusMessage) => void;

export interface Bus {
  /** Sends a command to one process; resolves with how many processes heard it (0: gone). */
  command(toProcess: string, body: unknown): Promise<number>;
  /** Sends a delivery to every process, this one included. */
  deliver(body: unknown): Promise<void>;
  onCommand(handler: BusHandler): void;
  onDelivery(handler: BusHandler): void;
  close(): Promise<void>;
}

/** Parses one envelope; null (logged) when malformed. */
export function parseEnvelope(raw: string, log: (why: string) => void = (w) => console.warn(w)): BusMessage | null {
  let json: unknown;
  try {
    json = JSON.parse(raw);
  } catch {
    log(`bus: dropped a message that is not JSON (${raw.slice(0, 80)})`);
    return null;
  }
  const r = v.safeParse(Envelope, json);
  if (!r.success) {
    log(`bus: dropped a malformed message: ${r.issues[0]?.message ?? 'invalid'}`);
    return null;
  }
  return { from: r.output.from, body: r.output.body };
}

function dispatch(handlers: BusHandler[], m: BusMessage): void {
  for (const h of handlers) {
    try {
      h(m);
    } catch (err) {
      console.warn(`bus: a handler failed: ${(err as Error).message}`);
    }
  }
}

export class RedisBus implements Bus {
  private readonly commands: BusHandler[] = [];
  private readonly deliveries: BusHandler[] = [];
  private constructor(private readonly processId: string, private readonly pub: RedisClient, private readonly sub: RedisClient) {}

  /** Subscribes this process's channels on a dedicated connection; `pub` is shared. */
  static async open(url: string, pub: RedisClient, processId: string): Promise<RedisBus> {
    requireId('processId', processId);
    const sub = await connectRedis(url, `bus ${processId}`);
    const bus = new RedisBus(processId, pub, sub);
    await sub.subscribe(KEYS.proc(processId), (raw: string) => {
      const m = parseEnvelope(raw);
      if (m) dispatch(bus.commands, m);
    });
    await sub.subscribe(KEYS.deliver, (raw: string) => {
      const m = parseEnvelope(raw);
      if (m) dispatch(bus.deliveries, m);
    });
    return bus;
  }

  async command(toProcess: string, body: unknown): Promise<number> {
    return Number(await this.pub.sendCommand(['PUBLISH', KEYS.proc(requireId('toProcess', toProcess)), JSON.stringify({ from: this.processId, body })]));
  }
  async deliver(body: unknown): Promise<void> {
    await this.pub.sendCommand(['PUBLISH', KEYS.deliver, JSON.stringify({ from: this.processId, body })]);
  }
  onCommand(handler: BusHandler): void {
    this.commands.push(handler);
  }
  onDelivery(handler: BusHandler): void {
    this.deliveries.push(handler);
  }
  async close(): Promise<void> {
    this.sub.destroy();
  }
}
