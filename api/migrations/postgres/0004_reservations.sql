-- Each stored copy of an upload's part is named by the request that stored it, so a request
-- refused after storing its copy removes only that copy (NULL: a part stored under its number
-- and digest alone, by an older release).
ALTER TABLE upload_parts ADD COLUMN copy_id TEXT;
-- Storage held for a capture or upload while its bytes arrive, written in the transaction that
-- checks the account's quota: `id` is the capture's or upload's id (once that is recorded, it
-- counts instead), `expires_at` when an abandoned reservation stops counting.
CREATE TABLE reservations (
    id TEXT PRIMARY KEY,
    account TEXT NOT NULL,
    bytes BIGINT NOT NULL,
    expires_at BIGINT NOT NULL
);
CREATE INDEX reservations_by_account ON reservations (account);
-- A place in an account's queue held for a job about to be submitted or restarted, written in
-- the transaction that checks `max_queued`; it counts until its job is in the queue.
CREATE TABLE queue_places (
    job_id TEXT PRIMARY KEY,
    account TEXT NOT NULL,
    expires_at BIGINT NOT NULL
);
