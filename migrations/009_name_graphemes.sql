-- Names count user-perceived characters (issue 37, defect 5): a name of 32 emoji such as a family
-- (7 code points) or a flag of Scotland (7) is one the server accepts (server/players/names.ts),
-- but SQLite's length() counts code points, and the CHECK of 001 allowed 32. The limit in
-- characters is the server's; the table keeps only a bound, 20 code points a character, as the
-- protocol does. A CHECK cannot be altered in SQLite, so the table is rebuilt: its rows are copied
-- aside and put back into the new table under the same ids. Foreign keys from other tables are
-- deferred to the commit meanwhile (dropping the table leaves their rows orphaned until each
-- player is back, which the commit checks).
PRAGMA defer_foreign_keys = ON;
CREATE TEMP TABLE players_copy AS SELECT * FROM players;
DROP TABLE players;
CREATE TABLE players (
  id              INTEGER PRIMARY KEY,
  name            TEXT    NOT NULL UNIQUE COLLATE NOCASE CHECK (length(name) BETWEEN 1 AND 640),
  token_hash      BLOB    NOT NULL UNIQUE CHECK (length(token_hash) = 32),
  created_at      INTEGER NOT NULL CHECK (created_at >= 0),
  name_key_lower  TEXT,
  name_key_upper  TEXT,
  last_seen       INTEGER
);
INSERT INTO players (id, name, token_hash, created_at, name_key_lower, name_key_upper, last_seen)
  SELECT id, name, token_hash, created_at, name_key_lower, name_key_upper, last_seen FROM players_copy;
DROP TABLE players_copy;
CREATE UNIQUE INDEX players_name_key_lower ON players (name_key_lower);
CREATE UNIQUE INDEX players_name_key_upper ON players (name_key_upper);
