//! The embedded store: one SQLite file in WAL mode behind a mutex. Every statement is short, so
//! the async methods run them in place (holding the mutex for a few microseconds to milliseconds).

use std::path::Path;
use std::sync::Mutex;

use rusqlite::{params, Connection, OptionalExtension, Row, TransactionBehavior};

use super::{
    abandoned_message, corrupt, to_json, CaptureRecord, DeleteOutcome, Finish, JobRecord, JobSpec,
    NewJob, PartOutcome, Progress, QueueCounts, RawCapture, RawJob, RawUpload, Reserved, Store,
    StoreError, UploadEnd, UploadPart, UploadRecord, WebhookDelivery, ABANDONED, UPLOAD_COLUMNS,
};
use super::{AccountUsage, RunningLimits};

/// The embedded SQLite store.
pub struct SqliteStore {
    conn: Mutex<Connection>,
}

const SCHEMA: &str = "
CREATE TABLE IF NOT EXISTS captures (
    id TEXT PRIMARY KEY,
    views INTEGER NOT NULL,
    kinds TEXT NOT NULL,
    warnings TEXT NOT NULL,
    size_bytes INTEGER NOT NULL,
    created_at INTEGER NOT NULL,
    account TEXT
);
CREATE TABLE IF NOT EXISTS jobs (
    id TEXT PRIMARY KEY,
    capture_id TEXT NOT NULL,
    spec TEXT NOT NULL,
    state TEXT NOT NULL,
    progress TEXT NOT NULL,
    error TEXT,
    created_at INTEGER NOT NULL,
    started_at INTEGER,
    finished_at INTEGER,
    attempts INTEGER NOT NULL DEFAULT 0,
    cancel_requested INTEGER NOT NULL DEFAULT 0,
    owner TEXT,
    lease_until INTEGER,
    request_hash TEXT,
    account TEXT
);
CREATE INDEX IF NOT EXISTS jobs_by_state ON jobs(state, created_at);
CREATE TABLE IF NOT EXISTS job_events (
    job_id TEXT NOT NULL,
    seq INTEGER NOT NULL,
    event TEXT NOT NULL,
    PRIMARY KEY (job_id, seq)
);
CREATE INDEX IF NOT EXISTS jobs_by_capture ON jobs(capture_id, state);
CREATE TABLE IF NOT EXISTS uploads (
    id TEXT PRIMARY KEY,
    account TEXT,
    size INTEGER NOT NULL,
    part_size INTEGER NOT NULL,
    sha256 TEXT,
    state TEXT NOT NULL,
    lease_until INTEGER,
    capture_id TEXT,
    error_code TEXT,
    error TEXT,
    created_at INTEGER NOT NULL,
    updated_at INTEGER NOT NULL
);
CREATE INDEX IF NOT EXISTS uploads_by_update ON uploads(updated_at);
CREATE TABLE IF NOT EXISTS upload_parts (
    upload_id TEXT NOT NULL,
    idx INTEGER NOT NULL,
    size INTEGER NOT NULL,
    sha256 TEXT NOT NULL,
    PRIMARY KEY (upload_id, idx)
);
CREATE TABLE IF NOT EXISTS reservations (
    id TEXT PRIMARY KEY,
    account TEXT NOT NULL,
    bytes INTEGER NOT NULL,
    expires_at INTEGER NOT NULL
);
CREATE INDEX IF NOT EXISTS reservations_by_account ON reservations(account);
CREATE TABLE IF NOT EXISTS queue_places (
    job_id TEXT PRIMARY KEY,
    account TEXT NOT NULL,
    expires_at INTEGER NOT NULL
);
";

/// The jobs account `?1` has queued at `?2` (unix ms), with the live places reserved for jobs
/// not yet in the queue (a place whose job is queued, running or ended counts no more; a
/// failed or cancelled job's place is one for its restart).
const QUEUED_OR_PLACED: &str = "
    (SELECT COUNT(*) FROM jobs WHERE account = ?1 AND state = 'queued')
  + (SELECT COUNT(*) FROM queue_places q
     WHERE q.account = ?1 AND q.expires_at > ?2
       AND NOT EXISTS (SELECT 1 FROM jobs j
                       WHERE j.id = q.job_id AND j.state NOT IN ('failed', 'cancelled')))";

/// The bytes account `?1` stores at `?2` (unix ms): its captures, its open uploads, and its
/// reservations still live whose capture or upload is not recorded yet.
const STORED_BYTES: &str = "
    (SELECT COALESCE(SUM(size_bytes), 0) FROM captures WHERE account = ?1)
  + (SELECT COALESCE(SUM(size), 0) FROM uploads
     WHERE account = ?1 AND state IN ('open', 'committing'))
  + (SELECT COALESCE(SUM(r.bytes), 0) FROM reservations r
     WHERE r.account = ?1 AND r.expires_at > ?2
       AND NOT EXISTS (SELECT 1 FROM captures c WHERE c.id = r.id)
       AND NOT EXISTS (SELECT 1 FROM uploads u WHERE u.id = r.id))";

