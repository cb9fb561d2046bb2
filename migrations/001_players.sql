-- Players: a display name, the SHA-256 of their session token (the token itself is never stored)
-- and the creation time in milliseconds since the Unix epoch.
CREATE TABLE players (
  id          INTEGER PRIMARY KEY,
  name        TEXT    NOT NULL UNIQUE COLLATE NOCASE CHECK (length(name) BETWEEN 1 AND 32),
  token_hash  BLOB    NOT NULL UNIQUE CHECK (length(token_hash) = 32),
  created_at  INTEGER NOT NULL CHECK (created_at >= 0)
);
