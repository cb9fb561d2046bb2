-- The one row /healthz rewrites to prove that writes work.
CREATE TABLE health (
  id         INTEGER PRIMARY KEY CHECK (id = 1),
  checked_at BIGINT  NOT NULL
);
