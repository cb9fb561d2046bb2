// The HTTP API (docs/api.md): leaderboards, records, players, matches with their replays, and
// practice runs the server plays itself from seeds it issued. JSON in and out; reads go straight
// to the store (its asynchronous contract, either database); practice requests are rate-limited per address and per player.
import { randomBytes } from 'node:crypto';
import type { IncomingMessage, ServerResponse } from 'node:http';
import type { PracticeKind } from '../../shared/rules/index.ts';
import { PROVISIONAL_RD } from '../ratings/glicko2.ts';
import { PRACTICE_SEED_TTL_MS, PracticeSeedError, type MatchRow, type PlayerRow, type AsyncStore, type RecordEntry } from '../store/index.ts';
import { hashToken } from '../tokens.ts';
import { ApiError, IdParam, LeaderboardQuery, MatchesQuery, parse, PracticeBody, PracticeStartBody, RecordsQuery } from './params.ts';
import { addressKey } from '../address.ts';
import { PRACTICE_LIMITS, RateLimiter, type PracticeLimits } from './rate-limit.ts';
import { IN_PROCESS, type PracticeScorer } from '../workers/pool.ts';
import { RefusedTask } from '../workers/tasks.ts';

/** Largest request body accepted (bytes): a practice run of 500 shots fits well within it. */
export const MAX_BODY_BYTES = 256 * 1024;

type Json = Record<string, unknown>;

const round = (x: number, digits = 2) => Math.round(x * 10 ** digits) / 10 ** digits;

function matchSummary(m: MatchRow): Json {
  return {
    id: m.id,
    kind: m.kind,
    raceTo: m.raceTo,
    players: [
      { id: String(m.player1), name: m.name1 },
      { id: String(m.player2), name: m.name2 },
    ],
    status: m.finishedAt === null ? 'playing' : 'over',
    result: m.winner === null ? null : { winner: String(m.winner), reason: m.how, rated: m.rated === 1, ...(m.unrated === null ? {} : { unrated: m.unrated }) },
    startedAt: m.startedAt,
    finishedAt: m.finishedAt,
  };
}

function recordEntry(r: RecordEntry, rank?: number): Json {
  return {
    ...(rank === undefined ? {} : { rank }),
    kind: r.kind,
    what: r.what,
    value: r.value,
    player: { id: String(r.playerId), name: r.name },
    source: r.matchId === null ? 'practice' : 'match',
    ...(r.matchId === null ? {} : { match: r.matchId }),
    ...(r.practiceId === null ? {} : { practice: r.practiceId }),
    at: r.createdAt,
  };
}

const SEED_HOURS = PRACTICE_SEED_TTL_MS / 3600_000;

export class Api {
  private readonly perPlayer: RateLimiter;
  private readonly perAddress: RateLimiter;

  constructor(
    private readonly store: AsyncStore,
    limits: PracticeLimits = PRACTICE_LIMITS,
    /** Where practice runs are replayed: the server's worker pool, off the event loop. */
    private readonly scorer: PracticeScorer = IN_PROCESS,
    private readonly now: () => number = Date.now,
  ) {
    this.perPlayer = new RateLimiter(limits.perPlayer);
    this.perAddress = new RateLimiter(limits.perAddress);
  }

  /** Answers a request under /api/; the caller has checked the prefix. */
  async handle(req: IncomingMessage, res: ServerResponse): Promise<void> {
    let status = 200;
    let body: Json;
    let headers: Readonly<Record<string, string>> = {};
    try {
      body = await this.route(req);
    } catch (err) {
      if (err instanceof ApiError) {
        status = err.status;
        headers = err.headers;
        body = { error: err.error, message: err.message };
      } else {
        status = 500;
        body = { error: 'internal', message: 'the server could not answer' };
        console.error(`api ${req.method} ${req.url}: ${(err as Error).stack ?? String(err)}`);
      }
    }
    const text = JSON.stringify(body);
    res.writeHead(status, { ...headers, 'content-type': 'application/json; charset=utf-8', 'content-length': Buffer.byteLength(text), 'cache-control': 'no-store', 'x-content-type-options': 'nosniff' });
    res.end(req.method === 'HEAD' ? undefined : text);
  }

