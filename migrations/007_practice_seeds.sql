-- Practice with seeds the server issues, one standing practice record per player, and the records
-- boards of matches and of practice apart (issue 36).

-- Seeds issued for practice runs: a run is accepted only with a seed issued to its player for its
-- kind, once (`used_at` set in the transaction that saves the run). Rows older than a seed's
-- lifetime (the store's PRACTICE_SEED_TTL_MS) are deleted, used or not.
CREATE TABLE practice_seeds (
  id         INTEGER PRIMARY KEY,
  player_id  INTEGER NOT NULL REFERENCES players (id),
  kind       TEXT    NOT NULL,
  seed       INTEGER NOT NULL CHECK (seed BETWEEN 0 AND 4294967295),
  issued_at  INTEGER NOT NULL,
  used_at    INTEGER,
  UNIQUE (player_id, kind, seed)
);
CREATE INDEX practice_seeds_issued ON practice_seeds (issued_at);
-- A player's seeds not yet used, in the order issued (the oldest beyond a few are retired).
CREATE INDEX practice_seeds_open ON practice_seeds (player_id, id) WHERE used_at IS NULL;

-- One standing practice record per player, kind and record type: each one's best (the earliest
-- among equals) stays, the others go. Their runs stay in practice_runs.
DELETE FROM records WHERE practice_id IS NOT NULL AND id NOT IN (
  SELECT (SELECT r.id FROM records r
          WHERE r.practice_id IS NOT NULL AND r.player_id = k.player_id AND r.kind = k.kind AND r.what = k.what
          ORDER BY r.better DESC, r.id LIMIT 1)
  FROM (SELECT DISTINCT player_id, kind, what FROM records WHERE practice_id IS NOT NULL) k);
CREATE UNIQUE INDEX records_practice_one ON records (player_id, kind, what) WHERE practice_id IS NOT NULL;

-- The boards, read apart: a page of either is cut from its own index.
CREATE INDEX records_board_match ON records (kind, better DESC, id) WHERE match_id IS NOT NULL;
CREATE INDEX records_board_practice ON records (kind, better DESC, id) WHERE practice_id IS NOT NULL;
DROP INDEX records_board;
