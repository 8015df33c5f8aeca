//! Durable records of captures and jobs, and the job queue itself. [`Store`] is the seam between
//! the service and the database that holds them: [`SqliteStore`] is the embedded default (one
//! file beside the data), [`PostgresStore`] the shared one that API replicas and workers on many
//! machines use together. Both pass the same test-suite (`api/tests/store.rs`).
//!
//! Queue protocol: a worker claims the oldest `queued` job with one `UPDATE ... RETURNING`, which
//! writes its owner token and a lease deadline. While it runs, heartbeats (carrying progress)
//! extend the lease; every write by a worker is conditional on still owning the job, so a worker
//! whose lease was taken over can never finish or overwrite a job another worker now runs. Jobs
//! whose lease expired (their process died) are put back to `queued` by [`Store::requeue_expired`].

mod postgres;
mod sqlite;

pub use postgres::PostgresStore;
pub use sqlite::SqliteStore;

use std::collections::BTreeMap;

use phygap::core::config::TrainConfig;
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Failures of the store.
#[derive(Debug, Error)]
pub enum StoreError {
    #[error("sqlite: {0}")]
    Sqlite(#[from] rusqlite::Error),
    #[error("postgres: {0}")]
    Postgres(tokio_postgres::Error),
    #[error("invalid database URL: {0}")]
    InvalidUrl(String),
    /// The database cannot be reached (connection refused or lost, pool exhausted): the request
    /// may succeed later, and nothing stored was changed by it.
    #[error("the job database is unavailable: {0}")]
    Unavailable(String),
    #[error("the job database's schema: {0}")]
    Migration(String),
    #[error("corrupt `{column}` of job `{id}`: {problem}")]
    Corrupt {
        id: String,
        column: &'static str,
        problem: String,
    },
    #[error("job `{0}` is no longer owned by this worker (its lease expired and was taken over)")]
    LeaseLost(String),
    #[error("Idempotency-Key `{0}` was already used for a different request")]
    IdempotencyConflict(String),
    #[error("the store's lock was poisoned by a panic")]
    Poisoned,
}

/// Life cycle of a job: `queued → running → succeeded | failed | cancelled`; `running → queued`
/// when interrupted by a shutdown or a crash.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, utoipa::ToSchema)]
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
// A spec lives one per job record, read from and written to the store as JSON: a boxed training
// config would save a few hundred bytes per record in memory at the cost of every match on it.
#[allow(clippy::large_enum_variant)]
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
    /// The size of its views (0 × 0 for captures recorded before it was).
    pub width: u32,
    pub height: u32,
    pub kinds: Vec<String>,
    pub warnings: Vec<String>,
    pub size_bytes: u64,
    /// Unix milliseconds.
    pub created_at: i64,
    /// The account whose token uploaded it (`None`: uploaded without an account token).
    pub account: Option<String>,
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
    /// The size of the views the latest run trains on, e.g. `306×256 (1224×1024 ÷ 4)`.
    #[serde(default)]
    pub resolution: Option<String>,
    /// The latest run's peak resident memory so far, bytes (its process's; absent in rows
    /// written before it was reported).
    #[serde(default)]
    pub peak_rss_bytes: Option<u64>,
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
    /// Why it failed, as a stable name (`out_of_memory`, `time_limit`, `training_failed`, …).
    pub error_code: Option<String>,
    /// How its latest attempt's process died, when it did (`out_of_memory`, …): an attempt that
    /// dies the same way again fails the job instead of requeueing it.
    pub last_death: Option<String>,
    /// Unix milliseconds.
    pub created_at: i64,
    pub started_at: Option<i64>,
    pub finished_at: Option<i64>,
    /// How many times a worker claimed it (more than one: it was resumed).
    pub attempts: u32,
    pub cancel_requested: bool,
    /// The account whose token submitted it (`None`: submitted without an account token).
    pub account: Option<String>,
    /// Its webhook, when it has one.
    pub webhook: Option<WebhookRecord>,
    /// Queued jobs of higher priority are claimed first (then the oldest).
    pub priority: i32,
    /// Longest one attempt may run before the job fails `time_limit`; `None`: the server's.
    pub max_runtime_seconds: Option<u64>,
}