  private async route(req: IncomingMessage): Promise<Json> {
    const url = new URL(req.url ?? '/', 'http://localhost');
    const path = url.pathname;
    const query = Object.fromEntries(url.searchParams);
    if (path === '/api/practice' || path === '/api/practice/start') {
      if (req.method !== 'POST') throw new ApiError(405, 'method-not-allowed', `POST to ${path}`);
      // The address is limited before its body is read, the player once its token is known.
      this.limit(this.perAddress, addressKey(req.socket.remoteAddress), 'this address');
      const input = await readJson(req);
      return path === '/api/practice' ? this.practice(input) : this.practiceStart(input);
    }
    if (req.method !== 'GET' && req.method !== 'HEAD') throw new ApiError(405, 'method-not-allowed', `${req.method} is not allowed on ${path}`);
    if (path === '/api/leaderboard') return this.leaderboard(query);
    if (path === '/api/records') return this.records(query);
    if (path === '/api/matches') return this.matches(query);
    const match = /^\/api\/matches\/([^/]+)$/.exec(path);
    if (match) return this.match(match[1]!);
    const player = /^\/api\/players\/([^/]+)$/.exec(path);
    if (player) return this.player(player[1]!);
    throw new ApiError(404, 'not-found', `no such endpoint: ${path}`);
  }

  private async leaderboard(query: Json): Promise<Json> {
    const q = parse(LeaderboardQuery, query);
    const { total, rows } = await this.store.leaderboard(q.kind, q.limit, q.offset);
    return {
      kind: q.kind,
      total,
      limit: q.limit,
      offset: q.offset,
      entries: rows.map((r, i) => ({
        rank: q.offset + i + 1,
        player: { id: String(r.id), name: r.name },
        rating: round(r.rating),
        rd: round(r.rd),
        games: r.games,
        wins: r.wins,
        // Always false: the board lists established ratings only (kept for the clients that read it).
        provisional: r.rd >= PROVISIONAL_RD,
      })),
    };
  }

  private async records(query: Json): Promise<Json> {
    const q = parse(RecordsQuery, query);
    return { kind: q.kind, source: q.source, entries: (await this.store.records(q.kind, q.limit, q.offset, q.source)).map((r, i) => recordEntry(r, q.offset + i + 1)) };
  }

  private async matches(query: Json): Promise<Json> {
    const q = parse(MatchesQuery, query);
    const filter = { ...(q.player === undefined ? {} : { player: q.player }), ...(q.kind === undefined ? {} : { kind: q.kind }) };
    return { limit: q.limit, offset: q.offset, matches: (await this.store.matches(filter, q.limit, q.offset)).map(matchSummary) };
  }

  private async match(idText: string): Promise<Json> {
    const id = parse(IdParam, idText);
    const m = await this.store.match(id);
    if (!m) throw new ApiError(404, 'not-found', `no match ${id}`);
    return {
      ...matchSummary(m),
      start: m.start === null ? null : (JSON.parse(m.start) as unknown),
      actions: (await this.store.matchActions(id)).map((a) => a.action),
    };
  }

  private async player(idText: string): Promise<Json> {
    const id = parse(IdParam, idText);
    const p = await this.store.playerById(id);
    if (!p) throw new ApiError(404, 'not-found', `no player ${id}`);
    const ratings = await this.store.ratingsOf(id);
    return {
      id: String(p.id),
      name: p.name,
      ratings: Object.fromEntries(ratings.map((r) => [r.kind, { rating: round(r.rating), rd: round(r.rd), games: r.games, wins: r.wins, provisional: r.rd >= PROVISIONAL_RD }])),
      games: ratings.reduce((n, r) => n + r.games, 0),
      wins: ratings.reduce((n, r) => n + r.wins, 0),
      records: (await this.store.bestRecordsOf(id)).map((r) => recordEntry(r)),
      recent: (await this.store.matches({ player: id }, 10, 0)).map(matchSummary),
    };
  }

  /** Takes a request from `key`'s bucket, or refuses it with a 429 saying when to come back. */
  private limit(limiter: RateLimiter, key: string, who: string): void {
    const wait = limiter.take(key, this.now());
    if (wait > 0) throw new ApiError(429, 'rate-limited', `too many practice requests from ${who}: try again in ${wait} s`, { 'retry-after': String(wait) });
  }

