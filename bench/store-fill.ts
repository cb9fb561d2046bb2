// Fills a fresh database for bench:store through the Store's public methods only: players, a few
// hundred rooms, and finished matches whose results go through saveChanges (so the Glicko-2
// ratings and the records are written by the store itself, in the same transaction as the result).
// Everything is drawn from a seeded generator: the same options give the same database.
import { createHash } from 'node:crypto';
import type { Database } from 'better-sqlite3';
import { Store, type RecordRow } from '../server/store/index.ts';
import { newGame } from '../shared/rules/index.ts';
import { generator } from '../shared/scenes/index.ts';

export const KINDS = ['nineball', 'eightball', 'snooker', 'threecushion'] as const;
export type Kind = (typeof KINDS)[number];

/** Share of the matches of each kind, and of the players whose favourite kind it is. */
const KIND_SHARE: Record<Kind, number> = { nineball: 0.3, eightball: 0.3, snooker: 0.2, threecushion: 0.2 };
/** Share of players who signed up and never finished a match. */
const IDLE_SHARE = 0.15;
/** Pareto exponent of the players' activity (lower: heavier tail), and its cap (in units of the least active). */
const ACTIVITY_ALPHA = 1.15;
const ACTIVITY_CAP = 1000;
/** How much more often a player plays their favourite kind than each other kind. */
const FAVOURITE_WEIGHT = 7;
/** Rooms per kind, reused by the matches of that kind. */
const ROOMS_PER_KIND = 100;
/** Matches written per outer transaction, by default: a big one writes each index page touched once. */
const BATCH = 50_000;
/** The first player signs up here; matches are played over the following year (ms since the epoch). */
const T0 = Date.UTC(2024, 0, 1);
const DAY = 86_400_000;
/** Sign-ups run over the first 300 days; matches from day 60 for a year. */
const SIGN_UP_SPAN = 300 * DAY;
const MATCHES_FROM = 60 * DAY;

/** The project's seeded generator (mulberry32, shared/scenes), uniform in [0, 1). */
export const rng = generator;

export interface FillOptions {
  readonly players: number;
  readonly matches: number;
  readonly seed?: number;
  /** Matches written per outer transaction. */
  readonly batch?: number;
  /** Called every so often with a line of progress. */
  readonly progress?: (line: string) => void;
}

export interface Quantiles {
  readonly median: number;
  readonly p90: number;
  readonly p99: number;
  readonly max: number;
}

export interface FillStats {
  readonly players: number;
  readonly matches: number;
  readonly rooms: number;
  readonly playersSeconds: number;
  readonly matchesSeconds: number;
  /** Results the store rated (the game's rule and the pairs' daily limit). */
  readonly rated: number;
  /** Records written, by kind (snooker breaks, three-cushion runs, nine-ball break-and-runs). */
  readonly records: Record<string, number>;
  /** Players with at least one rated match, by kind. */
  readonly ratedPlayers: Record<Kind, number>;
  /** Players on the leaderboard, by kind (established ratings: the leaderboard's total). */
  readonly ranked: Record<Kind, number>;
  /** Matches per player, over all players (idle ones count as 0). */
  readonly matchesPerPlayer: Quantiles;
  /** Players who never finished a match. */
  readonly idlePlayers: number;
  /** Ids of the players with the most matches, busiest first (at most 100). */
  readonly busiest: readonly number[];
  /** Matches of the busiest player. */
  readonly busiestMatches: number;
  /** The id range of players and of matches (both 1..n in a fresh database). */
  readonly playerIds: readonly [number, number];
  readonly matchIds: readonly [number, number];
}

/**
 * A unique name of 1-32 characters, also by its lookalike keys (server/players/names.ts): the index
 * in decimal ends it, and no two digit strings look alike.
 */
const ADJECTIVES = ['Swift', 'Calm', 'Lucky', 'Bold', 'Quiet', 'Sharp', 'Steady', 'Clever', 'Brave', 'Silent', 'Golden', 'Red', 'Blue', 'Green', 'Pink', 'Black'];
const NOUNS = ['Cue', 'Pocket', 'Rail', 'Chalk', 'Break', 'Spin', 'Kiss', 'Bank', 'Draw', 'Baize', 'Frame', 'Carom', 'Cushion', 'Rack', 'Shark', 'Hustler'];
function playerName(i: number, r: () => number): string {
  const a = ADJECTIVES[Math.floor(r() * ADJECTIVES.length)]!;
  const n = NOUNS[Math.floor(r() * NOUNS.length)]!;
  return `${a}${n}_${i}`;
}

/** sha256 of the index: unique 32-byte token hashes, the same on every run. */
const tokenHash = (i: number): Buffer => createHash('sha256').update(`bench-token-${i}`).digest();

