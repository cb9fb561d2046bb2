-- A player's best record of each kind, read from one index.
CREATE INDEX records_player_best ON records (player_id, kind, better DESC, id);
DROP INDEX records_player;
