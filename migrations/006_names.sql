-- Names unique by their lookalike keys (server/players/names.ts), and when each player was last seen.

-- The skeletons (Unicode TR39) of the lower- and upper-case name. Rows from before this migration
-- get theirs at start-up (Store.fillNameKeys, in JS); until then they are NULL, which UNIQUE allows.
ALTER TABLE players ADD COLUMN name_key_lower TEXT;
ALTER TABLE players ADD COLUMN name_key_upper TEXT;
CREATE UNIQUE INDEX players_name_key_lower ON players (name_key_lower);
CREATE UNIQUE INDEX players_name_key_upper ON players (name_key_upper);

-- Updated at hello (at most hourly); guests who never played are deleted some days after it.
ALTER TABLE players ADD COLUMN last_seen INTEGER;
UPDATE players SET last_seen = created_at;

-- Every column that refers to a player is indexed, so deleting a player checks its foreign keys
-- by index and not by scanning whole tables.
CREATE INDEX rooms_created_by ON rooms (created_by);
CREATE INDEX results_winner ON results (winner);
CREATE INDEX results_loser ON results (loser);
