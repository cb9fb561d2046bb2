// The HTTP API's inputs: query parameters and the practice bodies, each checked by a valibot
// schema, and the error every refusal becomes (400 naming the parameter, 404 for an unknown id).
import * as v from 'valibot';
import { GAME_KINDS, PointSchema, ShotSchema } from '../../shared/protocol/index.ts';
import { PRACTICE_KINDS, PRACTICE_MAX_SHOTS } from '../../shared/rules/index.ts';

export class ApiError extends Error {
  constructor(
    readonly status: 400 | 404 | 405 | 408 | 409 | 413 | 429,
    readonly error: string,
    message: string,
    /** Headers the answer carries (Retry-After on a 429). */
    readonly headers: Readonly<Record<string, string>> = {},
  ) {
    super(message);
  }
}

/** A whole number written in decimal, within [min, max]. */
const int = (name: string, min: number, max: number) =>
  v.pipe(
    v.string(),
    v.regex(/^\d{1,10}$/, `${name} must be a whole number from ${min} to ${max}`),
    v.transform(Number),
    v.number(),
    v.minValue(min, `${name} must be a whole number from ${min} to ${max}`),
    v.maxValue(max, `${name} must be a whole number from ${min} to ${max}`),
  );

const kindOf = (kinds: readonly string[]) => v.picklist(kinds, `kind must be one of ${kinds.join(', ')}`);

export const LeaderboardQuery = v.object({
  kind: kindOf(GAME_KINDS),
  limit: v.optional(int('limit', 1, 100), '20'),
  offset: v.optional(int('offset', 0, 1_000_000_000), '0'),
});

export const RecordsQuery = v.object({
  kind: kindOf(PRACTICE_KINDS),
  source: v.optional(v.picklist(['match', 'practice'], 'source must be match or practice'), 'match'),
  limit: v.optional(int('limit', 1, 100), '20'),
  offset: v.optional(int('offset', 0, 1_000_000_000), '0'),
});

export const MatchesQuery = v.object({
  player: v.optional(int('player', 1, Number.MAX_SAFE_INTEGER)),
  kind: v.optional(kindOf(GAME_KINDS)),
  limit: v.optional(int('limit', 1, 100), '20'),
  offset: v.optional(int('offset', 0, 1_000_000_000), '0'),
});

export const IdParam = int('id', 1, Number.MAX_SAFE_INTEGER);

export { PRACTICE_MAX_SHOTS };

const Token = v.pipe(v.string('token must be a string'), v.minLength(1, 'token must not be empty'), v.maxLength(128, 'token is too long'));

export const PracticeStartBody = v.object({
  token: Token,
  kind: kindOf(PRACTICE_KINDS),
});

export const PracticeBody = v.object({
  token: Token,
  kind: kindOf(PRACTICE_KINDS),
  seed: v.pipe(
    v.number('seed must be the number POST /api/practice/start answered'),
    v.integer('seed must be a whole number'),
    v.minValue(0, 'seed must be 0 or more'),
    v.maxValue(0xffffffff, 'seed must fit 32 bits'),
  ),
  shots: v.pipe(
    v.array(v.object({ shot: ShotSchema, cueBall: v.optional(PointSchema) }), 'shots must be an array of { shot, cueBall? }'),
    v.minLength(1, 'shots must not be empty'),
    v.maxLength(PRACTICE_MAX_SHOTS, `shots may hold at most ${PRACTICE_MAX_SHOTS}`),
  ),
});

/** Parses with a schema, or throws the 400 that names the first bad field. */
export function parse<S extends v.GenericSchema>(schema: S, input: unknown, error = 'bad-parameter'): v.InferOutput<S> {
  const r = v.safeParse(schema, input);
  if (r.success) return r.output;
  const issue = r.issues[0];
  const path = issue.path?.map((p) => String(p.key)).join('.') ?? '';
  const message = path && !issue.message.startsWith(path.split('.')[0]!) ? `${path}: ${issue.message}` : issue.message;
  throw new ApiError(400, error, message);
}
