-- The account (per-token owner) of each capture and job; NULL for records made without an
-- account token.
ALTER TABLE captures ADD COLUMN account TEXT;
ALTER TABLE jobs ADD COLUMN account TEXT;
CREATE INDEX jobs_by_account ON jobs (account, created_at DESC, seq DESC);
