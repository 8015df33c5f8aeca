-- Captures, jobs and the job queue (the same records as the embedded SQLite store).
-- JSON columns are text written and read by the service (serde); timestamps are unix ms.
CREATE TABLE captures (
    id TEXT PRIMARY KEY,
    views BIGINT NOT NULL,
    kinds TEXT NOT NULL,
    warnings TEXT NOT NULL,
    size_bytes BIGINT NOT NULL,
    created_at BIGINT NOT NULL
);

CREATE TABLE jobs (
    -- Insertion order: breaks ties of created_at (FIFO claims, newest-first lists).
    seq BIGSERIAL NOT NULL,
    id TEXT PRIMARY KEY,
    capture_id TEXT NOT NULL,
    spec TEXT NOT NULL,
    state TEXT NOT NULL CHECK (state IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
    progress TEXT NOT NULL,
    error TEXT,
    created_at BIGINT NOT NULL,
    started_at BIGINT,
    finished_at BIGINT,
    attempts INTEGER NOT NULL DEFAULT 0,
    cancel_requested BOOLEAN NOT NULL DEFAULT FALSE,
    -- The worker that holds the job and until when (unix ms); NULL unless running.
    owner TEXT,
    lease_until BIGINT,
    idempotency_key TEXT UNIQUE,
    request_hash TEXT
);

CREATE INDEX jobs_by_state ON jobs (state, created_at, seq);
CREATE INDEX jobs_by_capture ON jobs (capture_id, state);
CREATE INDEX jobs_newest_first ON jobs (created_at DESC, seq DESC);
