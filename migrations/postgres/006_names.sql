-- Name keys (lookalike names are taken: see server/players/names.ts), when a player was last seen,
-- and the indexes the pruner of idle players walks.
ALTER TABLE players ADD COLUMN name_key_lower TEXT;
ALTER TABLE players ADD COLUMN name_key_upper TEXT;
CREATE UNIQUE INDEX players_name_key_lower ON players (name_key_lower);
CREATE UNIQUE INDEX players_name_key_upper ON players (name_key_upper);

ALTER TABLE players ADD COLUMN last_seen BIGINT;
UPDATE players SET last_seen = created_at;

CREATE INDEX rooms_created_by ON rooms (created_by);
CREATE INDEX results_winner ON results (winner);
CREATE INDEX results_loser ON results (loser);
