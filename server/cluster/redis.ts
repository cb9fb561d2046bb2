// The Redis connection the cluster pieces share. They send raw commands (sendCommand), so that
// they do not depend on the client's typed option shapes.
import { createClient } from '@redis/client';

function make(url: string) {
  // Reconnects with a capped back-off; a lost server shows as rejected commands, not a crash.
  return createClient({ url, socket: { reconnectStrategy: (retries: number) => Math.min(50 * 2 ** retries, 2000), connectTimeout: 2000 } });
}

export type RedisClient = ReturnType<typeof make>;

/** A connected client whose errors are logged, never thrown at the process (it reconnects). */
export async function connectRedis(url: string, name = 'redis'): Promise<RedisClient> {
  const client = make(url);
  client.on('error', (err: Error) => console.warn(`${name}: ${err.message}`));
  await client.connect();
  return client;
}

export async function command(client: RedisClient, args: string[]): Promise<unknown> {
  return client.sendCommand(args);
}