/** Normal(0, 1) by Box-Muller. */
function gauss(r: () => number): number {
  return Math.sqrt(-2 * Math.log(1 - r())) * Math.cos(2 * Math.PI * r());
}

/** An index below `limit` with probability proportional to cum[i] - cum[i-1] (cum ascending). */
function pick(cum: Float64Array, limit: number, r: () => number): number {
  const x = r() * cum[limit - 1]!;
  let lo = 0;
  let hi = limit - 1;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (cum[mid]! > x) hi = mid;
    else lo = mid + 1;
  }
  return lo;
}

function quantiles(xs: Int32Array): Quantiles {
  const s = Int32Array.from(xs).sort();
  const at = (q: number) => s[Math.min(s.length - 1, Math.floor(q * s.length))]!;
  return { median: at(0.5), p90: at(0.9), p99: at(0.99), max: s[s.length - 1]! };
}

/** The records one finished match sets, the way the replay's achievements would. */
function recordsOf(kind: Kind, winner: number, loser: number, rated: boolean, r: () => number): RecordRow[] {
  const out: RecordRow[] = [];
  const scored = rated ? 0.85 : 0.25; // a match conceded early often has no scoring visit
  if (kind === 'snooker') {
    for (const p of [winner, loser]) {
      // The highest break of each player who potted: mostly small, now and then a century.
      if (r() < scored) {
        const value = Math.min(147, 1 + Math.floor(-Math.log(1 - r()) * (p === winner ? 22 : 14)));
        out.push({ what: 'break', player: p, value, better: value });
      }
    }
  } else if (kind === 'threecushion') {
    for (const p of [winner, loser]) {
      if (r() < scored) {
        const value = Math.min(40, 1 + Math.floor(-Math.log(1 - r()) * (p === winner ? 2.5 : 1.5)));
        out.push({ what: 'run', player: p, value, better: value });
      }
    }
  } else if (kind === 'nineball' && rated && r() < 0.06) {
    // A rack won by its breaker without the opponent at the table: the shots it took, fewer better.
    const value = 4 + Math.floor(r() * r() * 9);
    out.push({ what: 'break-and-run', player: winner, value, better: -value });
  }
  return out;
}

