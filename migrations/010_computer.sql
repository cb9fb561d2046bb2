-- The computer opponent (issue 38): a stored player per level, so that its matches are recorded and
-- replayable like any other, listed here so that the ratings skip its matches. The reference keeps
-- the pruner from deleting it (a foreign key it cannot break).
CREATE TABLE computers (
  level     INTEGER PRIMARY KEY CHECK (level BETWEEN 1 AND 5),
  player_id INTEGER NOT NULL UNIQUE REFERENCES players (id)
);

-- A new reason a result is not rated: a computer played. SQLite cannot alter a CHECK, so results
-- is rebuilt under the same rows (nothing refers to it), with its indexes.
CREATE TEMP TABLE results_copy AS SELECT * FROM results;
DROP TABLE results;
CREATE TABLE results (
  match_id    INTEGER PRIMARY KEY REFERENCES matches (id),
  winner      INTEGER NOT NULL REFERENCES players (id),
  loser       INTEGER NOT NULL REFERENCES players (id),
  how         TEXT    NOT NULL,
  scores      TEXT    NOT NULL,
  finished_at INTEGER NOT NULL,
  rated       INTEGER NOT NULL DEFAULT 0 CHECK (rated IN (0, 1)),
  unrated     TEXT CHECK (unrated IN ('few-shots', 'too-short', 'pair-limit', 'computer'))
);
INSERT INTO results (match_id, winner, loser, how, scores, finished_at, rated, unrated)
  SELECT match_id, winner, loser, how, scores, finished_at, rated, unrated FROM results_copy;
DROP TABLE results_copy;
CREATE INDEX results_winner ON results (winner);
CREATE INDEX results_loser ON results (loser);
CREATE INDEX results_pair ON results (winner, loser, finished_at) WHERE rated = 1;
