-- The leaderboard's partial index (established ratings only), the pair's daily limit, and why a
-- result was not rated.
DROP INDEX ratings_board;
CREATE INDEX ratings_board ON ratings (kind, rating DESC, player_id, rd) WHERE rd < 110;

CREATE INDEX results_pair ON results (winner, loser, finished_at) WHERE rated = 1;

ALTER TABLE results ADD COLUMN unrated TEXT CONSTRAINT results_unrated CHECK (unrated IN ('few-shots', 'too-short', 'pair-limit'));
UPDATE results SET unrated = 'few-shots' WHERE rated = 0;