export function fill(db: Database, options: FillOptions): FillStats {
  const r = rng(options.seed ?? 20_240_101);
  const say = options.progress ?? (() => {});
  const n = options.players;
  const m = options.matches;
  let clock = T0;
  const store = new Store(db, () => clock);

  // Players: a name, a token hash, a hidden skill that decides their matches, an activity (how
  // often they play, heavy-tailed) and a favourite kind.
  const t0 = performance.now();
  const ids = new Int32Array(n);
  const skill = new Float64Array(n);
  const activity = new Float64Array(n);
  const favourite = new Uint8Array(n);
  const signUpSpan = SIGN_UP_SPAN;
  db.transaction(() => {
    for (let i = 0; i < n; i++) {
      clock = T0 + Math.floor((i / n) * signUpSpan);
      ids[i] = store.createPlayer(playerName(i, r), tokenHash(i)).id;
      skill[i] = 1500 + 250 * gauss(r);
      activity[i] = r() < IDLE_SHARE ? 0 : Math.min(ACTIVITY_CAP, (1 - r()) ** (-1 / ACTIVITY_ALPHA));
      let x = r();
      let k = 0;
      while (k < KINDS.length - 1 && x >= KIND_SHARE[KINDS[k]!]) x -= KIND_SHARE[KINDS[k++]!];
      favourite[i] = k;
    }
  })();
  const playersSeconds = (performance.now() - t0) / 1000;
  say(`players: ${n} in ${playersSeconds.toFixed(1)} s`);

  // Who plays a kind: activity times the kind's weight for that player, as a cumulative table.
  // Players are in the order they signed up, and a match draws from those signed up by then.
  const cum = KINDS.map((_, k) => {
    const c = new Float64Array(n);
    let total = 0;
    for (let i = 0; i < n; i++) {
      total += activity[i]! * (favourite[i] === k ? FAVOURITE_WEIGHT : 1);
      c[i] = total;
    }
    return c;
  });

  // Rooms: a hundred of each kind, closed (so a restarted server brings none of them back).
  const rooms = KINDS.map((kind, k) =>
    Array.from({ length: ROOMS_PER_KIND }, (_, j) => {
      const id = `bench-${kind}-${j}`;
      store.createRoom({ id, kind, raceTo: 1, private: false, shotClock: 60, createdBy: ids[(k * ROOMS_PER_KIND + j) % n]!, status: 'closed', state: '{}' });
      return id;
    }),
  );
  // The rules' starting Game of each kind, the same JSON for every match of the kind.
  const starts = KINDS.map((kind) => JSON.stringify(newGame(kind, ['1', '2'], { seed: 1 })));

  const played = new Int32Array(n);
  const ratedIn = KINDS.map(() => new Uint8Array(n));
  const records: Record<string, number> = {};
  let rated = 0;
  let firstMatch = 0;
  let lastMatch = 0;
  const t1 = performance.now();
  const span = 365 * DAY;
  for (let done = 0; done < m; ) {
    const end = Math.min(m, done + (options.batch ?? BATCH));
    db.transaction(() => {
      for (; done < end; done++) {
        let x = r();
        let k = 0;
        while (k < KINDS.length - 1 && x >= KIND_SHARE[KINDS[k]!]) x -= KIND_SHARE[KINDS[k++]!];
        const kind = KINDS[k]!;
        const started = T0 + MATCHES_FROM + Math.floor((done / m) * span);
        // Players signed up by then (at least a few, so that two different ones can be drawn).
        const limit = Math.max(Math.min(n, 50), Math.min(n, Math.ceil(((started - T0) / signUpSpan) * n)));
        const a = pick(cum[k]!, limit, r);
        let b = pick(cum[k]!, limit, r);
        for (let tries = 0; b === a; tries++) b = tries < 100 ? pick(cum[k]!, limit, r) : (a + 1) % limit;
        const raceTo = kind === 'threecushion' ? (r() < 0.7 ? 15 : 25) : kind === 'snooker' ? 1 + Math.floor(r() * 3) : [1, 3, 5][Math.floor(r() * 3)]!;
        const roomId = rooms[k]![Math.floor(r() * ROOMS_PER_KIND)]!;
        clock = started;
        const matchId = store.createMatch({ roomId, kind, raceTo, player1: ids[a]!, player2: ids[b]!, seed: Math.floor(r() * 2 ** 32), start: starts[k]! });
        if (firstMatch === 0) firstMatch = matchId;
        lastMatch = matchId;
        const aWins = r() < 1 / (1 + 10 ** ((skill[b]! - skill[a]!) / 400));
        const [w, l] = aWins ? [a, b] : [b, a];
        const isRated = r() < 0.95;
        const how = !isRated ? 'concession' : r() < 0.9 ? 'played' : r() < 0.85 ? 'concession' : 'claim';
        const loserScore = Math.floor(r() * raceTo);
        const recs = recordsOf(kind, ids[w]!, ids[l]!, isRated, r);
        clock = started + 60_000 * (3 + Math.floor(r() * (kind === 'snooker' || kind === 'threecushion' ? 60 : 25)));
        store.saveChanges({
          roomId,
          status: 'closed',
          state: '{}',
          result: {
            matchId,
            kind,
            winner: ids[w]!,
            loser: ids[l]!,
            how,
            scores: JSON.stringify({ [ids[w]!]: how === 'played' ? raceTo : Math.floor(r() * raceTo), [ids[l]!]: loserScore }),
            rated: isRated,
            records: recs,
          },
        });
        played[a]!++;
        played[b]!++;
        // The store may leave it unrated (the pair's daily limit).
        if (isRated && store.matchResult(matchId)!.rated) {
          rated++;
          ratedIn[k]![a] = 1;
          ratedIn[k]![b] = 1;
        }
        if (recs.length > 0) records[kind] = (records[kind] ?? 0) + recs.length;
      }
    })();
    if (done % 50_000 === 0 || done === m) {
      const s = (performance.now() - t1) / 1000;
      say(`matches: ${done} / ${m} in ${s.toFixed(1)} s (${Math.round(done / s)} a second)`);
    }
  }
  const matchesSeconds = (performance.now() - t1) / 1000;

  const order = Array.from({ length: n }, (_, i) => i).sort((x, y) => played[y]! - played[x]! || x - y);
  const ratedPlayers = Object.fromEntries(KINDS.map((kind, k) => [kind, ratedIn[k]!.reduce((s, v) => s + v, 0)])) as Record<Kind, number>;
  const ranked = Object.fromEntries(KINDS.map((kind) => [kind, store.leaderboard(kind, 1, 0).total])) as Record<Kind, number>;
  return {
    players: n,
    matches: m,
    rooms: KINDS.length * ROOMS_PER_KIND,
    playersSeconds,
    matchesSeconds,
    rated,
    records,
    ratedPlayers,
    ranked,
    matchesPerPlayer: quantiles(played),
    idlePlayers: played.reduce((s, v) => s + (v === 0 ? 1 : 0), 0),
    busiest: order.slice(0, 100).map((i) => ids[i]!),
    busiestMatches: played[order[0]!] ?? 0,
    playerIds: [ids[0] ?? 0, ids[n - 1] ?? 0],
    matchIds: [firstMatch, lastMatch],
  };
}
