-- Ratings, records and practice runs (issue 26), and the indexes the HTTP API reads by.

-- The rules' Game at the start of the match: with match_actions, the replay.
ALTER TABLE matches ADD COLUMN start TEXT;
CREATE INDEX matches_player1 ON matches (player1, id);
CREATE INDEX matches_player2 ON matches (player2, id);
CREATE INDEX matches_kind ON matches (kind, id);

-- Whether the result moved the ratings (a match with fewer than two shots by each player does not).
ALTER TABLE results ADD COLUMN rated INTEGER NOT NULL DEFAULT 0 CHECK (rated IN (0, 1));

-- A Glicko-2 rating per player and game kind.
CREATE TABLE ratings (
  kind       TEXT    NOT NULL,
  player_id  INTEGER NOT NULL REFERENCES players (id),
  rating     REAL    NOT NULL,
  rd         REAL    NOT NULL,
  vol        REAL    NOT NULL,
  games      INTEGER NOT NULL,
  wins       INTEGER NOT NULL,
  updated_at INTEGER NOT NULL,
  PRIMARY KEY (kind, player_id)
) WITHOUT ROWID;
CREATE INDEX ratings_board ON ratings (kind, rating DESC, player_id);
CREATE INDEX ratings_player ON ratings (player_id);

-- Practice runs the server played itself from their starting layout.
CREATE TABLE practice_runs (
  id         INTEGER PRIMARY KEY,
  player_id  INTEGER NOT NULL REFERENCES players (id),
  kind       TEXT    NOT NULL,
  seed       INTEGER NOT NULL,
  shots      TEXT    NOT NULL,
  score      INTEGER NOT NULL,
  created_at INTEGER NOT NULL
);
CREATE INDEX practice_player ON practice_runs (player_id, id);

-- Verified achievements: from a finished match or a practice run, never from a client's word.
-- `better` is the sort key, higher first (snooker breaks and three-cushion runs: the points;
-- nine-ball break-and-runs: fewer shots is better, so its negative).
CREATE TABLE records (
  id          INTEGER PRIMARY KEY,
  kind        TEXT    NOT NULL,
  what        TEXT    NOT NULL,
  player_id   INTEGER NOT NULL REFERENCES players (id),
  value       INTEGER NOT NULL,
  better      INTEGER NOT NULL,
  match_id    INTEGER REFERENCES matches (id),
  practice_id INTEGER REFERENCES practice_runs (id),
  created_at  INTEGER NOT NULL,
  CHECK ((match_id IS NULL) <> (practice_id IS NULL))
);
CREATE INDEX records_board ON records (kind, better DESC, id);
CREATE INDEX records_player ON records (player_id, kind);