const JOB_COLUMNS: &str = "id, capture_id, spec, state, progress, error, created_at, started_at, \
                           finished_at, attempts, cancel_requested, account, error_code, \
                           last_death, webhook_url, webhook_attempts, webhook_status, \
                           webhook_done, priority, max_runtime_s";

/// Columns added after the first release, added to older files when they are opened.
/// `request_key` is the client's Idempotency-Key, unique per account (the first release kept
/// keys in `idempotency_key`, prefixed with the account's name, which two accounts could collide
/// on; that column is no longer written).
const ADDED_COLUMNS: &[(&str, &str)] = &[
    ("captures", "account TEXT"),
    ("jobs", "account TEXT"),
    ("jobs", "error_code TEXT"),
    ("jobs", "last_death TEXT"),
    ("jobs", "request_key TEXT"),
    ("captures", "width INTEGER NOT NULL DEFAULT 0"),
    ("captures", "height INTEGER NOT NULL DEFAULT 0"),
    ("jobs", "webhook_url TEXT"),
    ("jobs", "webhook_attempts INTEGER NOT NULL DEFAULT 0"),
    ("jobs", "webhook_status TEXT"),
    ("jobs", "webhook_next_at INTEGER"),
    ("jobs", "webhook_done INTEGER NOT NULL DEFAULT 0"),
    ("jobs", "priority INTEGER NOT NULL DEFAULT 0"),
    ("jobs", "max_runtime_s INTEGER"),
    ("upload_parts", "copy_id TEXT"),
];

/// Moves keys of files written by the first release into `request_key`, dropping the
/// `account/` prefix they were stored with.
const MIGRATE_LEGACY_KEYS: &str = "
UPDATE jobs SET request_key = CASE
        WHEN account IS NOT NULL AND substr(idempotency_key, 1, length(account) + 1) = account || '/'
        THEN substr(idempotency_key, length(account) + 2)
        ELSE idempotency_key END,
    idempotency_key = NULL
WHERE idempotency_key IS NOT NULL;
";

/// Keys are unique per account (the admin's, without an account, is one more scope); webhook
/// deliveries still to make are found by an index of their own.
const ADDED_INDEXES: &str = "
CREATE UNIQUE INDEX IF NOT EXISTS jobs_by_request_key
    ON jobs (COALESCE(account, ''), request_key) WHERE request_key IS NOT NULL;
CREATE INDEX IF NOT EXISTS jobs_by_claim_order ON jobs (state, priority DESC, created_at);
CREATE INDEX IF NOT EXISTS jobs_with_webhooks_to_send
    ON jobs (webhook_next_at) WHERE webhook_url IS NOT NULL AND webhook_done = 0;
";

fn has_column(conn: &Connection, table: &str, column: &str) -> rusqlite::Result<bool> {
    conn.query_row(
        &format!("SELECT count(*) > 0 FROM pragma_table_info('{table}') WHERE name = ?1"),
        params![column],
        |r| r.get(0),
    )
}

fn raw_job(row: &Row<'_>) -> rusqlite::Result<RawJob> {
    Ok(RawJob {
        id: row.get(0)?,
        capture_id: row.get(1)?,
        spec: row.get(2)?,
        state: row.get(3)?,
        progress: row.get(4)?,
        error: row.get(5)?,
        created_at: row.get(6)?,
        started_at: row.get(7)?,
        finished_at: row.get(8)?,
        attempts: row.get(9)?,
        cancel_requested: row.get(10)?,
        account: row.get(11)?,
        error_code: row.get(12)?,
        last_death: row.get(13)?,
        webhook_url: row.get(14)?,
        webhook_attempts: row.get(15)?,
        webhook_status: row.get(16)?,
        webhook_done: row.get(17)?,
        priority: row.get(18)?,
        max_runtime_seconds: row.get(19)?,
    })
}

/// A part as `SELECT idx, size, sha256, copy_id` reads it.
fn part_row(row: &Row<'_>) -> rusqlite::Result<UploadPart> {
    Ok(UploadPart {
        index: row.get(0)?,
        size: row.get::<_, i64>(1)?.max(0) as u64,
        sha256: row.get(2)?,
        copy: row.get(3)?,
    })
}

fn raw_upload(row: &Row<'_>) -> rusqlite::Result<RawUpload> {
    Ok(RawUpload {
        id: row.get(0)?,
        account: row.get(1)?,
        size: row.get(2)?,
        part_size: row.get(3)?,
        sha256: row.get(4)?,
        state: row.get(5)?,
        lease_until: row.get(6)?,
        capture_id: row.get(7)?,
        error_code: row.get(8)?,
        error: row.get(9)?,
        created_at: row.get(10)?,
        updated_at: row.get(11)?,
    })
}