/// A job to enqueue.
#[derive(Clone, Debug, PartialEq)]
pub struct NewJob {
    pub id: String,
    pub capture_id: String,
    pub spec: JobSpec,
    pub iterations: u32,
    pub created_at: i64,
    pub account: Option<String>,
    /// Where to report the job's end ([`crate::jobs::webhooks`]).
    pub webhook_url: Option<String>,
    /// Claimed before queued jobs of lower priority.
    pub priority: i32,
    /// Its own time limit ([`JobRecord::max_runtime_seconds`]).
    pub max_runtime_seconds: Option<u64>,
}

/// How a job's end is being reported to its webhook.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize, utoipa::ToSchema)]
pub struct WebhookRecord {
    /// The URL the job's end is POSTed to.
    pub url: String,
    /// Attempts made.
    pub attempts: u32,
    /// How the last attempt went (`delivered: 200`, `answered 503`, `not delivered: cannot
    /// connect`, …); null before the first.
    #[schema(required = true)]
    pub last_status: Option<String>,
    /// Delivered, or given up: no more attempts.
    pub done: bool,
}

/// A delivery a process took to send: the job as it ended, the URL and the attempts so far.
#[derive(Clone, Debug, PartialEq)]
pub struct WebhookDelivery {
    pub job: JobRecord,
    pub url: String,
    pub attempts: u32,
}

impl WebhookDelivery {
    /// The delivery of a job taken for it (one with a webhook).
    pub(crate) fn of(job: JobRecord) -> Option<WebhookDelivery> {
        let webhook = job.webhook.clone()?;
        Some(WebhookDelivery {
            url: webhook.url,
            attempts: webhook.attempts,
            job,
        })
    }
}

/// How a worker's run of a job ended.
#[derive(Clone, Debug, PartialEq)]
pub enum Finish {
    Succeeded,
    /// The job failed: a stable `code` and a message for people.
    Failed {
        code: &'static str,
        message: String,
    },
    Cancelled,
    /// Back to the queue (graceful shutdown): the next claim resumes from the checkpoint.
    Requeue,
    /// The job's process died (`reason`: `out_of_memory`, `time_limit`, `killed`, `crashed`):
    /// back to the queue, or failed with that code when its previous attempt died the same way.
    Died {
        reason: &'static str,
        message: String,
    },
}

/// A resumable upload as stored ([`crate::http::upload_sessions`]): what it declared, where it
/// stands, and the parts received (ascending by number).
#[derive(Clone, Debug, PartialEq)]
pub struct UploadRecord {
    /// `upl_…`.
    pub id: String,
    pub account: Option<String>,
    /// The archive's size, bytes.
    pub size: u64,
    /// Bytes a part (the last may be shorter).
    pub part_size: u64,
    /// The whole archive's declared SHA-256 (lower-case hexadecimal).
    pub sha256: Option<String>,
    pub state: UploadState,
    pub parts: Vec<UploadPart>,
    /// Unix ms.
    pub created_at: i64,
    /// The last part or commit (unix ms): an upload idle for the expiry is removed.
    pub updated_at: i64,
}

/// Where an upload stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UploadState {
    /// Receiving parts.
    Open,
    /// A commit holds it until `until` (unix ms); after that another may take it over.
    Committing { until: i64 },
    /// It became this capture.
    Committed { capture_id: String },
    /// Its commit was refused with this answer.
    Failed { code: String, message: String },
}

/// One received part.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UploadPart {
    /// From 0.
    pub index: u32,
    pub size: u64,
    /// Lower-case hexadecimal SHA-256.
    pub sha256: String,
    /// The request that stored this copy of the part (part of its key, so no other request
    /// writes or removes it); `None` for a part an older release stored under its number and
    /// digest alone.
    pub copy: Option<String>,
}

/// What recording a part did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PartOutcome {
    /// Recorded; `replaced` is the part of that number recorded before, if any.
    Recorded {
        replaced: Option<UploadPart>,
    },
    /// The upload no longer takes parts (being committed, committed or failed).
    Closed,
    NotFound,
}

/// How a commit ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UploadEnd {
    Committed {
        capture_id: String,
    },
    Failed {
        code: String,
        message: String,
    },
    /// A failure of the service's own: open again, to be committed again.
    Reopened,
    /// Open again without these parts, whose stored copies could not be read back: the client
    /// sends them again.
    PartsLost {
        indexes: Vec<u32>,
    },
}

/// What a storage reservation ([`Store::reserve_bytes`]) found and granted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Reserved {
    /// Bytes added to the reservation by this call (0: refused).
    pub granted: u64,
    /// What the account stored before the call: captures, open uploads and live reservations
    /// (this one's earlier grants included).
    pub stored_bytes: u64,
}

