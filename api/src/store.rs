//! Durable records of captures and jobs, and the job queue itself. [`Store`] is the seam (a
//! PostgreSQL store can implement it later); [`SqliteStore`] is the embedded default: one SQLite
//! file in WAL mode behind a mutex (every statement is short, so callers may hold it briefly from
//! async code).
//!
//! Queue protocol: a worker claims the oldest `queued` job with one `UPDATE ... RETURNING`, which
//! writes its owner token and a lease deadline. While it runs, heartbeats (carrying progress)
//! extend the lease; every write by a worker is conditional on still owning the job, so a worker
//! whose lease was taken over can never finish or overwrite a job another worker now runs. Jobs
//! whose lease expired (their process died) are put back to `queued` by [`Store::requeue_expired`].

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Mutex;

use phygap::config::TrainConfig;
use rusqlite::{params, Connection, OptionalExtension, Row};
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Failures of the store.
#[derive(Debug, Error)]
pub enum StoreError {
    #[error("sqlite: {0}")]
    Sqlite(#[from] rusqlite::Error),
    #[error("corrupt `{column}` of job `{id}`: {problem}")]
    Corrupt {
        id: String,
        column: &'static str,
        problem: String,
    },
    #[error("job `{0}` is no longer owned by this worker (its lease expired and was taken over)")]
    LeaseLost(String),
    #[error("idempotency key `{0}` was already used for a different request")]
    IdempotencyConflict(String),
    #[error("the store's lock was poisoned by a panic")]
    Poisoned,
}

/// Life cycle of a job: `queued → running → succeeded | failed | cancelled`; `running → queued`
/// when interrupted by a shutdown or a crash.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JobState {
    Queued,
    Running,
    Succeeded,
    Failed,
    Cancelled,
}

impl JobState {
    pub fn as_str(self) -> &'static str {
        match self {
            JobState::Queued => "queued",
            JobState::Running => "running",
            JobState::Succeeded => "succeeded",
            JobState::Failed => "failed",
            JobState::Cancelled => "cancelled",
        }
    }

    fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "queued" => JobState::Queued,
            "running" => JobState::Running,
            "succeeded" => JobState::Succeeded,
            "failed" => JobState::Failed,
            "cancelled" => JobState::Cancelled,
            _ => return None,
        })
    }

    /// True once the job will never change again.
    pub fn is_terminal(self) -> bool {
        matches!(
            self,
            JobState::Succeeded | JobState::Failed | JobState::Cancelled
        )
    }
}

/// What a job does.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum JobSpec {
    /// Train a model of `capture_id`, then export its artifacts.
    Train { config: TrainConfig },
    /// Relight the model trained by `parent_job_id` under an uploaded environment map (stored in
    /// the job's input folder as `envmap.exr`/`envmap.hdr`, optional `cameras.json`).
    Relight {
        parent_job_id: String,
        envmap_file: String,
        cameras_file: Option<String>,
        rotate_deg: f64,
    },
}

impl JobSpec {
    pub fn kind(&self) -> &'static str {
        match self {
            JobSpec::Train { .. } => "train",
            JobSpec::Relight { .. } => "relight",
        }
    }
}

/// An accepted capture.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaptureRecord {
    pub id: String,
    pub views: usize,
    pub kinds: Vec<String>,
    pub warnings: Vec<String>,
    pub size_bytes: u64,
    /// Unix milliseconds.
    pub created_at: i64,
}

/// Live progress of a running job, written by heartbeats.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Progress {
    pub stage: Option<String>,
    pub iteration: u32,
    pub iterations: u32,
    pub losses: BTreeMap<String, f64>,
    pub test_psnr: Option<f64>,
    pub eta_seconds: Option<f64>,
    /// Last iteration a checkpoint was written at.
    pub checkpoint_iteration: Option<u32>,
    /// Iteration the latest run resumed from (after a restart or crash).
    pub resumed_from: Option<u32>,
    /// The compute backend the latest run trains on (absent in rows written before it existed).
    #[serde(default)]
    pub backend: Option<String>,
    /// The run's latest warning (e.g. a GridMap mesh that could not be extracted), if any.
    #[serde(default)]
    pub warning: Option<String>,
}