impl SqliteStore {
    /// Opens (creating if needed) the database file.
    pub fn open(path: &Path) -> Result<Self, StoreError> {
        let conn = Connection::open(path)?;
        conn.busy_timeout(std::time::Duration::from_secs(10))?;
        conn.pragma_update(None, "journal_mode", "WAL")?;
        conn.pragma_update(None, "synchronous", "NORMAL")?;
        conn.execute_batch(SCHEMA)?;
        for (table, column) in ADDED_COLUMNS {
            let name = column.split_whitespace().next().unwrap_or(column);
            if !has_column(&conn, table, name)? {
                conn.execute_batch(&format!("ALTER TABLE {table} ADD COLUMN {column}"))?;
            }
        }
        if has_column(&conn, "jobs", "idempotency_key")? {
            conn.execute_batch(MIGRATE_LEGACY_KEYS)?;
        }
        conn.execute_batch(ADDED_INDEXES)?;
        Ok(SqliteStore {
            conn: Mutex::new(conn),
        })
    }

    fn with<T>(
        &self,
        f: impl FnOnce(&mut Connection) -> Result<T, StoreError>,
    ) -> Result<T, StoreError> {
        let mut conn = self.conn.lock().map_err(|_| StoreError::Poisoned)?;
        f(&mut conn)
    }

    fn upload_in(conn: &Connection, id: &str) -> Result<Option<UploadRecord>, StoreError> {
        let sql = format!("SELECT {UPLOAD_COLUMNS} FROM uploads WHERE id = ?1");
        let Some(raw) = conn.query_row(&sql, params![id], raw_upload).optional()? else {
            return Ok(None);
        };
        let mut stmt = conn.prepare(
            "SELECT idx, size, sha256, copy_id FROM upload_parts WHERE upload_id = ?1
             ORDER BY idx",
        )?;
        let parts = stmt
            .query_map(params![id], part_row)?
            .collect::<Result<Vec<_>, _>>()?;
        raw.parse(parts).map(Some)
    }

    fn job_in(conn: &Connection, id: &str) -> Result<Option<JobRecord>, StoreError> {
        let sql = format!("SELECT {JOB_COLUMNS} FROM jobs WHERE id = ?1");
        conn.query_row(&sql, params![id], raw_job)
            .optional()?
            .map(RawJob::parse)
            .transpose()
    }
}

/// The columns [`capture_row`] reads, in order.
const CAPTURE_COLUMNS: &str =
    "id, views, kinds, warnings, size_bytes, created_at, account, width, \
                               height";

fn capture_row(row: &Row<'_>) -> rusqlite::Result<RawCapture> {
    Ok(RawCapture {
        id: row.get(0)?,
        views: row.get(1)?,
        kinds: row.get(2)?,
        warnings: row.get(3)?,
        size_bytes: row.get(4)?,
        created_at: row.get(5)?,
        account: row.get(6)?,
        width: row.get(7)?,
        height: row.get(8)?,
    })
}

#[async_trait::async_trait]
impl Store for SqliteStore {
    async fn ping(&self) -> Result<(), StoreError> {
        self.with(|c| {
            Ok(c.query_row("SELECT 1", [], |r| r.get::<_, i64>(0))
                .map(|_| ())?)
        })
    }