/// Result of deleting a capture or a job.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeleteOutcome {
    Deleted,
    NotFound,
    /// Queued or running: the job itself, or jobs that need the capture or the job's model.
    InUse,
}

/// Number of jobs per live state (for /metrics).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QueueCounts {
    pub queued: u64,
    pub running: u64,
}

/// Durable captures, jobs and queue. Every method is one short transaction.
#[async_trait::async_trait]
pub trait Store: Send + Sync + 'static {
    async fn ping(&self) -> Result<(), StoreError>;
    async fn insert_capture(&self, capture: &CaptureRecord) -> Result<(), StoreError>;
    async fn capture(&self, id: &str) -> Result<Option<CaptureRecord>, StoreError>;
    async fn capture_ids(&self) -> Result<Vec<String>, StoreError>;
    /// Deletes the capture's record unless a queued or running job uses it (checked atomically).
    async fn delete_capture(&self, id: &str) -> Result<DeleteOutcome, StoreError>;
    /// Enqueues `job`. With an idempotency key (and the hash of the request it came with), a key
    /// the same account used before returns the job it created then (`false`: not new), or
    /// [`StoreError::IdempotencyConflict`] if the request differed. Keys are per account: equal
    /// keys of different accounts (or of the admin) are different keys.
    async fn submit(
        &self,
        job: &NewJob,
        idempotency: Option<(&str, &str)>,
    ) -> Result<(JobRecord, bool), StoreError>;
    async fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError>;
    /// Whether `account` (`None`: the admin) submitted a job with this Idempotency-Key.
    async fn has_request_key(&self, account: Option<&str>, key: &str) -> Result<bool, StoreError>;
    /// Newest first; only `account`'s jobs when one is given.
    async fn list_jobs(
        &self,
        limit: usize,
        account: Option<&str>,
    ) -> Result<Vec<JobRecord>, StoreError>;
    /// Deletes a job's record unless it is queued or running, or a queued or running relight
    /// job uses its model (checked atomically).
    async fn delete_job(&self, id: &str) -> Result<DeleteOutcome, StoreError>;
    /// Jobs that ended before `before` (unix ms) and that no queued or running job needs.
    async fn jobs_ended_before(&self, before: i64) -> Result<Vec<String>, StoreError>;
    /// Captures uploaded before `before` (unix ms) that no job uses.
    async fn unused_captures_before(&self, before: i64) -> Result<Vec<String>, StoreError>;
    /// Atomically takes a queued job for `owner` until `lease_until` (unix ms): the highest
    /// priority, then the oldest, of the accounts running fewer jobs than `running` allows them.
    /// Claims under limits from several processes take turns, so the limits hold across them.
    async fn claim_within(
        &self,
        owner: &str,
        now: i64,
        lease_until: i64,
        running: &RunningLimits,
    ) -> Result<Option<JobRecord>, StoreError>;
    /// [`Store::claim_within`] with no account limited.
    async fn claim(
        &self,
        owner: &str,
        now: i64,
        lease_until: i64,
    ) -> Result<Option<JobRecord>, StoreError> {
        self.claim_within(owner, now, lease_until, &RunningLimits::default())
            .await
    }
    /// What `account` holds: its running and queued jobs, and the bytes of its captures, open
    /// uploads and live storage reservations ([`Store::reserve_bytes`]).
    async fn account_usage(&self, account: &str) -> Result<AccountUsage, StoreError>;
    /// Writes progress and extends the lease; returns whether a cancel was requested.
    async fn heartbeat(
        &self,
        id: &str,
        owner: &str,
        progress: &Progress,
        lease_until: i64,
    ) -> Result<bool, StoreError>;
    /// Ends the owner's run of the job.
    async fn finish(
        &self,
        id: &str,
        owner: &str,
        finish: &Finish,
        now: i64,
    ) -> Result<(), StoreError>;
    /// Puts a failed or cancelled job back in the queue as a new run: its error, death and cancel
    /// request cleared, its spec replaced by `spec` when given. With `fresh` progress the run
    /// starts over (that progress, attempts counted from 0, so the next claim does not resume);
    /// without, it resumes from the job's last checkpoint. `None`: no such job; `Some(job)` in
    /// a state other than `queued`: it was not failed or cancelled, and is unchanged.
    async fn restart(
        &self,
        id: &str,
        spec: Option<&JobSpec>,
        fresh: Option<&Progress>,
    ) -> Result<Option<JobRecord>, StoreError>;
    /// Queued jobs are cancelled at once; running ones get `cancel_requested`. `None`: no such job.
    async fn request_cancel(&self, id: &str, now: i64) -> Result<Option<JobRecord>, StoreError>;
    /// Puts running jobs whose lease ended before `now` back in the queue (or fails them after
    /// `max_attempts` claims); returns their ids.
    async fn requeue_expired(&self, now: i64, max_attempts: u32)
        -> Result<Vec<String>, StoreError>;
    /// Queued and running jobs, of `account` only when one is given.
    async fn counts(&self, account: Option<&str>) -> Result<QueueCounts, StoreError>;
    /// Appends a job's progress events (JSON objects) numbered from `first_seq`.
    async fn append_events(
        &self,
        id: &str,
        first_seq: u64,
        events: &[String],
    ) -> Result<(), StoreError>;
    /// A job's recorded progress events from number `from`, at most `limit`, in order, as
    /// (number, JSON object).
    async fn events(
        &self,
        id: &str,
        from: u64,
        limit: usize,
    ) -> Result<Vec<(u64, String)>, StoreError>;
    /// The number the job's next progress event gets (one past the last recorded).
    async fn next_event_seq(&self, id: &str) -> Result<u64, StoreError>;
    /// Takes the oldest webhook delivery due at `now` (a job that ended, with a webhook not yet
    /// delivered or given up, whose next attempt is due) for the caller until `lease_until`,
    /// passing over the jobs of `busy_accounts` (`""`: jobs without an account).
    async fn take_webhook(
        &self,
        now: i64,
        lease_until: i64,
        busy_accounts: &[String],
    ) -> Result<Option<WebhookDelivery>, StoreError>;
    /// Records attempt number `attempts` of a job's webhook: its status, and when the next is
    /// due (`None`: no more, it was delivered or given up).
    async fn record_webhook(
        &self,
        id: &str,
        attempts: u32,
        status: &str,
        next_at: Option<i64>,
    ) -> Result<(), StoreError>;
    /// Records a new upload (open, without parts).
    async fn create_upload(&self, upload: &UploadRecord) -> Result<(), StoreError>;
    /// An upload with its parts.
    async fn upload(&self, id: &str) -> Result<Option<UploadRecord>, StoreError>;
    /// Records a received part of an open upload (replacing one of the same number) and marks
    /// the upload touched at `now`.
    async fn record_part(
        &self,
        id: &str,
        part: &UploadPart,
        now: i64,
    ) -> Result<PartOutcome, StoreError>;
    /// Takes an open upload (or one whose commit lease ended before `now`) for a commit until
    /// `until`; `None` when it is not open or another commit holds it.
    async fn begin_commit(
        &self,
        id: &str,
        now: i64,
        until: i64,
    ) -> Result<Option<UploadRecord>, StoreError>;
    /// Settles a commit: committed or failed (its parts forgotten), or open again.
    async fn end_commit(&self, id: &str, end: &UploadEnd, now: i64) -> Result<(), StoreError>;
    /// Deletes an upload's record and parts' records; whether there was one.
    async fn delete_upload(&self, id: &str) -> Result<bool, StoreError>;
    /// Uploads last touched before `before` (unix ms), in any state.
    async fn uploads_idle_before(&self, before: i64) -> Result<Vec<String>, StoreError>;
    /// Reserves storage for `account` under `id` (the id of the capture or upload the bytes
    /// are for), checking its stored bytes against `limit` in the same transaction as the
    /// reservation is written, so concurrent requests, from any process, cannot pass the limit
    /// together. Grants `bytes` more when they fit; when they do not, what still fits if
    /// `partial`, else nothing. A reservation adds to the account's stored bytes until `until`
    /// (unix ms, renewed by each grant) or until a capture or upload with its id is recorded
    /// (which then counts instead); [`Store::release_reservation`] removes it.
    #[allow(clippy::too_many_arguments)]
    async fn reserve_bytes(
        &self,
        account: &str,
        id: &str,
        bytes: u64,
        partial: bool,
        limit: u64,
        now: i64,
        until: i64,
    ) -> Result<Reserved, StoreError>;
    /// Removes a reservation (whether or not its capture or upload was recorded).
    async fn release_reservation(&self, id: &str) -> Result<(), StoreError>;
    /// Reserves a place in `account`'s queue for job `job_id` (about to be submitted, or
    /// restarted) when its queued jobs and live places number fewer than `max_queued`, checked
    /// in the transaction that writes the place; `Err(n)`: refused, the account holds `n`. A
    /// place counts until `until` (unix ms), or until its job is in the queue (or past it);
    /// [`Store::release_queue_place`] removes it.
    async fn reserve_queue_place(
        &self,
        account: &str,
        job_id: &str,
        max_queued: u32,
        now: i64,
        until: i64,
    ) -> Result<Result<(), u32>, StoreError>;
    /// Removes a queue place (whether or not its job was submitted).
    async fn release_queue_place(&self, job_id: &str) -> Result<(), StoreError>;
}

