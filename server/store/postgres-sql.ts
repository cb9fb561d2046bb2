// The PostgreSQL store's statements, one for each of the SQLite store's (sqlite-sync.ts) and
// answering alike: aliases quoted (PostgreSQL folds them to lower case otherwise), text ordered
// by code point (COLLATE "C", as SQLite does), and what SQLite says with INDEXED BY or
// json_extract said in PostgreSQL's words.
import { PROVISIONAL_RD } from '../ratings/glicko2.ts';

/** Established (not provisional) ratings: the bound of the partial index ratings_board. */
const ESTABLISHED = `rd < ${PROVISIONAL_RD}`;

const MATCH_COLUMNS = `m.id, m.kind, m.race_to AS "raceTo", m.player1, p1.name AS name1, m.player2, p2.name AS name2,
  m.started_at AS "startedAt", m.finished_at AS "finishedAt", r.winner, r.how, r.rated, r.unrated`;
const MATCH_FROM = `FROM matches m JOIN players p1 ON p1.id = m.player1 JOIN players p2 ON p2.id = m.player2 LEFT JOIN results r ON r.match_id = m.id`;

const RECORD_COLUMNS = `rec.id, rec.kind, rec.what, rec.player_id AS "playerId", p.name, rec.value, rec.match_id AS "matchId",
  rec.practice_id AS "practiceId", rec.created_at AS "createdAt" FROM records rec JOIN players p ON p.id = rec.player_id`;

