// BAIZE_REDIS_URL and BAIZE_PROCESS_ID: unset is one process as before; a redis:// URL makes the
// process one of several, and only beside PostgreSQL; bad values are refused without echoing them.
import { describe, expect, it } from 'vitest';
import { readConfig } from '../../../server/config.ts';

const PG = 'postgres://127.0.0.1/baize';

function refusal(env: NodeJS.ProcessEnv): Error {
  try {
    readConfig(env);
  } catch (e) {
    return e as Error;
  }
  throw new Error(`accepted ${JSON.stringify(env)}`);
}

describe('BAIZE_REDIS_URL', () => {
  it('is optional: without it (or empty) the process is the whole platform', () => {
    expect(readConfig({}).redisUrl).toBeUndefined();
    expect(readConfig({ BAIZE_REDIS_URL: ' ', BAIZE_DATABASE_URL: PG }).redisUrl).toBeUndefined();
  });

  it('takes a redis:// or rediss:// URL with a host, beside BAIZE_DATABASE_URL', () => {
    for (const url of ['redis://127.0.0.1:6379', 'rediss://u:secret@cache.example:6380/2']) {
      expect(readConfig({ BAIZE_REDIS_URL: url, BAIZE_DATABASE_URL: PG }).redisUrl).toBe(url);
    }
  });

  it('refuses several processes on a SQLite file', () => {
    expect(refusal({ BAIZE_REDIS_URL: 'redis://127.0.0.1:6379' }).message).toMatch(/needs BAIZE_DATABASE_URL/);
  });

  it('refuses anything else, without repeating it', () => {
    for (const bad of ['http://hunter2@h', 'hunter2', 'redis://:hunter2@/0', 'postgres://hunter2@h/x']) {
      const err = refusal({ BAIZE_REDIS_URL: bad, BAIZE_DATABASE_URL: PG });
      expect(err, bad).toBeInstanceOf(RangeError);
      expect(err.message).toMatch(/^BAIZE_REDIS_URL must/);
      expect(err.message).not.toContain('hunter2');
    }
  });
});

describe('BAIZE_PROCESS_ID', () => {
  it('names the process, or is made up when unset', () => {
    expect(readConfig({}).processId).toBeUndefined();
    expect(readConfig({ BAIZE_PROCESS_ID: 'web-3.eu_1' }).processId).toBe('web-3.eu_1');
  });

  it('refuses names that could not be a channel name', () => {
    for (const bad of ['a b', 'x'.repeat(65), 'p:1', 'é']) expect(refusal({ BAIZE_PROCESS_ID: bad }).message).toMatch(/^BAIZE_PROCESS_ID must/);
  });
});