pub(crate) fn corrupt(id: &str, column: &'static str, problem: impl ToString) -> StoreError {
    StoreError::Corrupt {
        id: id.to_owned(),
        column,
        problem: problem.to_string(),
    }
}

/// A row as read, before its JSON columns are parsed.
pub(crate) struct RawJob {
    pub id: String,
    pub capture_id: String,
    pub spec: String,
    pub state: String,
    pub progress: String,
    pub error: Option<String>,
    pub created_at: i64,
    pub started_at: Option<i64>,
    pub finished_at: Option<i64>,
    pub attempts: u32,
    pub cancel_requested: bool,
    pub account: Option<String>,
    pub error_code: Option<String>,
    pub last_death: Option<String>,
    pub webhook_url: Option<String>,
    pub webhook_attempts: u32,
    pub webhook_status: Option<String>,
    pub webhook_done: bool,
    pub priority: i32,
    pub max_runtime_seconds: Option<i64>,
}

impl RawJob {
    pub fn parse(self) -> Result<JobRecord, StoreError> {
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
            error_code: self.error_code,
            last_death: self.last_death,
            webhook: self.webhook_url.map(|url| WebhookRecord {
                url,
                attempts: self.webhook_attempts,
                last_status: self.webhook_status,
                done: self.webhook_done,
            }),
            created_at: self.created_at,
            started_at: self.started_at,
            finished_at: self.finished_at,
            attempts: self.attempts,
            cancel_requested: self.cancel_requested,
            account: self.account,
            priority: self.priority,
            max_runtime_seconds: self.max_runtime_seconds.and_then(|s| u64::try_from(s).ok()),
        })
    }
}

