-- Names are limited by graphemes (server/players/names.ts), so a name's code units may number up
-- to 640.
ALTER TABLE players DROP CONSTRAINT players_name_length;
ALTER TABLE players ADD CONSTRAINT players_name_length CHECK (char_length(name) BETWEEN 1 AND 640);