/// A job as stored.
#[derive(Clone, Debug, PartialEq)]
pub struct JobRecord {
    pub id: String,
    pub capture_id: String,
    pub spec: JobSpec,
    pub state: JobState,
    pub progress: Progress,
    pub error: Option<String>,
    /// Unix milliseconds.
    pub created_at: i64,
    pub started_at: Option<i64>,
    pub finished_at: Option<i64>,
    /// How many times a worker claimed it (more than one: it was resumed).
    pub attempts: u32,
    pub cancel_requested: bool,
}

/// A job to enqueue.
#[derive(Clone, Debug, PartialEq)]
pub struct NewJob {
    pub id: String,
    pub capture_id: String,
    pub spec: JobSpec,
    pub iterations: u32,
    pub created_at: i64,
}

/// How a worker's run of a job ended.
#[derive(Clone, Debug, PartialEq)]
pub enum Finish {
    Succeeded,
    Failed(String),
    Cancelled,
    /// Back to the queue (graceful shutdown): the next claim resumes from the checkpoint.
    Requeue,
}

/// Result of deleting a capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeleteOutcome {
    Deleted,
    NotFound,
    /// Jobs that are queued or running still need it.
    InUse,
}

/// Number of jobs per live state (for /metrics).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueueCounts {
    pub queued: u64,
    pub running: u64,
}

/// Durable captures, jobs and queue. All methods are short and blocking.
pub trait Store: Send + Sync + 'static {
    fn ping(&self) -> Result<(), StoreError>;
    fn insert_capture(&self, capture: &CaptureRecord) -> Result<(), StoreError>;
    fn capture(&self, id: &str) -> Result<Option<CaptureRecord>, StoreError>;
    fn capture_ids(&self) -> Result<Vec<String>, StoreError>;
    /// Deletes the capture's record unless a queued or running job uses it (checked atomically).
    fn delete_capture(&self, id: &str) -> Result<DeleteOutcome, StoreError>;
    /// Enqueues `job`. With an idempotency key (and the hash of the request it came with), a key
    /// seen before returns the job it created then (`false`: not new), or
    /// [`StoreError::IdempotencyConflict`] if the request differed.
    fn submit(
        &self,
        job: &NewJob,
        idempotency: Option<(&str, &str)>,
    ) -> Result<(JobRecord, bool), StoreError>;
    fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError>;
    /// Newest first.
    fn list_jobs(&self, limit: usize) -> Result<Vec<JobRecord>, StoreError>;
    /// Atomically takes the oldest queued job for `owner` until `lease_until` (unix ms).
    fn claim(
        &self,
        owner: &str,
        now: i64,
        lease_until: i64,
    ) -> Result<Option<JobRecord>, StoreError>;
    /// Writes progress and extends the lease; returns whether a cancel was requested.
    fn heartbeat(
        &self,
        id: &str,
        owner: &str,
        progress: &Progress,
        lease_until: i64,
    ) -> Result<bool, StoreError>;
    /// Ends the owner's run of the job.
    fn finish(&self, id: &str, owner: &str, finish: &Finish, now: i64) -> Result<(), StoreError>;
    /// Queued jobs are cancelled at once; running ones get `cancel_requested`. `None`: no such job.
    fn request_cancel(&self, id: &str, now: i64) -> Result<Option<JobRecord>, StoreError>;
    /// Puts running jobs whose lease ended before `now` back in the queue (or fails them after
    /// `max_attempts` claims); returns their ids.
    fn requeue_expired(&self, now: i64, max_attempts: u32) -> Result<Vec<String>, StoreError>;
    fn counts(&self) -> Result<QueueCounts, StoreError>;
}

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
    created_at INTEGER NOT NULL
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
    idempotency_key TEXT UNIQUE,
    request_hash TEXT
);
CREATE INDEX IF NOT EXISTS jobs_by_state ON jobs(state, created_at);
CREATE INDEX IF NOT EXISTS jobs_by_capture ON jobs(capture_id, state);
";

