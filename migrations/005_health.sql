-- One row the health check rewrites (at most once a second): /healthz says the database can be
-- written only when a real write has just gone through.
CREATE TABLE health (
  id         INTEGER PRIMARY KEY CHECK (id = 1),
  checked_at INTEGER NOT NULL
);
