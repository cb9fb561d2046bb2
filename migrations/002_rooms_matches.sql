-- Rooms, matches, their action logs (the replays) and results. Times in ms since the Unix epoch.
-- A room's `state` is its JSON snapshot (seats, stateId, the rules' Game, the shot clock's
-- deadline), written in the same transaction as the action that changed it, so a server killed at
-- any moment restarts with every room in play as it was after its last change.
CREATE TABLE rooms (
  id          TEXT    PRIMARY KEY,
  kind        TEXT    NOT NULL CHECK (kind IN ('nineball', 'eightball', 'snooker', 'threecushion')),
  race_to     INTEGER NOT NULL CHECK (race_to >= 1),
  private     INTEGER NOT NULL CHECK (private IN (0, 1)),
  shot_clock  REAL    NOT NULL CHECK (shot_clock >= 0),
  created_by  INTEGER NOT NULL REFERENCES players (id),
  created_at  INTEGER NOT NULL,
  status      TEXT    NOT NULL CHECK (status IN ('waiting', 'playing', 'over', 'closed')),
  state       TEXT    NOT NULL,
  updated_at  INTEGER NOT NULL
);
CREATE INDEX rooms_open ON rooms (status) WHERE status IN ('waiting', 'playing', 'over');

-- One match: a game (or, in snooker, a race of frames) between two players in a room.
CREATE TABLE matches (
  id          INTEGER PRIMARY KEY,
  room_id     TEXT    NOT NULL REFERENCES rooms (id),
  kind        TEXT    NOT NULL,
  race_to     INTEGER NOT NULL,
  player1     INTEGER NOT NULL REFERENCES players (id),
  player2     INTEGER NOT NULL REFERENCES players (id),
  seed        INTEGER NOT NULL,
  started_at  INTEGER NOT NULL,
  finished_at INTEGER
);
CREATE INDEX matches_room ON matches (room_id);

-- Every move of a match in order (seq is the stateId it produced): the replay.
CREATE TABLE match_actions (
  match_id    INTEGER NOT NULL REFERENCES matches (id),
  seq         INTEGER NOT NULL,
  action      TEXT    NOT NULL,
  created_at  INTEGER NOT NULL,
  PRIMARY KEY (match_id, seq)
) WITHOUT ROWID;

-- A finished match's result, written once (the primary key refuses a second).
CREATE TABLE results (
  match_id    INTEGER PRIMARY KEY REFERENCES matches (id),
  winner      INTEGER NOT NULL REFERENCES players (id),
  loser       INTEGER NOT NULL REFERENCES players (id),
  how         TEXT    NOT NULL,
  scores      TEXT    NOT NULL,
  finished_at INTEGER NOT NULL
);