  /** The player of a practice request's token, within their rate limit. */
  private async practiser(token: string): Promise<PlayerRow> {
    const player = await this.store.playerByTokenHash(hashToken(token));
    if (!player) throw new ApiError(400, 'bad-token', 'token: unknown; say hello over the WebSocket to get one');
    this.limit(this.perPlayer, String(player.id), 'you');
    return player;
  }

  /** Issues a seed for a run: the rack it is played from, which the client cannot choose. */
  private async practiceStart(input: unknown): Promise<Json> {
    const body = parse(PracticeStartBody, input, 'bad-body');
    const player = await this.practiser(body.token);
    // A seed the player already holds for this kind is drawn again (about 1 in 200 million).
    for (let i = 0; i < 8; i++) {
      const seed = randomBytes(4).readUInt32LE(0);
      const issuedAt = await this.store.issuePracticeSeed(player.id, body.kind, seed);
      if (issuedAt !== null) return { kind: body.kind, seed, expiresAt: issuedAt + PRACTICE_SEED_TTL_MS };
    }
    throw new Error('no new practice seed in 8 draws');
  }

  /**
   * Plays the run's shots from the start of its game (in the worker pool), scores it, and keeps it
   * with its records; only from a seed issued to the player for the kind and not used yet, checked
   * before the shots are played and again as the run is saved.
   */
  private async practice(input: unknown): Promise<Json> {
    const body = parse(PracticeBody, input, 'bad-body');
    const player = await this.practiser(body.token);
    const seed = body.seed;
    const state = await this.store.practiceSeedState(player.id, body.kind, seed);
    if (state !== 'open') throw seedRefused(state, body.kind);
    let run;
    try {
      run = await this.scorer.scorePractice({ kind: body.kind as PracticeKind, player: String(player.id), seed, shots: body.shots });
    } catch (err) {
      if (err instanceof RefusedTask) throw new ApiError(400, 'bad-shot', err.message);
      throw err;
    }
    const records = run.achievements.map((a) => ({ what: a.what, player: player.id, value: a.value, better: a.what === 'break-and-run' ? -a.value : a.value }));
    let saved;
    try {
      saved = await this.store.savePractice({ player: player.id, kind: body.kind, seed, shots: JSON.stringify(body.shots), score: run.score, records });
    } catch (err) {
      if (err instanceof PracticeSeedError) throw seedRefused(err.state, body.kind);
      throw err;
    }
    return {
      id: saved.id,
      kind: body.kind,
      seed,
      score: run.score,
      shots: run.shots,
      records: run.achievements.map((a, i) => ({ what: a.what, value: a.value, standing: saved.standing[i] })),
    };
  }
}

function seedRefused(state: 'used' | 'unknown', kind: string): ApiError {
  return state === 'used'
    ? new ApiError(409, 'seed-used', 'seed: already used for a run; POST /api/practice/start for a new one')
    : new ApiError(409, 'seed-not-issued', `seed: not issued to you for ${kind}, or expired (a seed lasts ${SEED_HOURS} hours); POST /api/practice/start for one`);
}

/** Reads a JSON body of at most MAX_BODY_BYTES. */
async function readJson(req: IncomingMessage): Promise<unknown> {
  const chunks: Buffer[] = [];
  let size = 0;
  try {
    for await (const chunk of req) {
      size += (chunk as Buffer).length;
      if (size > MAX_BODY_BYTES) throw new ApiError(413, 'too-large', `the body is larger than ${MAX_BODY_BYTES} bytes`);
      chunks.push(chunk as Buffer);
    }
  } catch (err) {
    if (err instanceof ApiError) throw err;
    // The request's deadline passed (the server has answered 408 and closed it) or the client left.
    throw new ApiError(408, 'timeout', 'the request body did not arrive in time');
  }
  try {
    return JSON.parse(Buffer.concat(chunks).toString('utf8')) as unknown;
  } catch {
    throw new ApiError(400, 'bad-body', 'the body is not valid JSON');
  }
}