pub(crate) fn to_json<T: Serialize>(value: &T) -> String {
    // Serializing these plain structs cannot fail (no maps with non-string keys).
    serde_json::to_string(value).unwrap_or_else(|_| "null".into())
}

/// A capture row as read, before its JSON columns are parsed.
pub(crate) struct RawCapture {
    pub id: String,
    pub views: i64,
    pub width: i64,
    pub height: i64,
    pub kinds: String,
    pub warnings: String,
    pub size_bytes: i64,
    pub created_at: i64,
    pub account: Option<String>,
}

impl RawCapture {
    pub fn parse(self) -> Result<CaptureRecord, StoreError> {
        let id = self.id;
        Ok(CaptureRecord {
            kinds: serde_json::from_str(&self.kinds).map_err(|e| corrupt(&id, "kinds", e))?,
            warnings: serde_json::from_str(&self.warnings)
                .map_err(|e| corrupt(&id, "warnings", e))?,
            views: self.views.max(0) as usize,
            width: u32::try_from(self.width).unwrap_or(0),
            height: u32::try_from(self.height).unwrap_or(0),
            size_bytes: self.size_bytes.max(0) as u64,
            created_at: self.created_at,
            account: self.account,
            id,
        })
    }
}

/// Message of a job failed because its workers kept dying.
/// An upload's row as read, before its state is parsed.
pub(crate) struct RawUpload {
    pub id: String,
    pub account: Option<String>,
    pub size: i64,
    pub part_size: i64,
    pub sha256: Option<String>,
    pub state: String,
    pub lease_until: Option<i64>,
    pub capture_id: Option<String>,
    pub error_code: Option<String>,
    pub error: Option<String>,
    pub created_at: i64,
    pub updated_at: i64,
}

/// The columns of `uploads` in [`RawUpload`]'s order.
pub(crate) const UPLOAD_COLUMNS: &str = "id, account, size, part_size, sha256, state, \
                                          lease_until, capture_id, error_code, error, \
                                          created_at, updated_at";

