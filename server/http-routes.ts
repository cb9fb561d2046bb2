// Plain HTTP: the client's files, /healthz and the JSON API under /api/. Everything else is 404
// (the client's page for a browser, JSON otherwise).
import type { IncomingMessage, ServerResponse } from 'node:http';
import type { Api } from './api/routes.ts';
import { pageOf } from '../shared/protocol/pages.ts';
import type { StaticFile } from './static-files.ts';
import type { EventLoopStats } from './event-loop-stats.ts';

export interface Health {
  readonly ok: boolean;
  readonly version: string;
  readonly schema: number;
  /** Why it is not ok. */
  readonly error?: string;
}

export function createRequestHandler(files: ReadonlyMap<string, StaticFile>, health: () => Health | Promise<Health>, api?: Api, loop?: EventLoopStats) {
  return (req: IncomingMessage, res: ServerResponse): void => {
    const path = (req.url ?? '/').split('?', 1)[0] ?? '/';
    if (api && path.startsWith('/api/')) {
      void api.handle(req, res);
      return;
    }
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      send(res, 405, 'application/json', JSON.stringify({ error: 'method not allowed' }), { allow: 'GET, HEAD' });
      return;
    }
    if (loop && path === '/diagnostics/event-loop') {
      send(res, 200, 'application/json', JSON.stringify(loop.read((req.url ?? '').includes('reset=1'))), { 'cache-control': 'no-store' });
      return;
    }
    if (path === '/healthz') {
      // Asynchronous: the store's probe may wait on another machine's database.
      void (async () => {
        let body: Health;
        try {
          body = await health();
        } catch (err) {
          body = { ok: false, version: '', schema: -1 };
          send(res, 503, 'application/json', JSON.stringify({ ...body, error: (err as Error).message }));
          return;
        }
        send(res, body.ok ? 200 : 503, 'application/json', JSON.stringify(body), { 'cache-control': 'no-store' });
      })();
      return;
    }
    // The client's pages are one document; its router shows the page of the path.
    const file = files.get(pageOf(path) ? '/' : path);
    if (file) {
      send(res, 200, file.contentType, file.body);
      return;
    }
    if (path === '/') {
      send(res, 503, 'text/plain; charset=utf-8', 'client not built: run `npm run build`\n');
      return;
    }
    // A browser asking for a page that does not exist gets the client, which says so in words.
    const index = files.get('/');
    if (index && /\btext\/html\b/.test(req.headers.accept ?? '')) {
      send(res, 404, index.contentType, index.body);
      return;
    }
    send(res, 404, 'application/json', JSON.stringify({ error: 'not found' }));
  };
}

function send(res: ServerResponse, status: number, type: string, body: string | Buffer, headers: Record<string, string> = {}): void {
  res.writeHead(status, {
    'content-type': type,
    'content-length': Buffer.byteLength(body),
    'x-content-type-options': 'nosniff',
    ...headers,
  });
  res.end(res.req.method === 'HEAD' ? undefined : body);
}
