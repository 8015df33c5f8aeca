-- Why a job failed as a stable name (out_of_memory, time_limit, training_failed, …), and how its
-- latest attempt's process died (an attempt that dies the same way again fails the job).
ALTER TABLE jobs ADD COLUMN error_code TEXT;
ALTER TABLE jobs ADD COLUMN last_death TEXT;
-- Idempotency keys per account: the client's key as sent, unique within its account (the admin's
-- records, without an account, are one more scope). Keys were stored prefixed with the account's
-- name in `idempotency_key`, on which an admin's key `bob/k7` and bob's `k7` collided.
ALTER TABLE jobs ADD COLUMN request_key TEXT;
UPDATE jobs SET request_key = CASE
        WHEN account IS NOT NULL AND left(idempotency_key, length(account) + 1) = account || '/'
        THEN substr(idempotency_key, length(account) + 2)
        ELSE idempotency_key END
WHERE idempotency_key IS NOT NULL;
ALTER TABLE jobs DROP COLUMN idempotency_key;
CREATE UNIQUE INDEX jobs_by_request_key ON jobs (COALESCE(account, ''), request_key)
    WHERE request_key IS NOT NULL;
-- The size of a capture's views, for the memory a job on it needs (0 for older captures).
ALTER TABLE captures ADD COLUMN width BIGINT NOT NULL DEFAULT 0;
ALTER TABLE captures ADD COLUMN height BIGINT NOT NULL DEFAULT 0;
-- Webhooks: where a job's end is reported, and how its delivery goes (attempts, the last one's
-- status, when the next is due, whether delivered or given up).
ALTER TABLE jobs ADD COLUMN webhook_url TEXT;
ALTER TABLE jobs ADD COLUMN webhook_attempts INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN webhook_status TEXT;
ALTER TABLE jobs ADD COLUMN webhook_next_at BIGINT;
ALTER TABLE jobs ADD COLUMN webhook_done BOOLEAN NOT NULL DEFAULT FALSE;
CREATE INDEX jobs_with_webhooks_to_send ON jobs (webhook_next_at)
    WHERE webhook_url IS NOT NULL AND NOT webhook_done;
-- Progress events of each job (as its run reported them), read back by
-- GET /v1/jobs/{id}/progress?from=N.
CREATE TABLE job_events (
    job_id TEXT NOT NULL,
    seq BIGINT NOT NULL,
    event TEXT NOT NULL,
    PRIMARY KEY (job_id, seq)
);
-- Resumable uploads (api/src/uploads.rs): what each declared, where it stands, and its parts.
CREATE TABLE uploads (
    id TEXT PRIMARY KEY,
    account TEXT,
    size BIGINT NOT NULL,
    part_size BIGINT NOT NULL,
    sha256 TEXT,
    state TEXT NOT NULL,
    lease_until BIGINT,
    capture_id TEXT,
    error_code TEXT,
    error TEXT,
    created_at BIGINT NOT NULL,
    updated_at BIGINT NOT NULL
);
CREATE INDEX uploads_by_update ON uploads (updated_at);
CREATE TABLE upload_parts (
    upload_id TEXT NOT NULL REFERENCES uploads (id) ON DELETE CASCADE,
    idx INTEGER NOT NULL,
    size BIGINT NOT NULL,
    sha256 TEXT NOT NULL,
    PRIMARY KEY (upload_id, idx)
);
-- Fair sharing (api/src/quotas.rs): queued jobs of higher priority are claimed first, then the
-- oldest; a job's own time limit, seconds (NULL: the server's).
ALTER TABLE jobs ADD COLUMN priority INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN max_runtime_s BIGINT;
CREATE INDEX jobs_by_claim_order ON jobs (state, priority DESC, created_at);
