// The process registry and presence in Redis: each process scores itself in one sorted set at
// every heartbeat, and lists its welcomed sockets in a hash of its own. A process whose heartbeat
// is older than the deadline is dead: any survivor removes its entry and its sockets (idempotent).
import * as v from 'valibot';
import { KEYS, requireId } from './keys.ts';
import { command, type RedisClient } from './redis.ts';

export interface PresenceEntry {
  readonly proc: string;
  readonly conn: number;
  readonly player: { readonly id: string; readonly name: string };
}

const Player = v.object({ id: v.pipe(v.string(), v.minLength(1)), name: v.string() });

export class RedisRegistry {
  constructor(private readonly client: RedisClient) {}

  /** Scores `proc` alive at `now`; true when it was already listed (false: new, or declared dead meanwhile). */
  async beat(proc: string, now: number): Promise<boolean> {
    const added = Number(await command(this.client, ['ZADD', KEYS.procs, String(Math.floor(now)), requireId('proc', proc)]));
    return added === 0;
  }

  /** Every listed process with its last heartbeat (ms). */
  async processes(): Promise<Map<string, number>> {
    const reply = (await command(this.client, ['ZRANGE', KEYS.procs, '0', '-1', 'WITHSCORES'])) as unknown[];
    // RESP2 answers member, score, member, ...; RESP3 answers [member, score] pairs.
    const pairs = reply.length > 0 && Array.isArray(reply[0]) ? (reply as unknown[][]).map((p) => [p[0], p[1]]) : pairsOf(reply as string[]);
    return new Map(pairs.map(([proc, at]) => [String(proc), Number(at)]));
  }

  /** Forgets a dead process and its sockets. */
  async remove(proc: string): Promise<void> {
    await Promise.all([command(this.client, ['ZREM', KEYS.procs, requireId('proc', proc)]), command(this.client, ['DEL', KEYS.presence(proc)])]);
  }

  async joined(proc: string, conn: number, player: { id: string; name: string }): Promise<void> {
    await command(this.client, ['HSET', KEYS.presence(requireId('proc', proc)), String(conn), JSON.stringify({ id: player.id, name: player.name })]);
  }

  async left(proc: string, conn: number): Promise<void> {
    await command(this.client, ['HDEL', KEYS.presence(requireId('proc', proc)), String(conn)]);
  }

  /** The welcomed sockets of the listed processes; malformed entries are skipped. */
  async presence(procs: Iterable<string>): Promise<PresenceEntry[]> {
    const out: PresenceEntry[] = [];
    for (const proc of procs) {
      const flat = (await command(this.client, ['HGETALL', KEYS.presence(proc)])) as string[] | Record<string, string>;
      const pairs = Array.isArray(flat) ? pairsOf(flat) : Object.entries(flat);
      for (const [conn, json] of pairs) {
        const id = Number(conn);
        let parsed: unknown;
        try {
          parsed = JSON.parse(json);
        } catch {
          continue;
        }
        const r = v.safeParse(Player, parsed);
        if (Number.isSafeInteger(id) && r.success) out.push({ proc, conn: id, player: r.output });
      }
    }
    return out;
  }
}

function pairsOf(flat: readonly string[]): [string, string][] {
  const out: [string, string][] = [];
  for (let i = 0; i + 1 < flat.length; i += 2) out.push([String(flat[i]), String(flat[i + 1])]);
  return out;
}