impl RawUpload {
    pub fn parse(self, parts: Vec<UploadPart>) -> Result<UploadRecord, StoreError> {
        let bad = |problem: &str| corrupt(&self.id, "state", problem);
        let state = match self.state.as_str() {
            "open" => UploadState::Open,
            "committing" => UploadState::Committing {
                until: self
                    .lease_until
                    .ok_or_else(|| bad("committing without a lease"))?,
            },
            "committed" => UploadState::Committed {
                capture_id: self
                    .capture_id
                    .clone()
                    .ok_or_else(|| bad("committed without a capture"))?,
            },
            "failed" => UploadState::Failed {
                code: self.error_code.clone().unwrap_or_default(),
                message: self.error.clone().unwrap_or_default(),
            },
            other => return Err(bad(&format!("unknown upload state `{other}`"))),
        };
        Ok(UploadRecord {
            size: u64::try_from(self.size).map_err(|_| bad("negative size"))?,
            part_size: u64::try_from(self.part_size).map_err(|_| bad("negative part size"))?,
            id: self.id,
            account: self.account,
            sha256: self.sha256,
            state,
            parts,
            created_at: self.created_at,
            updated_at: self.updated_at,
        })
    }
}

impl UploadEnd {
    /// The `state`, `capture_id`, `error_code` and `error` columns it writes.
    pub(crate) fn columns(&self) -> (&'static str, Option<&str>, Option<&str>, Option<&str>) {
        match self {
            UploadEnd::Committed { capture_id } => ("committed", Some(capture_id), None, None),
            UploadEnd::Failed { code, message } => ("failed", None, Some(code), Some(message)),
            UploadEnd::Reopened | UploadEnd::PartsLost { .. } => ("open", None, None, None),
        }
    }
}

pub(crate) fn abandoned_message(max_attempts: u32) -> String {
    format!("abandoned: the worker running it died {max_attempts} times (lease expired)")
}

/// The `error_code` of a job failed because its workers kept dying.
pub(crate) const ABANDONED: &str = "abandoned";

/// The columns [`Finish`] writes: state, error, error code, finished (whether `finished_at` is
/// set), and for a death its reason. A death is resolved in SQL against the stored `last_death`.
pub(crate) struct FinishColumns<'a> {
    pub state: &'static str,
    pub error: Option<&'a str>,
    pub error_code: Option<&'a str>,
    pub finished: bool,
    pub death: Option<&'a str>,
}

impl Finish {
    pub(crate) fn columns(&self) -> FinishColumns<'_> {
        let plain = |state, finished| FinishColumns {
            state,
            error: None,
            error_code: None,
            finished,
            death: None,
        };
        match self {
            Finish::Succeeded => plain("succeeded", true),
            Finish::Cancelled => plain("cancelled", true),
            Finish::Requeue => plain("queued", false),
            Finish::Failed { code, message } => FinishColumns {
                state: "failed",
                error: Some(message),
                error_code: Some(code),
                finished: true,
                death: None,
            },
            Finish::Died { reason, message } => FinishColumns {
                state: "queued",
                error: Some(message),
                error_code: Some(reason),
                finished: false,
                death: Some(reason),
            },
        }
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

/// Jobs each account may run at once, as the store's claim reads them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RunningLimits {
    /// An account without a limit of its own; `None`: unlimited.
    pub default: Option<u32>,
    /// Accounts with a limit of their own.
    pub accounts: BTreeMap<String, u32>,
}

impl RunningLimits {
    /// The per-account limits as a JSON object (`{"alice": 2}`), which both stores' SQL reads.
    pub fn accounts_json(&self) -> String {
        serde_json::to_string(&self.accounts).unwrap_or_else(|_| "{}".into())
    }
}

/// What an account holds now.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, utoipa::ToSchema)]
pub struct AccountUsage {
    pub running: u32,
    pub queued: u32,
    /// Bytes of its captures and of its open uploads (as declared).
    pub stored_bytes: u64,
}

#[cfg(test)]
mod tests {
    use super::rfc3339;

    #[test]
    fn rfc3339_matches_known_instants() {
        assert_eq!(rfc3339(0), "1970-01-01T00:00:00.000Z");
        assert_eq!(rfc3339(951_782_400_123), "2000-02-29T00:00:00.123Z");
        assert_eq!(rfc3339(1_767_225_599_999), "2025-12-31T23:59:59.999Z");
    }
}