    async fn insert_capture(&self, capture: &CaptureRecord) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "INSERT INTO captures (id, views, kinds, warnings, size_bytes, created_at, account,
                                       width, height)
                 VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)",
                params![
                    capture.id,
                    capture.views as i64,
                    to_json(&capture.kinds),
                    to_json(&capture.warnings),
                    capture.size_bytes as i64,
                    capture.created_at,
                    capture.account,
                    capture.width,
                    capture.height,
                ],
            )?;
            Ok(())
        })
    }

    async fn capture(&self, id: &str) -> Result<Option<CaptureRecord>, StoreError> {
        let row = self.with(|c| {
            Ok(c.query_row(
                &format!("SELECT {CAPTURE_COLUMNS} FROM captures WHERE id = ?1"),
                params![id],
                capture_row,
            )
            .optional()?)
        })?;
        row.map(RawCapture::parse).transpose()
    }

    async fn capture_ids(&self) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare("SELECT id FROM captures")?;
            let ids = stmt
                .query_map([], |r| r.get(0))?
                .collect::<Result<_, _>>()?;
            Ok(ids)
        })
    }

    async fn delete_capture(&self, id: &str) -> Result<DeleteOutcome, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            let exists: bool = tx
                .query_row("SELECT 1 FROM captures WHERE id = ?1", params![id], |_| {
                    Ok(true)
                })
                .optional()?
                .unwrap_or(false);
            if !exists {
                return Ok(DeleteOutcome::NotFound);
            }
            let active: i64 = tx.query_row(
                "SELECT count(*) FROM jobs WHERE capture_id = ?1 AND state IN ('queued', 'running')",
                params![id],
                |r| r.get(0),
            )?;
            if active > 0 {
                return Ok(DeleteOutcome::InUse);
            }
            tx.execute("DELETE FROM captures WHERE id = ?1", params![id])?;
            tx.commit()?;
            Ok(DeleteOutcome::Deleted)
        })
    }

    async fn submit(
        &self,
        job: &NewJob,
        idempotency: Option<(&str, &str)>,
    ) -> Result<(JobRecord, bool), StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            if let Some((key, hash)) = idempotency {
                let existing: Option<(String, Option<String>)> = tx
                    .query_row(
                        "SELECT id, request_hash FROM jobs WHERE request_key = ?1 AND account IS ?2",
                        params![key, job.account],
                        |r| Ok((r.get(0)?, r.get(1)?)),
                    )
                    .optional()?;
                if let Some((id, stored_hash)) = existing {
                    if stored_hash.as_deref() != Some(hash) {
                        return Err(StoreError::IdempotencyConflict(key.to_owned()));
                    }
                    let record = Self::job_in(&tx, &id)?.ok_or_else(|| {
                        corrupt(&id, "id", "idempotency key points to a missing job")
                    })?;
                    return Ok((record, false));
                }
            }
            let progress = Progress {
                iterations: job.iterations,
                ..Progress::default()
            };
            tx.execute(
                "INSERT INTO jobs (id, capture_id, spec, state, progress, created_at,
                                   request_key, request_hash, account, webhook_url, priority,
                                   max_runtime_s)
                 VALUES (?1, ?2, ?3, 'queued', ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)",
                params![
                    job.id,
                    job.capture_id,
                    to_json(&job.spec),
                    to_json(&progress),
                    job.created_at,
                    idempotency.map(|(k, _)| k),
                    idempotency.map(|(_, h)| h),
                    job.account,
                    job.webhook_url,
                    job.priority,
                    job.max_runtime_seconds.map(|s| s.min(i64::MAX as u64) as i64),
                ],
            )?;
            let record = Self::job_in(&tx, &job.id)?
                .ok_or_else(|| corrupt(&job.id, "id", "inserted job not found"))?;
            tx.commit()?;
            Ok((record, true))
        })
    }

    async fn has_request_key(&self, account: Option<&str>, key: &str) -> Result<bool, StoreError> {
        self.with(|c| {
            Ok(c.query_row(
                "SELECT EXISTS (SELECT 1 FROM jobs WHERE request_key = ?1 AND account IS ?2)",
                params![key, account],
                |r| r.get(0),
            )?)
        })
    }

    async fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError> {
        self.with(|c| Self::job_in(c, id))
    }

    async fn list_jobs(
        &self,
        limit: usize,
        account: Option<&str>,
    ) -> Result<Vec<JobRecord>, StoreError> {
        self.with(|c| {
            let sql = format!(
                "SELECT {JOB_COLUMNS} FROM jobs WHERE ?2 IS NULL OR account = ?2
                 ORDER BY created_at DESC, rowid DESC LIMIT ?1"
            );
            let mut stmt = c.prepare(&sql)?;
            let raws = stmt
                .query_map(params![limit as i64, account], raw_job)?
                .collect::<Result<Vec<_>, _>>()?;
            raws.into_iter().map(RawJob::parse).collect()
        })
    }

    async fn delete_job(&self, id: &str) -> Result<DeleteOutcome, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            let state: Option<String> = tx
                .query_row("SELECT state FROM jobs WHERE id = ?1", params![id], |r| {
                    r.get(0)
                })
                .optional()?;
            let Some(state) = state else {
                return Ok(DeleteOutcome::NotFound);
            };
            let needed: i64 = tx.query_row(
                "SELECT count(*) FROM jobs WHERE state IN ('queued', 'running')
                 AND json_extract(spec, '$.parent_job_id') = ?1",
                params![id],
                |r| r.get(0),
            )?;
            if matches!(state.as_str(), "queued" | "running") || needed > 0 {
                return Ok(DeleteOutcome::InUse);
            }
            tx.execute("DELETE FROM jobs WHERE id = ?1", params![id])?;
            tx.execute("DELETE FROM job_events WHERE job_id = ?1", params![id])?;
            tx.commit()?;
            Ok(DeleteOutcome::Deleted)
        })
    }

    async fn jobs_ended_before(&self, before: i64) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare(
                "SELECT id FROM jobs AS ended
                 WHERE state IN ('succeeded', 'failed', 'cancelled') AND finished_at < ?1
                 AND NOT EXISTS (SELECT 1 FROM jobs WHERE state IN ('queued', 'running')
                                 AND json_extract(spec, '$.parent_job_id') = ended.id)
                 ORDER BY finished_at",
            )?;
            let ids = stmt
                .query_map(params![before], |r| r.get(0))?
                .collect::<Result<_, _>>()?;
            Ok(ids)
        })
    }

    async fn unused_captures_before(&self, before: i64) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare(
                "SELECT id FROM captures WHERE created_at < ?1
                 AND NOT EXISTS (SELECT 1 FROM jobs WHERE jobs.capture_id = captures.id)
                 ORDER BY created_at",
            )?;
            let ids = stmt
                .query_map(params![before], |r| r.get(0))?
                .collect::<Result<_, _>>()?;
            Ok(ids)
        })
    }

    async fn claim_within(
        &self,
        owner: &str,
        now: i64,
        lease_until: i64,
        running: &RunningLimits,
    ) -> Result<Option<JobRecord>, StoreError> {
        self.with(|c| {
            // ?4: {"account": limit, …}; ?5: the limit of other accounts (NULL: none). Account
            // names are [A-Za-z0-9._-], so a quoted JSON path names them exactly.
            let sql = format!(
                "UPDATE jobs SET state = 'running', owner = ?1, lease_until = ?2,
                        started_at = COALESCE(started_at, ?3), attempts = attempts + 1
                 WHERE state = 'queued' AND id = (
                     SELECT id FROM (
                         SELECT id, priority, created_at, rowid AS r,
                                COALESCE(json_extract(?4, '$.\"' || account || '\"'), ?5) AS cap,
                                account
                         FROM jobs WHERE state = 'queued') AS q
                     WHERE q.account IS NULL OR q.cap IS NULL
                        OR (SELECT COUNT(*) FROM jobs AS busy
                            WHERE busy.state = 'running' AND busy.account = q.account) < q.cap
                     ORDER BY priority DESC, created_at, r LIMIT 1)
                 RETURNING {JOB_COLUMNS}"
            );
            let default = running.default.map(i64::from);
            let accounts = running.accounts_json();
            c.query_row(
                &sql,
                params![owner, lease_until, now, accounts, default],
                raw_job,
            )
            .optional()?
            .map(RawJob::parse)
            .transpose()
        })
    }

    async fn account_usage(&self, account: &str) -> Result<AccountUsage, StoreError> {
        self.with(|c| {
            Ok(c.query_row(
                &format!(
                    "SELECT
                    (SELECT COUNT(*) FROM jobs WHERE account = ?1 AND state = 'running'),
                    (SELECT COUNT(*) FROM jobs WHERE account = ?1 AND state = 'queued'),
                    {STORED_BYTES}"
                ),
                params![account, super::now_ms()],
                |r| {
                    Ok(AccountUsage {
                        running: r.get(0)?,
                        queued: r.get(1)?,
                        stored_bytes: r.get::<_, i64>(2)?.max(0) as u64,
                    })
                },
            )?)
        })
    }

    async fn heartbeat(
        &self,
        id: &str,
        owner: &str,
        progress: &Progress,
        lease_until: i64,
    ) -> Result<bool, StoreError> {
        self.with(|c| {
            c.query_row(
                "UPDATE jobs SET progress = ?1, lease_until = ?2
                 WHERE id = ?3 AND owner = ?4 AND state = 'running'
                 RETURNING cancel_requested",
                params![to_json(progress), lease_until, id, owner],
                |r| r.get::<_, bool>(0),
            )
            .optional()?
            .ok_or_else(|| StoreError::LeaseLost(id.to_owned()))
        })
    }

    async fn finish(
        &self,
        id: &str,
        owner: &str,
        finish: &Finish,
        now: i64,
    ) -> Result<(), StoreError> {
        let columns = finish.columns();
        let finished_at = columns.finished.then_some(now);
        self.with(|c| {
            // A death fails the job when its previous attempt died the same way, else requeues
            // it and remembers how it died; other endings are written as they are.
            let changed = c.execute(
                "UPDATE jobs SET
                    state = CASE WHEN ?5 IS NULL THEN ?1
                                 WHEN last_death IS ?5 THEN 'failed' ELSE 'queued' END,
                    error = CASE WHEN ?5 IS NULL OR last_death IS ?5 THEN ?2 ELSE error END,
                    error_code = CASE WHEN ?5 IS NULL OR last_death IS ?5 THEN ?3
                                      ELSE error_code END,
                    finished_at = CASE WHEN ?5 IS NULL THEN ?4
                                       WHEN last_death IS ?5 THEN ?6 ELSE NULL END,
                    last_death = COALESCE(?5, last_death),
                    owner = NULL, lease_until = NULL
                 WHERE id = ?7 AND owner = ?8 AND state = 'running'",
                params![
                    columns.state,
                    columns.error,
                    columns.error_code,
                    finished_at,
                    columns.death,
                    now,
                    id,
                    owner
                ],
            )?;
            if changed == 0 {
                return Err(StoreError::LeaseLost(id.to_owned()));
            }
            Ok(())
        })
    }

    async fn restart(
        &self,
        id: &str,
        spec: Option<&JobSpec>,
        fresh: Option<&Progress>,
    ) -> Result<Option<JobRecord>, StoreError> {
        let (spec, fresh) = (spec.map(to_json), fresh.map(to_json));
        self.with(|c| {
            let tx = c.transaction()?;
            tx.execute(
                "UPDATE jobs SET state = 'queued', error = NULL, error_code = NULL,
                        last_death = NULL, finished_at = NULL, cancel_requested = 0,
                        webhook_attempts = 0, webhook_status = NULL, webhook_next_at = NULL,
                        webhook_done = 0, spec = COALESCE(?2, spec),
                        attempts = CASE WHEN ?3 IS NULL THEN attempts ELSE 0 END,
                        progress = COALESCE(?3, progress)
                 WHERE id = ?1 AND state IN ('failed', 'cancelled')",
                params![id, spec, fresh],
            )?;
            let record = Self::job_in(&tx, id)?;
            tx.commit()?;
            Ok(record)
        })
    }

    async fn request_cancel(&self, id: &str, now: i64) -> Result<Option<JobRecord>, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            tx.execute(
                "UPDATE jobs SET state = 'cancelled', finished_at = ?2, cancel_requested = 1
                 WHERE id = ?1 AND state = 'queued'",
                params![id, now],
            )?;
            tx.execute(
                "UPDATE jobs SET cancel_requested = 1 WHERE id = ?1 AND state = 'running'",
                params![id],
            )?;
            let record = Self::job_in(&tx, id)?;
            tx.commit()?;
            Ok(record)
        })
    }

    async fn requeue_expired(
        &self,
        now: i64,
        max_attempts: u32,
    ) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            let failed_message = abandoned_message(max_attempts);
            let mut ids: Vec<String> = Vec::new();
            {
                let mut stmt = tx.prepare(
                    "UPDATE jobs SET state = CASE
                            WHEN cancel_requested = 1 THEN 'cancelled'
                            WHEN attempts >= ?2 THEN 'failed'
                            ELSE 'queued' END,
                        error = CASE WHEN cancel_requested = 0 AND attempts >= ?2 THEN ?3
                                     ELSE error END,
                        error_code = CASE WHEN cancel_requested = 0 AND attempts >= ?2 THEN ?4
                                          ELSE error_code END,
                        finished_at = CASE WHEN cancel_requested = 1 OR attempts >= ?2 THEN ?1
                                           ELSE finished_at END,
                        owner = NULL, lease_until = NULL
                     WHERE state = 'running' AND lease_until < ?1
                     RETURNING id",
                )?;
                let rows = stmt
                    .query_map(params![now, max_attempts, failed_message, ABANDONED], |r| {
                        r.get::<_, String>(0)
                    })?;
                for row in rows {
                    ids.push(row?);
                }
            }
            tx.commit()?;
            Ok(ids)
        })
    }

    async fn append_events(
        &self,
        id: &str,
        first_seq: u64,
        events: &[String],
    ) -> Result<(), StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            {
                let mut insert = tx.prepare_cached(
                    "INSERT OR REPLACE INTO job_events (job_id, seq, event) VALUES (?1, ?2, ?3)",
                )?;
                for (i, event) in events.iter().enumerate() {
                    insert.execute(params![id, (first_seq + i as u64) as i64, event])?;
                }
            }
            tx.commit()?;
            Ok(())
        })
    }

    async fn events(
        &self,
        id: &str,
        from: u64,
        limit: usize,
    ) -> Result<Vec<(u64, String)>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare_cached(
                "SELECT seq, event FROM job_events WHERE job_id = ?1 AND seq >= ?2
                 ORDER BY seq LIMIT ?3",
            )?;
            let rows = stmt
                .query_map(params![id, from as i64, limit as i64], |r| {
                    Ok((r.get::<_, i64>(0)?.max(0) as u64, r.get(1)?))
                })?
                .collect::<Result<_, _>>()?;
            Ok(rows)
        })
    }

    async fn next_event_seq(&self, id: &str) -> Result<u64, StoreError> {
        self.with(|c| {
            let next: i64 = c.query_row(
                "SELECT COALESCE(MAX(seq) + 1, 0) FROM job_events WHERE job_id = ?1",
                params![id],
                |r| r.get(0),
            )?;
            Ok(next.max(0) as u64)
        })
    }

    async fn take_webhook(
        &self,
        now: i64,
        lease_until: i64,
        busy_accounts: &[String],
    ) -> Result<Option<WebhookDelivery>, StoreError> {
        let busy = serde_json::to_string(busy_accounts).unwrap_or_else(|_| "[]".into());
        self.with(|c| {
            let sql = format!(
                "UPDATE jobs SET webhook_next_at = ?2
                 WHERE id = (
                     SELECT id FROM jobs
                     WHERE webhook_url IS NOT NULL AND webhook_done = 0
                       AND state IN ('succeeded', 'failed', 'cancelled')
                       AND COALESCE(webhook_next_at, 0) <= ?1
                       AND COALESCE(account, '') NOT IN (SELECT value FROM json_each(?3))
                     ORDER BY COALESCE(webhook_next_at, 0), finished_at LIMIT 1)
                 RETURNING {JOB_COLUMNS}"
            );
            let job = c
                .query_row(&sql, params![now, lease_until, busy], raw_job)
                .optional()?
                .map(RawJob::parse)
                .transpose()?;
            Ok(job.and_then(WebhookDelivery::of))
        })
    }

    async fn record_webhook(
        &self,
        id: &str,
        attempts: u32,
        status: &str,
        next_at: Option<i64>,
    ) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "UPDATE jobs SET webhook_attempts = ?2, webhook_status = ?3, webhook_next_at = ?4,
                        webhook_done = (?4 IS NULL)
                 WHERE id = ?1",
                params![id, attempts, status, next_at],
            )?;
            Ok(())
        })
    }

    async fn create_upload(&self, upload: &UploadRecord) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "INSERT INTO uploads (id, account, size, part_size, sha256, state, created_at,
                                      updated_at)
                 VALUES (?1, ?2, ?3, ?4, ?5, 'open', ?6, ?6)",
                params![
                    upload.id,
                    upload.account,
                    upload.size as i64,
                    upload.part_size as i64,
                    upload.sha256,
                    upload.created_at
                ],
            )?;
            Ok(())
        })
    }

    async fn upload(&self, id: &str) -> Result<Option<UploadRecord>, StoreError> {
        self.with(|c| Self::upload_in(c, id))
    }

    async fn record_part(
        &self,
        id: &str,
        part: &UploadPart,
        now: i64,
    ) -> Result<PartOutcome, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            let state: Option<String> = tx
                .query_row(
                    "SELECT state FROM uploads WHERE id = ?1",
                    params![id],
                    |r| r.get(0),
                )
                .optional()?;
            match state.as_deref() {
                None => return Ok(PartOutcome::NotFound),
                Some("open") => {}
                Some(_) => return Ok(PartOutcome::Closed),
            }
            let replaced = tx
                .query_row(
                    "SELECT idx, size, sha256, copy_id FROM upload_parts
                     WHERE upload_id = ?1 AND idx = ?2",
                    params![id, part.index],
                    part_row,
                )
                .optional()?;
            tx.execute(
                "INSERT INTO upload_parts (upload_id, idx, size, sha256, copy_id)
                 VALUES (?1, ?2, ?3, ?4, ?5)
                 ON CONFLICT (upload_id, idx) DO UPDATE SET size = ?3, sha256 = ?4, copy_id = ?5",
                params![id, part.index, part.size as i64, part.sha256, part.copy],
            )?;
            tx.execute(
                "UPDATE uploads SET updated_at = ?2 WHERE id = ?1",
                params![id, now],
            )?;
            tx.commit()?;
            Ok(PartOutcome::Recorded { replaced })
        })
    }

    async fn begin_commit(
        &self,
        id: &str,
        now: i64,
        until: i64,
    ) -> Result<Option<UploadRecord>, StoreError> {
        self.with(|c| {
            let taken = c.execute(
                "UPDATE uploads SET state = 'committing', lease_until = ?3, updated_at = ?2
                 WHERE id = ?1 AND (state = 'open' OR (state = 'committing' AND lease_until < ?2))",
                params![id, now, until],
            )?;
            if taken == 0 {
                return Ok(None);
            }
            Self::upload_in(c, id)
        })
    }

    async fn end_commit(&self, id: &str, end: &UploadEnd, now: i64) -> Result<(), StoreError> {
        let (state, capture_id, code, error) = end.columns();
        self.with(|c| {
            let tx = c.transaction()?;
            tx.execute(
                "UPDATE uploads SET state = ?2, capture_id = ?3, error_code = ?4, error = ?5,
                        lease_until = NULL, updated_at = ?6
                 WHERE id = ?1",
                params![id, state, capture_id, code, error, now],
            )?;
            if state != "open" {
                tx.execute("DELETE FROM upload_parts WHERE upload_id = ?1", params![id])?;
            }
            if let UploadEnd::PartsLost { indexes } = end {
                for index in indexes {
                    tx.execute(
                        "DELETE FROM upload_parts WHERE upload_id = ?1 AND idx = ?2",
                        params![id, index],
                    )?;
                }
            }
            tx.commit()?;
            Ok(())
        })
    }

    async fn delete_upload(&self, id: &str) -> Result<bool, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            tx.execute("DELETE FROM upload_parts WHERE upload_id = ?1", params![id])?;
            let deleted = tx.execute("DELETE FROM uploads WHERE id = ?1", params![id])?;
            tx.commit()?;
            Ok(deleted > 0)
        })
    }

    async fn uploads_idle_before(&self, before: i64) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare("SELECT id FROM uploads WHERE updated_at < ?1")?;
            let ids = stmt
                .query_map(params![before], |r| r.get(0))?
                .collect::<Result<Vec<String>, _>>()?;
            Ok(ids)
        })
    }

    async fn reserve_bytes(
        &self,
        account: &str,
        id: &str,
        bytes: u64,
        partial: bool,
        limit: u64,
        now: i64,
        until: i64,
    ) -> Result<Reserved, StoreError> {
        self.with(|c| {
            // IMMEDIATE: the write lock is taken before the check, so another process on the
            // same file cannot check between this check and this write.
            let tx = c.transaction_with_behavior(TransactionBehavior::Immediate)?;
            tx.execute(
                "DELETE FROM reservations WHERE account = ?1 AND id <> ?3
                 AND (expires_at <= ?2 OR id IN (SELECT id FROM captures)
                      OR id IN (SELECT id FROM uploads))",
                params![account, now, id],
            )?;
            let stored: i64 = tx.query_row(
                &format!("SELECT {STORED_BYTES}"),
                params![account, now],
                |r| r.get(0),
            )?;
            let stored = stored.max(0) as u64;
            let room = limit.saturating_sub(stored);
            let granted = match (bytes <= room, partial) {
                (true, _) => bytes,
                (false, true) => room,
                (false, false) => 0,
            };
            if granted > 0 {
                tx.execute(
                    "INSERT INTO reservations (id, account, bytes, expires_at) VALUES (?1, ?2, ?3, ?4)
                     ON CONFLICT (id) DO UPDATE
                     SET bytes = bytes + excluded.bytes, expires_at = excluded.expires_at",
                    params![id, account, granted.min(i64::MAX as u64) as i64, until],
                )?;
            }
            tx.commit()?;
            Ok(Reserved {
                granted,
                stored_bytes: stored,
            })
        })
    }

    async fn release_reservation(&self, id: &str) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute("DELETE FROM reservations WHERE id = ?1", params![id])?;
            Ok(())
        })
    }

    async fn reserve_queue_place(
        &self,
        account: &str,
        job_id: &str,
        max_queued: u32,
        now: i64,
        until: i64,
    ) -> Result<Result<(), u32>, StoreError> {
        self.with(|c| {
            let tx = c.transaction_with_behavior(TransactionBehavior::Immediate)?;
            tx.execute(
                "DELETE FROM queue_places WHERE account = ?1 AND expires_at <= ?2",
                params![account, now],
            )?;
            let held: i64 = tx.query_row(
                &format!("SELECT {QUEUED_OR_PLACED}"),
                params![account, now],
                |r| r.get(0),
            )?;
            let held = held.clamp(0, u32::MAX as i64) as u32;
            if held >= max_queued {
                return Ok(Err(held));
            }
            tx.execute(
                "INSERT INTO queue_places (job_id, account, expires_at) VALUES (?1, ?2, ?3)
                 ON CONFLICT (job_id) DO UPDATE SET expires_at = excluded.expires_at",
                params![job_id, account, until],
            )?;
            tx.commit()?;
            Ok(Ok(()))
        })
    }

    async fn release_queue_place(&self, job_id: &str) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "DELETE FROM queue_places WHERE job_id = ?1",
                params![job_id],
            )?;
            Ok(())
        })
    }

    async fn counts(&self, account: Option<&str>) -> Result<QueueCounts, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare(
                "SELECT state, count(*) FROM jobs WHERE state IN ('queued', 'running')
                 AND (?1 IS NULL OR account = ?1) GROUP BY state",
            )?;
            let mut counts = QueueCounts::default();
            let rows = stmt.query_map(params![account], |r| {
                Ok((r.get::<_, String>(0)?, r.get::<_, i64>(1)?))
            })?;
            for row in rows {
                let (state, n) = row?;
                match state.as_str() {
                    "queued" => counts.queued = n.max(0) as u64,
                    _ => counts.running = n.max(0) as u64,
                }
            }
            Ok(counts)
        })
    }
}
