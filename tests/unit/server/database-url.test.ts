// BAIZE_DATABASE_URL: unset or empty is SQLite as before; a postgres:// URL is PostgreSQL; anything
// else is refused at start with a message that does not repeat the value (it may hold a password).
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { startServer } from '../../../server/app.ts';
import { readConfig } from '../../../server/config.ts';
import { tempDir } from '../../support/server-process.ts';

describe('BAIZE_DATABASE_URL', () => {
  it('is optional: without it (or empty) the server keeps its SQLite file', () => {
    expect(readConfig({}).databaseUrl).toBeUndefined();
    expect(readConfig({ BAIZE_DATABASE_URL: '' }).databaseUrl).toBeUndefined();
    expect(readConfig({ BAIZE_DATABASE_URL: '  ' }).databaseUrl).toBeUndefined();
  });

  it('takes a postgres:// or postgresql:// URL with a host', () => {
    for (const url of ['postgres://baize:secret@db.example:5432/baize', 'postgresql://127.0.0.1/baize', 'postgres://u@[::1]:6000/x?sslmode=require']) {
      expect(readConfig({ BAIZE_DATABASE_URL: url }).databaseUrl).toBe(url);
    }
  });

  it('refuses anything else, without repeating it', () => {
    for (const bad of ['mysql://u:hunter2@h/db', 'hunter2', 'postgres:///baize', 'file:/tmp/hunter2.db', 'http://hunter2@h/db']) {
      let err: unknown;
      try {
        readConfig({ BAIZE_DATABASE_URL: bad });
      } catch (e) {
        err = e;
      }
      expect(err, bad).toBeInstanceOf(RangeError);
      expect((err as Error).message).toMatch(/^BAIZE_DATABASE_URL must/);
      expect((err as Error).message).not.toContain('hunter2');
    }
  });
});

describe('the server with BAIZE_DATABASE_URL', () => {
  it('serves from PostgreSQL only: with no database there it does not start, and never falls back on the file', async () => {
    // Port 1 on this machine: nothing listens there, the connection is refused at once.
    const config = readConfig({ BAIZE_DATABASE_URL: 'postgres://baize@127.0.0.1:1/baize', BAIZE_DB: join(tempDir(), 'never.db') });
    await expect(startServer(config)).rejects.toThrow();
    expect(existsSync(config.dbPath)).toBe(false);
  });
});
