-- Ratings that resist farming (issue 36; docs/api.md, "Ratings").

-- The leaderboard lists established ratings only: RD under 110, PROVISIONAL_RD in
-- server/ratings/glicko2.ts (the store's queries spell the same bound and name this index, so a
-- mismatch fails when they are prepared). A page and the count are one walk of this covering
-- index (rd in it spares a look at the row), however many provisional players there are.
DROP INDEX ratings_board;
CREATE INDEX ratings_board ON ratings (kind, rating DESC, player_id, rd) WHERE rd < 110;

-- Rated results between two players by time: the limit of rated matches a pair plays a day is two
-- seeks here (winner, loser and the other way round), inside the transaction that writes a result.
CREATE INDEX results_pair ON results (winner, loser, finished_at) WHERE rated = 1;

-- Why a finished match was not rated (NULL when it was). Earlier unrated results all had a player
-- with fewer than two shots.
ALTER TABLE results ADD COLUMN unrated TEXT CHECK (unrated IN ('few-shots', 'too-short', 'pair-limit'));
UPDATE results SET unrated = 'few-shots' WHERE rated = 0;
