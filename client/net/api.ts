// The HTTP API (docs/api.md), read with fetch.

/** The server answered with an error: its status, its code (`error`) and its message. */
export class ApiRefusal extends Error {
  constructor(
    readonly status: number,
    readonly code: string,
    message: string,
  ) {
    super(message);
  }
}

/** A request's answer; an ApiRefusal when the server refuses it, fetch's TypeError when offline. */
export async function api<T>(path: string, init?: RequestInit): Promise<T> {
  const res = await fetch(path, init);
  const body = (await res.json()) as T & { error?: string; message?: string };
  if (!res.ok) throw new ApiRefusal(res.status, body.error ?? 'http', body.message ?? `HTTP ${res.status}`);
  return body;
}

const postJson = (body: unknown): RequestInit => ({ method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify(body) });

/** A seed for a practice run of `kind`, issued by the server to this player. */
export async function practiceSeed(token: string, kind: string): Promise<number> {
  const r = await api<{ seed: number }>('/api/practice/start', { ...postJson({ token, kind }), signal: AbortSignal.timeout(10_000) });
  return r.seed;
}

export interface PracticeResult {
  id: number;
  score: number;
  records: { what: string; value: number; standing: boolean }[];
}

/** Submits a run played from an issued seed; the server plays its shots again to score it. */
export function submitPractice(run: { token: string; kind: string; seed: number; shots: unknown[] }): Promise<PracticeResult> {
  return api<PracticeResult>('/api/practice', postJson(run));
}
