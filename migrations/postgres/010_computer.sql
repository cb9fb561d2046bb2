-- The computer's players, one per level, and 'computer' as a reason a result is not rated.
CREATE TABLE computers (
  level     INTEGER PRIMARY KEY CHECK (level BETWEEN 1 AND 5),
  player_id BIGINT  NOT NULL UNIQUE REFERENCES players (id)
);

ALTER TABLE results DROP CONSTRAINT results_unrated;
ALTER TABLE results ADD CONSTRAINT results_unrated CHECK (unrated IN ('few-shots', 'too-short', 'pair-limit', 'computer'));
