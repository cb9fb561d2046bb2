// The WebSocket protocol's one entry point (docs/protocol.md): the client messages' schemas, the
// server messages' types, the limits, and the parser the server runs on every frame.
import * as v from 'valibot';
import { ClientMessageSchema, type ClientMessage } from './client-messages.ts';

export * from './limits.ts';
export * from './text.ts';
export * from './client-messages.ts';
export type * from './server-messages.ts';

export type ParseResult =
  | { readonly ok: true; readonly message: ClientMessage }
  | { readonly ok: false; readonly code: 'bad-json' | 'bad-message'; readonly message: string; readonly re?: string | number };

/** The request id of a rejected message, when it has a usable one, so the error can carry it back. */
function requestIdOf(data: unknown): string | number | undefined {
  if (typeof data !== 'object' || data === null) return undefined;
  const id = (data as { id?: unknown }).id;
  if (typeof id === 'string' && id.length <= 64) return id;
  if (typeof id === 'number' && Number.isFinite(id)) return id;
  return undefined;
}

/** Parses one text frame: JSON, then the schema of its `type`. Never throws. */
export function parseClientMessage(text: string): ParseResult {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return { ok: false, code: 'bad-json', message: 'the frame is not valid JSON' };
  }
  const result = v.safeParse(ClientMessageSchema, data);
  if (result.success) return { ok: true, message: result.output };
  const issue = result.issues[0];
  const path = issue.path?.map((p) => String(p.key)).join('.') ?? '';
  const re = requestIdOf(data);
  return { ok: false, code: 'bad-message', message: path ? `${path}: ${issue.message}` : issue.message, ...(re === undefined ? {} : { re }) };
}