const JOB_COLUMNS: &str = "id, capture_id, spec, state, progress, error, created_at, started_at, \
                           finished_at, attempts, cancel_requested";

fn corrupt(id: &str, column: &'static str, problem: impl ToString) -> StoreError {
    StoreError::Corrupt {
        id: id.to_owned(),
        column,
        problem: problem.to_string(),
    }
}

/// A row as read, before its JSON columns are parsed.
struct RawJob {
    id: String,
    capture_id: String,
    spec: String,
    state: String,
    progress: String,
    error: Option<String>,
    created_at: i64,
    started_at: Option<i64>,
    finished_at: Option<i64>,
    attempts: u32,
    cancel_requested: bool,
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
    })
}

impl RawJob {
    fn parse(self) -> Result<JobRecord, StoreError> {
        let spec = serde_json::from_str(&self.spec).map_err(|e| corrupt(&self.id, "spec", e))?;
        let progress =
            serde_json::from_str(&self.progress).map_err(|e| corrupt(&self.id, "progress", e))?;
        let state = JobState::parse(&self.state)
            .ok_or_else(|| corrupt(&self.id, "state", format!("unknown state {:?}", self.state)))?;
        Ok(JobRecord {
            id: self.id,
            capture_id: self.capture_id,
            spec,
            state,
            progress,
            error: self.error,
            created_at: self.created_at,
            started_at: self.started_at,
            finished_at: self.finished_at,
            attempts: self.attempts,
            cancel_requested: self.cancel_requested,
        })
    }
}

fn to_json<T: Serialize>(value: &T) -> String {
    // Serializing these plain structs cannot fail (no maps with non-string keys).
    serde_json::to_string(value).unwrap_or_else(|_| "null".into())
}

impl SqliteStore {
    /// Opens (creating if needed) the database file.
    pub fn open(path: &Path) -> Result<Self, StoreError> {
        let conn = Connection::open(path)?;
        conn.busy_timeout(std::time::Duration::from_secs(10))?;
        conn.pragma_update(None, "journal_mode", "WAL")?;
        conn.pragma_update(None, "synchronous", "NORMAL")?;
        conn.execute_batch(SCHEMA)?;
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

    fn job_in(conn: &Connection, id: &str) -> Result<Option<JobRecord>, StoreError> {
        let sql = format!("SELECT {JOB_COLUMNS} FROM jobs WHERE id = ?1");
        conn.query_row(&sql, params![id], raw_job)
            .optional()?
            .map(RawJob::parse)
            .transpose()
    }
}

fn capture_row(row: &Row<'_>) -> rusqlite::Result<(String, i64, String, String, i64, i64)> {
    Ok((
        row.get(0)?,
        row.get(1)?,
        row.get(2)?,
        row.get(3)?,
        row.get(4)?,
        row.get(5)?,
    ))
}

impl Store for SqliteStore {
    fn ping(&self) -> Result<(), StoreError> {
        self.with(|c| {
            Ok(c.query_row("SELECT 1", [], |r| r.get::<_, i64>(0))
                .map(|_| ())?)
        })
    }

    fn insert_capture(&self, capture: &CaptureRecord) -> Result<(), StoreError> {
        self.with(|c| {
            c.execute(
                "INSERT INTO captures (id, views, kinds, warnings, size_bytes, created_at)
                 VALUES (?1, ?2, ?3, ?4, ?5, ?6)",
                params![
                    capture.id,
                    capture.views as i64,
                    to_json(&capture.kinds),
                    to_json(&capture.warnings),
                    capture.size_bytes as i64,
                    capture.created_at
                ],
            )?;
            Ok(())
        })
    }