export const SQL = {
  playerByToken: 'SELECT id, name, last_seen AS "lastSeen" FROM players WHERE token_hash = $1',
  playerById: 'SELECT id, name FROM players WHERE id = $1',
  nameOwner: 'SELECT id FROM players WHERE (name_key_lower = $1 OR name_key_upper = $2) AND id <> $3 LIMIT 1',
  insertPlayer: 'INSERT INTO players (name, name_key_lower, name_key_upper, token_hash, created_at, last_seen) VALUES ($1, $2, $3, $4, $5, $6) RETURNING id',
  renamePlayer: 'UPDATE players SET name = $1, name_key_lower = $2, name_key_upper = $3 WHERE id = $4',
  touchPlayer: 'UPDATE players SET last_seen = $1 WHERE id = $2',
  keyless: 'SELECT id, name FROM players WHERE name_key_lower IS NULL OR name_key_upper IS NULL ORDER BY id',
  keyLowerUsed: 'SELECT id FROM players WHERE name_key_lower = $1',
  keyUpperUsed: 'SELECT id FROM players WHERE name_key_upper = $1',
  setKeys: 'UPDATE players SET name_key_lower = $1, name_key_upper = $2 WHERE id = $3',
  idlePage: `SELECT p.id, (coalesce(p.last_seen, p.created_at) < $1
       AND NOT EXISTS (SELECT 1 FROM matches WHERE player1 = p.id)
       AND NOT EXISTS (SELECT 1 FROM matches WHERE player2 = p.id)
       AND NOT EXISTS (SELECT 1 FROM rooms WHERE created_by = p.id)
       AND NOT EXISTS (SELECT 1 FROM ratings WHERE player_id = p.id)
       AND NOT EXISTS (SELECT 1 FROM records WHERE player_id = p.id)
       AND NOT EXISTS (SELECT 1 FROM practice_runs WHERE player_id = p.id)
       AND NOT EXISTS (SELECT 1 FROM practice_seeds WHERE player_id = p.id)) AS idle
     FROM players p WHERE p.id > $2 ORDER BY p.id LIMIT $3`,
  deletePlayer: 'DELETE FROM players WHERE id = $1',
  computerByLevel: 'SELECT p.id, p.name FROM computers c JOIN players p ON p.id = c.player_id WHERE c.level = $1',
  insertComputer: 'INSERT INTO computers (level, player_id) VALUES ($1, $2)',
  computersAmong: 'SELECT count(*) AS n FROM computers WHERE player_id IN ($1, $2)',

  openRoomsOf: "SELECT COUNT(*)::int AS n FROM rooms WHERE created_by = $1 AND status IN ('waiting', 'playing')",
  insertRoom: 'INSERT INTO rooms (id, kind, race_to, private, shot_clock, created_by, created_at, status, state, updated_at) VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10)',
  updateRoom: 'UPDATE rooms SET status = $1, state = $2, updated_at = $3 WHERE id = $4',
  // jsonb compares numbers by value, and a state without a stateId matches nothing (no cast fails).
  updateRoomAt: `UPDATE rooms SET status = $1, state = $2, updated_at = $3 WHERE id = $4 AND state::jsonb -> 'stateId' = to_jsonb($5::bigint)`,
  // The same with the stateId optional ($5 null: no check), and a move in one statement: the action
  // is inserted when the room's guarded row was updated (unguarded, always, as in saveChanges).
  updateRoomIf: `UPDATE rooms SET status = $1, state = $2, updated_at = $3 WHERE id = $4 AND ($5::bigint IS NULL OR state::jsonb -> 'stateId' = to_jsonb($5::bigint))`,
  move: `WITH room AS (
       UPDATE rooms SET status = $1, state = $2, updated_at = $3 WHERE id = $4 AND ($5::bigint IS NULL OR state::jsonb -> 'stateId' = to_jsonb($5::bigint))
       RETURNING id)
     INSERT INTO match_actions (match_id, seq, action, created_at) SELECT $6, $7, $8, $3 WHERE $5::bigint IS NULL OR EXISTS (SELECT 1 FROM room)`,
  room: 'SELECT id, status, state FROM rooms WHERE id = $1',
  openRooms: `SELECT id, status, state FROM rooms WHERE status IN ('waiting', 'playing', 'over') ORDER BY created_at, id COLLATE "C"`,
  insertMatch: 'INSERT INTO matches (room_id, kind, race_to, player1, player2, seed, start, started_at) VALUES ($1, $2, $3, $4, $5, $6, $7, $8) RETURNING id',
  insertAction: 'INSERT INTO match_actions (match_id, seq, action, created_at) VALUES ($1, $2, $3, $4)',
  actions: 'SELECT seq, action FROM match_actions WHERE match_id = $1 ORDER BY seq',
  shotCounts: `SELECT action::jsonb ->> 'player' AS player, count(*) AS n FROM match_actions
     WHERE match_id = $1 AND action::jsonb ->> 'type' = 'shot' GROUP BY 1`,
  matchStart: 'SELECT started_at AS "startedAt" FROM matches WHERE id = $1',
  finishMatch: 'UPDATE matches SET finished_at = $1 WHERE id = $2 AND finished_at IS NULL',

  insertResult: `INSERT INTO results (match_id, winner, loser, how, scores, rated, unrated, finished_at) VALUES ($1, $2, $3, $4, $5, $6, $7, $8)
     ON CONFLICT (match_id) DO NOTHING`,
  // Rated results of a kind between two players since a time (results_pair, both ways).
  pairRated: `SELECT count(*) AS n FROM matches WHERE kind = $3 AND id IN (
       SELECT match_id FROM results WHERE rated = 1 AND winner = $1 AND loser = $2 AND finished_at > $4
       UNION ALL SELECT match_id FROM results WHERE rated = 1 AND winner = $2 AND loser = $1 AND finished_at > $4)`,
  anchored: `SELECT count(*) AS n FROM (SELECT 1 FROM ratings WHERE kind = $1 AND ${ESTABLISHED} LIMIT $2) a`,
  rating: 'SELECT rating, rd, vol, games, wins FROM ratings WHERE kind = $1 AND player_id = $2',
  upsertRating: `INSERT INTO ratings (kind, player_id, rating, rd, vol, games, wins, updated_at) VALUES ($1, $2, $3, $4, $5, $6, $7, $8)
     ON CONFLICT (kind, player_id) DO UPDATE SET rating = excluded.rating, rd = excluded.rd, vol = excluded.vol,
       games = excluded.games, wins = excluded.wins, updated_at = excluded.updated_at`,
  insertRecord: 'INSERT INTO records (kind, what, player_id, value, better, match_id, practice_id, created_at) VALUES ($1, $2, $3, $4, $5, $6, NULL, $7)',
  result: 'SELECT winner, loser, how, scores, rated, unrated FROM results WHERE match_id = $1',
  resultCount: 'SELECT count(*) AS n FROM results',

  // A page cut from the partial index ratings_board first, then its rows.
  board: `SELECT r.player_id AS id, p.name, r.rating, r.rd, r.games, r.wins
     FROM (SELECT kind, player_id FROM ratings WHERE kind = $1 AND ${ESTABLISHED} ORDER BY rating DESC, player_id LIMIT $2 OFFSET $3) page
     JOIN ratings r ON r.kind = page.kind AND r.player_id = page.player_id JOIN players p ON p.id = r.player_id
     ORDER BY r.rating DESC, r.player_id`,
  boardCount: `SELECT count(*) AS n FROM ratings WHERE kind = $1 AND ${ESTABLISHED}`,
  ratingsOf: `SELECT kind, player_id AS id, '' AS name, rating, rd, games, wins FROM ratings WHERE player_id = $1 ORDER BY kind COLLATE "C"`,
  recordsMatch: `SELECT ${RECORD_COLUMNS} WHERE rec.id IN (SELECT id FROM records WHERE kind = $1 AND match_id IS NOT NULL ORDER BY better DESC, id LIMIT $2 OFFSET $3)
     ORDER BY rec.better DESC, rec.id`,
  recordsPractice: `SELECT ${RECORD_COLUMNS} WHERE rec.id IN (SELECT id FROM records WHERE kind = $1 AND practice_id IS NOT NULL ORDER BY better DESC, id LIMIT $2 OFFSET $3)
     ORDER BY rec.better DESC, rec.id`,
  bestRecordsOf: `SELECT ${RECORD_COLUMNS} WHERE rec.id IN (
       SELECT (SELECT id FROM records r WHERE r.player_id = $1 AND r.kind = k.kind ORDER BY r.better DESC, r.id LIMIT 1)
       FROM (SELECT 'nineball' AS kind UNION ALL SELECT 'snooker' UNION ALL SELECT 'threecushion') k)
     AND rec.player_id = $1 ORDER BY rec.kind COLLATE "C"`,
  matchesAll: `SELECT ${MATCH_COLUMNS} ${MATCH_FROM} ORDER BY m.id DESC LIMIT $1 OFFSET $2`,
  matchesKind: `SELECT ${MATCH_COLUMNS} ${MATCH_FROM} WHERE m.kind = $1 ORDER BY m.id DESC LIMIT $2 OFFSET $3`,
  // The page's ids from matches_player1 and matches_player2, newest first.
  matchesPlayer: `SELECT ${MATCH_COLUMNS} ${MATCH_FROM} WHERE m.id IN (
       SELECT id FROM matches WHERE player1 = $1 AND ($2::text IS NULL OR kind = $2)
       UNION SELECT id FROM matches WHERE player2 = $1 AND ($2::text IS NULL OR kind = $2)
       ORDER BY id DESC LIMIT $3 OFFSET $4)
     ORDER BY m.id DESC`,
  match: `SELECT ${MATCH_COLUMNS}, m.start ${MATCH_FROM} WHERE m.id = $1`,

  insertPractice: 'INSERT INTO practice_runs (player_id, kind, seed, shots, score, created_at) VALUES ($1, $2, $3, $4, $5, $6) RETURNING id',
  issueSeed: 'INSERT INTO practice_seeds (player_id, kind, seed, issued_at) VALUES ($1, $2, $3, $4) ON CONFLICT (player_id, kind, seed) DO NOTHING',
  retireSeeds: `DELETE FROM practice_seeds WHERE id IN (
       SELECT id FROM practice_seeds WHERE player_id = $1 AND used_at IS NULL AND issued_at >= $2 ORDER BY id DESC OFFSET $3)`,
  sweepSeeds: 'DELETE FROM practice_seeds WHERE issued_at < $1',
  seed: 'SELECT issued_at AS "issuedAt", used_at AS "usedAt" FROM practice_seeds WHERE player_id = $1 AND kind = $2 AND seed = $3',
  useSeed: 'UPDATE practice_seeds SET used_at = $1 WHERE player_id = $2 AND kind = $3 AND seed = $4 AND used_at IS NULL AND issued_at >= $5',
  dropWorsePractice: 'DELETE FROM records WHERE practice_id IS NOT NULL AND player_id = $1 AND kind = $2 AND what = $3 AND better < $4',
  insertPracticeRecord: `INSERT INTO records (kind, what, player_id, value, better, match_id, practice_id, created_at) VALUES ($1, $2, $3, $4, $5, NULL, $6, $7)
     ON CONFLICT (player_id, kind, what) WHERE practice_id IS NOT NULL DO NOTHING`,

  probeWrite: 'INSERT INTO health (id, checked_at) VALUES (1, $1) ON CONFLICT (id) DO UPDATE SET checked_at = excluded.checked_at',
} as const;
