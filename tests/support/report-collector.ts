// A local server that collects what a page posts to it: a Firefox spectator opened with
// `?report=<url>` posts each shot's hash (client/pages/room.ts), as a test cannot drive it.
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';

export interface Reported {
  stateId: number;
  hash: string;
  server: string;
  userAgent: string;
}

export async function reportCollector(): Promise<{ url: string; got: Reported[]; close(): Promise<void> }> {
  const got: Reported[] = [];
  const server: Server = createServer((req, res) => {
    let body = '';
    req.on('data', (d: Buffer) => (body += d.toString()));
    req.on('end', () => {
      res.writeHead(204, { 'access-control-allow-origin': '*' }).end();
      if (req.method === 'POST') got.push(JSON.parse(body) as Reported);
    });
  });
  await new Promise<void>((r) => server.listen(0, '127.0.0.1', r));
  return {
    url: `http://127.0.0.1:${(server.address() as AddressInfo).port}/report`,
    got,
    close: () => new Promise((r) => server.close(() => r())),
  };
}
