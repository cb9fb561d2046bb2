// A local page that runs the golden corpus in a browser and a server that collects what the
// browser reports back: the bundle is built with esbuild from tests/browser/corpus-entry.ts.
import { build } from 'esbuild';
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { resolve } from 'node:path';
import { ROOT } from './server-process.ts';

export interface CorpusReport {
  readonly userAgent: string;
  readonly hashes: Record<string, string>;
}

export interface CorpusPage {
  /** The page; add ?report=<url>/report to have it post its hashes. */
  readonly url: string;
  readonly reportUrl: string;
  /** Resolves with the first report posted. */
  readonly report: Promise<CorpusReport>;
  close(): Promise<void>;
}

const HTML = '<!doctype html><meta charset="utf-8"><title>baize corpus</title><p id="status">running…</p><script type="module" src="/corpus.js"></script>';

export async function serveCorpusPage(): Promise<CorpusPage> {
  const bundle = await build({
    entryPoints: [resolve(ROOT, 'tests/browser/corpus-entry.ts')],
    bundle: true,
    format: 'esm',
    target: 'es2020',
    write: false,
    logLevel: 'warning',
  });
  const js = bundle.outputFiles[0]!.contents;
  let deliver: (r: CorpusReport) => void = () => {};
  const report = new Promise<CorpusReport>((res) => {
    deliver = res;
  });
  const server: Server = createServer((req, res) => {
    if (req.method === 'POST' && req.url === '/report') {
      let body = '';
      req.setEncoding('utf8');
      req.on('data', (d: string) => {
        body += d;
      });
      req.on('end', () => {
        res.writeHead(204).end();
        deliver(JSON.parse(body) as CorpusReport);
      });
      return;
    }
    if (req.url === '/corpus.js') {
      res.writeHead(200, { 'content-type': 'text/javascript' }).end(Buffer.from(js));
      return;
    }
    if (req.url?.startsWith('/?') || req.url === '/') {
      res.writeHead(200, { 'content-type': 'text/html; charset=utf-8' }).end(HTML);
      return;
    }
    res.writeHead(404).end();
  });
  await new Promise<void>((r) => server.listen(0, '127.0.0.1', r));
  const base = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
  return {
    url: `${base}/`,
    reportUrl: `${base}/report`,
    report,
    close: () =>
      new Promise<void>((r) => {
        server.closeAllConnections();
        server.close(() => r());
      }),
  };
}
