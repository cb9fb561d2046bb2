// Every Redis key and channel of the multi-process mode, in one place (docs/scale.md lists them).
export const KEYS = {
  /** string counter: the next block of connection ids (INCRBY). */
  connIds: 'baize:conn-ids',
  /** string, PX: the process that owns a room. */
  lease: (roomId: string) => `baize:lease:${roomId}`,
  /** hash of token-bucket state, PX: a player's chat allowance. */
  chat: (player: string) => `baize:chat:${player}`,
  /** channel: commands for one process. */
  proc: (processId: string) => `baize:proc:${processId}`,
  /** channel: deliveries for every process. */
  deliver: 'baize:deliver',
  /** sorted set: each live process scored by its last heartbeat (ms since the epoch). */
  procs: 'baize:procs',
  /** hash conn id -> player JSON: the welcomed sockets a process holds. */
  presence: (processId: string) => `baize:presence:${processId}`,
} as const;

/** A clear error for an empty or non-string id. */
export function requireId(what: string, value: unknown): string {
  if (typeof value !== 'string' || value.length === 0 || value.length > 200) throw new Error(`${what} must be a non-empty string (got ${JSON.stringify(value)})`);
  return value;
}

/** A clear error for a duration that is not a positive finite number of milliseconds. */
export function requireMs(what: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isFinite(value) || value <= 0) throw new Error(`${what} must be a positive number of milliseconds (got ${String(value)})`);
  return Math.ceil(value);
}
