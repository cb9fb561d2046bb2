import { readFileSync } from 'node:fs';
import type { IncomingMessage, ServerResponse } from 'node:http';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { createRequestHandler } from '../../../server/http-routes.ts';
import type { StaticFile } from '../../../server/static-files.ts';
import { pageOf, PAGES } from '../../../shared/protocol/pages.ts';
import { ROOT } from '../../support/server-process.ts';

const INDEX: StaticFile = { body: Buffer.from('<!doctype html><main id="app"></main>'), contentType: 'text/html; charset=utf-8' };
const APP: StaticFile = { body: Buffer.from('console.log(1)'), contentType: 'text/javascript; charset=utf-8' };
const handle = createRequestHandler(new Map([['/', INDEX], ['/index.html', INDEX], ['/app.js', APP]]), () => ({ ok: true, version: 't', schema: 1 }));

/** The status and body the server answers a browser's GET of `path` with. */
function get(path: string): { status: number; body: string } {
  let status = 0;
  let body = '';
  const req = { url: path, method: 'GET', headers: { accept: 'text/html' } } as unknown as IncomingMessage;
  const res = {
    req,
    writeHead: (s: number) => (status = s),
    end: (b?: string | Buffer) => (body = b === undefined ? '' : b.toString()),
  } as unknown as ServerResponse;
  handle(req, res);
  return { status, body };
}

const PATHS = [
  '/', '/help', '/lab', '/practice', '/leaderboard', '/room/abc', '/room/Z9_-x', '/player/1', '/player/abc', '/match/42', '/match/xyz',
  '/room/', '/room/a/b', '/room/a.b', `/room/${'a'.repeat(65)}`, '/help/', '/helps', '/lobby', '/nope', '/app.js', '/healthz',
];

describe('page routes, listed once for the server and the client', () => {
  it('the server answers 200 with the client document exactly for the paths the client routes', () => {
    for (const path of PATHS) {
      const { status, body } = get(path);
      const served = status === 200 && body === INDEX.body.toString();
      expect({ path, served }).toEqual({ path, served: pageOf(path) !== undefined });
    }
    expect(get('/help').status).toBe(200);
    expect(pageOf('/help')?.name).toBe('help');
    expect(pageOf('/player/abc')).toEqual({ name: 'player', param: 'abc' });
  });

  it('the client has a page to mount for every listed path, and no route list of its own', () => {
    const main = readFileSync(join(ROOT, 'client/main.ts'), 'utf8');
    const mounts = /const MOUNTS[^{]*\{([^}]*)\}/.exec(main)?.[1] ?? '';
    for (const p of PAGES) expect(mounts).toMatch(new RegExp(`\\b${p.name}: mount\\w+`));
    expect(main).toContain("from '../shared/protocol/pages.ts'");
    expect(main).not.toMatch(/\/\^\\\//); // no path regex of its own
  });
});