    fn capture(&self, id: &str) -> Result<Option<CaptureRecord>, StoreError> {
        let row = self.with(|c| {
            Ok(c.query_row(
                "SELECT id, views, kinds, warnings, size_bytes, created_at FROM captures WHERE id = ?1",
                params![id],
                capture_row,
            )
            .optional()?)
        })?;
        row.map(|(id, views, kinds, warnings, size, created_at)| {
            Ok(CaptureRecord {
                kinds: serde_json::from_str(&kinds).map_err(|e| corrupt(&id, "kinds", e))?,
                warnings: serde_json::from_str(&warnings)
                    .map_err(|e| corrupt(&id, "warnings", e))?,
                views: views.max(0) as usize,
                size_bytes: size.max(0) as u64,
                created_at,
                id,
            })
        })
        .transpose()
    }

    fn capture_ids(&self) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare("SELECT id FROM captures")?;
            let ids = stmt
                .query_map([], |r| r.get(0))?
                .collect::<Result<_, _>>()?;
            Ok(ids)
        })
    }

    fn delete_capture(&self, id: &str) -> Result<DeleteOutcome, StoreError> {
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

    fn submit(
        &self,
        job: &NewJob,
        idempotency: Option<(&str, &str)>,
    ) -> Result<(JobRecord, bool), StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            if let Some((key, hash)) = idempotency {
                let existing: Option<(String, Option<String>)> = tx
                    .query_row(
                        "SELECT id, request_hash FROM jobs WHERE idempotency_key = ?1",
                        params![key],
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
                                   idempotency_key, request_hash)
                 VALUES (?1, ?2, ?3, 'queued', ?4, ?5, ?6, ?7)",
                params![
                    job.id,
                    job.capture_id,
                    to_json(&job.spec),
                    to_json(&progress),
                    job.created_at,
                    idempotency.map(|(k, _)| k),
                    idempotency.map(|(_, h)| h),
                ],
            )?;
            let record = Self::job_in(&tx, &job.id)?
                .ok_or_else(|| corrupt(&job.id, "id", "inserted job not found"))?;
            tx.commit()?;
            Ok((record, true))
        })
    }

    fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError> {
        self.with(|c| Self::job_in(c, id))
    }

    fn list_jobs(&self, limit: usize) -> Result<Vec<JobRecord>, StoreError> {
        self.with(|c| {
            let sql = format!(
                "SELECT {JOB_COLUMNS} FROM jobs ORDER BY created_at DESC, rowid DESC LIMIT ?1"
            );
            let mut stmt = c.prepare(&sql)?;
            let raws = stmt
                .query_map(params![limit as i64], raw_job)?
                .collect::<Result<Vec<_>, _>>()?;
            raws.into_iter().map(RawJob::parse).collect()
        })
    }

    fn claim(
        &self,
        owner: &str,
        now: i64,
        lease_until: i64,
    ) -> Result<Option<JobRecord>, StoreError> {
        self.with(|c| {
            let sql = format!(
                "UPDATE jobs SET state = 'running', owner = ?1, lease_until = ?2,
                        started_at = COALESCE(started_at, ?3), attempts = attempts + 1
                 WHERE state = 'queued' AND id = (
                     SELECT id FROM jobs WHERE state = 'queued'
                     ORDER BY created_at, rowid LIMIT 1)
                 RETURNING {JOB_COLUMNS}"
            );
            c.query_row(&sql, params![owner, lease_until, now], raw_job)
                .optional()?
                .map(RawJob::parse)
                .transpose()
        })
    }

    fn heartbeat(
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

    fn finish(&self, id: &str, owner: &str, finish: &Finish, now: i64) -> Result<(), StoreError> {
        let (state, error, finished_at) = match finish {
            Finish::Succeeded => ("succeeded", None, Some(now)),
            Finish::Failed(message) => ("failed", Some(message.as_str()), Some(now)),
            Finish::Cancelled => ("cancelled", None, Some(now)),
            Finish::Requeue => ("queued", None, None),
        };
        self.with(|c| {
            let changed = c.execute(
                "UPDATE jobs SET state = ?1, error = ?2, finished_at = ?3, owner = NULL,
                        lease_until = NULL
                 WHERE id = ?4 AND owner = ?5 AND state = 'running'",
                params![state, error, finished_at, id, owner],
            )?;
            if changed == 0 {
                return Err(StoreError::LeaseLost(id.to_owned()));
            }
            Ok(())
        })
    }

    fn request_cancel(&self, id: &str, now: i64) -> Result<Option<JobRecord>, StoreError> {
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

    fn requeue_expired(&self, now: i64, max_attempts: u32) -> Result<Vec<String>, StoreError> {
        self.with(|c| {
            let tx = c.transaction()?;
            let failed_message = format!(
                "abandoned: the worker running it died {max_attempts} times (lease expired)"
            );
            let mut ids: Vec<String> = Vec::new();
            {
                let mut stmt = tx.prepare(
                    "UPDATE jobs SET state = CASE
                            WHEN cancel_requested = 1 THEN 'cancelled'
                            WHEN attempts >= ?2 THEN 'failed'
                            ELSE 'queued' END,
                        error = CASE WHEN cancel_requested = 0 AND attempts >= ?2 THEN ?3
                                     ELSE error END,
                        finished_at = CASE WHEN cancel_requested = 1 OR attempts >= ?2 THEN ?1
                                           ELSE finished_at END,
                        owner = NULL, lease_until = NULL
                     WHERE state = 'running' AND lease_until < ?1
                     RETURNING id",
                )?;
                let rows = stmt.query_map(params![now, max_attempts, failed_message], |r| {
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

    fn counts(&self) -> Result<QueueCounts, StoreError> {
        self.with(|c| {
            let mut stmt = c.prepare(
                "SELECT state, count(*) FROM jobs WHERE state IN ('queued', 'running') GROUP BY state",
            )?;
            let mut counts = QueueCounts::default();
            let rows = stmt.query_map([], |r| Ok((r.get::<_, String>(0)?, r.get::<_, i64>(1)?)))?;
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

/// Current time in unix milliseconds.
pub fn now_ms() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_millis() as i64)
        .unwrap_or(0)
}

/// Formats unix milliseconds as RFC 3339 UTC (`2026-03-01T12:00:00.123Z`).
pub fn rfc3339(ms: i64) -> String {
    let secs = ms.div_euclid(1000);
    let millis = ms.rem_euclid(1000);
    let days = secs.div_euclid(86_400);
    let second_of_day = secs.rem_euclid(86_400);
    // Civil date from days since 1970-01-01 (H. Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}.{millis:03}Z",
        second_of_day / 3600,
        second_of_day % 3600 / 60,
        second_of_day % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn store() -> (tempfile::TempDir, SqliteStore) {
        let dir = tempfile::tempdir().unwrap();
        let store = SqliteStore::open(&dir.path().join("db.sqlite3")).unwrap();
        (dir, store)
    }

    fn new_job(id: &str, created_at: i64) -> NewJob {
        NewJob {
            id: id.into(),
            capture_id: "cap_1".into(),
            spec: JobSpec::Train {
                config: TrainConfig::default(),
            },
            iterations: 100,
            created_at,
        }
    }

    #[test]
    fn rfc3339_matches_known_instants() {
        assert_eq!(rfc3339(0), "1970-01-01T00:00:00.000Z");
        assert_eq!(rfc3339(951_782_400_123), "2000-02-29T00:00:00.123Z");
        assert_eq!(rfc3339(1_767_225_599_999), "2025-12-31T23:59:59.999Z");
    }

    #[test]
    fn claim_is_exclusive_and_fifo() {
        let (_dir, s) = store();
        s.submit(&new_job("job_b", 2), None).unwrap();
        s.submit(&new_job("job_a", 1), None).unwrap();
        let first = s.claim("w1", 10, 1000).unwrap().unwrap();
        assert_eq!(first.id, "job_a");
        assert_eq!((first.state, first.attempts), (JobState::Running, 1));
        let second = s.claim("w2", 10, 1000).unwrap().unwrap();
        assert_eq!(second.id, "job_b");
        assert!(s.claim("w3", 10, 1000).unwrap().is_none());
        assert_eq!(
            s.counts().unwrap(),
            QueueCounts {
                queued: 0,
                running: 2
            }
        );
    }

    #[test]
    fn only_the_owner_can_heartbeat_and_finish() {
        let (_dir, s) = store();
        s.submit(&new_job("job_a", 1), None).unwrap();
        s.claim("w1", 10, 1000).unwrap().unwrap();
        let progress = Progress {
            iteration: 7,
            iterations: 100,
            ..Progress::default()
        };
        assert!(matches!(
            s.heartbeat("job_a", "intruder", &progress, 2000),
            Err(StoreError::LeaseLost(_))
        ));
        assert!(!s.heartbeat("job_a", "w1", &progress, 2000).unwrap());
        assert!(s
            .finish("job_a", "intruder", &Finish::Succeeded, 50)
            .is_err());
        s.finish("job_a", "w1", &Finish::Succeeded, 50).unwrap();
        let job = s.job("job_a").unwrap().unwrap();
        assert_eq!(job.state, JobState::Succeeded);
        assert_eq!(job.progress.iteration, 7);
        assert_eq!(job.finished_at, Some(50));
    }

    #[test]
    fn expired_leases_are_requeued_then_abandoned() {
        let (_dir, s) = store();
        s.submit(&new_job("job_a", 1), None).unwrap();
        s.claim("dead", 10, 100).unwrap().unwrap();
        assert!(
            s.requeue_expired(99, 3).unwrap().is_empty(),
            "lease still valid"
        );
        assert_eq!(
            s.requeue_expired(101, 3).unwrap(),
            vec!["job_a".to_string()]
        );
        assert_eq!(s.job("job_a").unwrap().unwrap().state, JobState::Queued);
        // The dead owner can no longer write.
        assert!(s.finish("job_a", "dead", &Finish::Succeeded, 5).is_err());
        for attempt in 2..=3 {
            let job = s.claim("w", 200, 300).unwrap().unwrap();
            assert_eq!(job.attempts, attempt);
            s.requeue_expired(301, 3).unwrap();
        }
        let job = s.job("job_a").unwrap().unwrap();
        assert_eq!(job.state, JobState::Failed);
        assert!(job.error.unwrap().contains("abandoned"));
    }

    #[test]
    fn idempotency_key_returns_the_same_job_or_conflicts() {
        let (_dir, s) = store();
        let (a, new_a) = s.submit(&new_job("job_a", 1), Some(("k1", "h1"))).unwrap();
        let (b, new_b) = s.submit(&new_job("job_b", 2), Some(("k1", "h1"))).unwrap();
        assert!(new_a && !new_b);
        assert_eq!(a.id, b.id);
        assert!(matches!(
            s.submit(&new_job("job_c", 3), Some(("k1", "other"))),
            Err(StoreError::IdempotencyConflict(_))
        ));
        assert_eq!(s.list_jobs(10).unwrap().len(), 1);
    }

    #[test]
    fn cancel_and_capture_deletion_respect_job_states() {
        let (_dir, s) = store();
        let capture = CaptureRecord {
            id: "cap_1".into(),
            views: 3,
            kinds: vec!["rgb".into()],
            warnings: vec![],
            size_bytes: 10,
            created_at: 0,
        };
        s.insert_capture(&capture).unwrap();
        assert_eq!(s.capture("cap_1").unwrap().unwrap(), capture);
        s.submit(&new_job("job_a", 1), None).unwrap();
        assert_eq!(s.delete_capture("cap_1").unwrap(), DeleteOutcome::InUse);
        let cancelled = s.request_cancel("job_a", 5).unwrap().unwrap();
        assert_eq!(cancelled.state, JobState::Cancelled);
        assert!(s.claim("w", 6, 100).unwrap().is_none());
        assert_eq!(s.delete_capture("cap_1").unwrap(), DeleteOutcome::Deleted);
        assert_eq!(s.delete_capture("cap_1").unwrap(), DeleteOutcome::NotFound);
        assert!(s.request_cancel("nope", 5).unwrap().is_none());
    }
}
