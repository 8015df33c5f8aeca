//! The shared store: PostgreSQL through a connection pool (deadpool over tokio-postgres), for API
//! replicas and workers on many machines. Claims take the oldest queued job with
//! `FOR UPDATE SKIP LOCKED`, so concurrent workers never wait on or take the same row; every other
//! write is one conditional statement or one short transaction. The schema is created and
//! upgraded at connect by the migrations in `api/migrations/postgres/`, under an advisory lock so
//! replicas starting together apply each one once.

use std::str::FromStr;
use std::time::Duration;

use deadpool_postgres::{Manager, ManagerConfig, Pool, RecyclingMethod, Runtime};
use tokio_postgres::types::ToSql;
use tokio_postgres::{NoTls, Row};

use super::{
    abandoned_message, corrupt, to_json, CaptureRecord, DeleteOutcome, Finish, JobRecord, JobSpec,
    NewJob, PartOutcome, Progress, QueueCounts, RawCapture, RawJob, RawUpload, Reserved, Store,
    StoreError, UploadEnd, UploadPart, UploadRecord, WebhookDelivery, ABANDONED, UPLOAD_COLUMNS,
};
use super::{AccountUsage, RunningLimits};

/// The schema's versions, oldest first; each runs once, in a transaction.
const MIGRATIONS: &[(i32, &str)] = &[
    (
        1,
        include_str!("../../../migrations/postgres/0001_captures_and_jobs.sql"),
    ),
    (
        2,
        include_str!("../../../migrations/postgres/0002_accounts.sql"),
    ),
    (
        3,
        include_str!("../../../migrations/postgres/0003_operations.sql"),
    ),
    (
        4,
        include_str!("../../../migrations/postgres/0004_reservations.sql"),
    ),
];

/// Key of the advisory lock that serializes migrations ("phygap" in ASCII).
const MIGRATION_LOCK: i64 = 0x7068_7967_6170;

/// Connections a process keeps open at most.
const POOL_SIZE: usize = 16;
/// How long a query waits for a free connection, or for a new one to be made.
const POOL_TIMEOUT: Duration = Duration::from_secs(5);

const JOB_COLUMNS: &str = "id, capture_id, spec, state, progress, error, created_at, started_at, \
                           finished_at, attempts, cancel_requested, account, error_code, \
                           last_death, webhook_url, webhook_attempts, webhook_status, \
                           webhook_done, priority, max_runtime_s";
/// Key of the advisory lock that claims under running limits take in turn (the migrations' + 1).
const CLAIM_LOCK: i64 = MIGRATION_LOCK + 1;

/// First key of the advisory locks that an account's storage reservations take in turn (the
/// second is a hash of the account's name).
const QUOTA_LOCK: i32 = 0x7068_7971;

/// The bytes account `$1` stores at `$2` (unix ms): its captures, its open uploads, and its
/// reservations still live whose capture or upload is not recorded yet.
const STORED_BYTES: &str = "
    ((SELECT COALESCE(SUM(size_bytes), 0) FROM captures WHERE account = $1)
     + (SELECT COALESCE(SUM(size), 0) FROM uploads
        WHERE account = $1 AND state IN ('open', 'committing'))
     + (SELECT COALESCE(SUM(r.bytes), 0) FROM reservations r
        WHERE r.account = $1 AND r.expires_at > $2
          AND NOT EXISTS (SELECT 1 FROM captures c WHERE c.id = r.id)
          AND NOT EXISTS (SELECT 1 FROM uploads u WHERE u.id = r.id)))::BIGINT";

/// The jobs account `$1` has queued at `$2` (unix ms), with the live places reserved for jobs
/// not yet in the queue (a place whose job is queued, running or ended counts no more; a
/// failed or cancelled job's place is one for its restart).
const QUEUED_OR_PLACED: &str = "
    ((SELECT COUNT(*) FROM jobs WHERE account = $1 AND state = 'queued')
     + (SELECT COUNT(*) FROM queue_places q
        WHERE q.account = $1 AND q.expires_at > $2
          AND NOT EXISTS (SELECT 1 FROM jobs j
                          WHERE j.id = q.job_id AND j.state NOT IN ('failed', 'cancelled'))))";

/// How many columns [`JOB_COLUMNS`] names.
const JOB_COLUMN_COUNT: usize = 20;

/// The PostgreSQL store.
pub struct PostgresStore {
    pool: Pool,
}

impl From<tokio_postgres::Error> for StoreError {
    /// Lost connections and a server that is shutting down or starting are `Unavailable` (the
    /// caller may retry); anything else is a query error.
    fn from(e: tokio_postgres::Error) -> Self {
        let io = std::error::Error::source(&e).is_some_and(|s| s.is::<std::io::Error>());
        let class = e.code().map(|c| &c.code()[..2]);
        // SQLSTATE 08: connection exception; 57: operator intervention (shutdown, restart).
        if e.is_closed() || io || matches!(class, Some("08" | "57")) {
            StoreError::Unavailable(e.to_string())
        } else {
            StoreError::Postgres(e)
        }
    }
}

impl From<deadpool_postgres::PoolError> for StoreError {
    fn from(e: deadpool_postgres::PoolError) -> Self {
        match e {
            deadpool_postgres::PoolError::Backend(e) => e.into(),
            other => StoreError::Unavailable(other.to_string()),
        }
    }
}

fn raw_job(row: &Row) -> Result<RawJob, StoreError> {
    Ok(RawJob {
        id: row.try_get(0)?,
        capture_id: row.try_get(1)?,
        spec: row.try_get(2)?,
        state: row.try_get(3)?,
        progress: row.try_get(4)?,
        error: row.try_get(5)?,
        created_at: row.try_get(6)?,
        started_at: row.try_get(7)?,
        finished_at: row.try_get(8)?,
        attempts: row.try_get::<_, i32>(9)?.max(0) as u32,
        cancel_requested: row.try_get(10)?,
        account: row.try_get(11)?,
        error_code: row.try_get(12)?,
        last_death: row.try_get(13)?,
        webhook_url: row.try_get(14)?,
        webhook_attempts: row.try_get::<_, i32>(15)?.max(0) as u32,
        webhook_status: row.try_get(16)?,
        webhook_done: row.try_get(17)?,
        priority: row.try_get(18)?,
        max_runtime_seconds: row.try_get(19)?,
    })
}

fn job_of(row: &Row) -> Result<JobRecord, StoreError> {
    raw_job(row)?.parse()
}

fn raw_upload(row: &Row) -> Result<RawUpload, StoreError> {
    Ok(RawUpload {
        id: row.try_get(0)?,
        account: row.try_get(1)?,
        size: row.try_get(2)?,
        part_size: row.try_get(3)?,
        sha256: row.try_get(4)?,
        state: row.try_get(5)?,
        lease_until: row.try_get(6)?,
        capture_id: row.try_get(7)?,
        error_code: row.try_get(8)?,
        error: row.try_get(9)?,
        created_at: row.try_get(10)?,
        updated_at: row.try_get(11)?,
    })
}

/// An upload and its parts, read by `client` (a connection or a transaction).
async fn upload_with<C: tokio_postgres::GenericClient>(
    client: &C,
    id: &str,
) -> Result<Option<UploadRecord>, StoreError> {
    let sql = format!("SELECT {UPLOAD_COLUMNS} FROM uploads WHERE id = $1");
    let Some(row) = client.query_opt(&sql, &[&id]).await? else {
        return Ok(None);
    };
    let raw = raw_upload(&row)?;
    let parts = client
        .query(
            "SELECT idx, size, sha256, copy_id FROM upload_parts WHERE upload_id = $1
             ORDER BY idx",
            &[&id],
        )
        .await?
        .iter()
        .map(part_of)
        .collect::<Result<Vec<_>, _>>()?;
    raw.parse(parts).map(Some)
}

fn part_of(row: &Row) -> Result<UploadPart, StoreError> {
    Ok(UploadPart {
        index: row.try_get::<_, i32>(0)?.max(0) as u32,
        size: row.try_get::<_, i64>(1)?.max(0) as u64,
        sha256: row.try_get(2)?,
        copy: row.try_get(3)?,
    })
}

impl PostgresStore {
    /// Connects to `url` (`postgres://user:password@host:port/database`, or key=value pairs) and
    /// brings the schema up to date. Fails when the server cannot be reached.
    pub async fn connect(url: &str) -> Result<Self, StoreError> {
        let mut config = tokio_postgres::Config::from_str(url)
            .map_err(|e| StoreError::InvalidUrl(e.to_string()))?;
        if config.get_connect_timeout().is_none() {
            config.connect_timeout(POOL_TIMEOUT);
        }
        config.application_name("phygap-api");
        let manager = Manager::from_config(
            config,
            NoTls,
            ManagerConfig {
                recycling_method: RecyclingMethod::Fast,
            },
        );
        let pool = Pool::builder(manager)
            .max_size(POOL_SIZE)
            .runtime(Runtime::Tokio1)
            .wait_timeout(Some(POOL_TIMEOUT))
            .create_timeout(Some(POOL_TIMEOUT))
            .build()
            .map_err(|e| StoreError::InvalidUrl(e.to_string()))?;
        let store = PostgresStore { pool };
        store.migrate().await?;
        Ok(store)
    }

    /// Applies the migrations this database has not seen yet.
    async fn migrate(&self) -> Result<(), StoreError> {
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        tx.execute("SELECT pg_advisory_xact_lock($1)", &[&MIGRATION_LOCK])
            .await?;
        tx.batch_execute(
            "CREATE TABLE IF NOT EXISTS schema_migrations (
                 version INTEGER PRIMARY KEY,
                 applied_at BIGINT NOT NULL)",
        )
        .await?;
        let applied: Vec<i32> = tx
            .query("SELECT version FROM schema_migrations", &[])
            .await?
            .iter()
            .map(|row| row.try_get(0))
            .collect::<Result<_, _>>()?;
        let newest_known = MIGRATIONS.last().map_or(0, |&(version, _)| version);
        if let Some(newer) = applied.iter().find(|&&v| v > newest_known) {
            return Err(StoreError::Migration(format!(
                "the database is at schema version {newer}, newer than this build knows \
                 ({newest_known}); upgrade phygap-api"
            )));
        }
        for &(version, sql) in MIGRATIONS {
            if applied.contains(&version) {
                continue;
            }
            tx.batch_execute(sql)
                .await
                .map_err(|e| StoreError::Migration(format!("version {version}: {e}")))?;
            tx.execute(
                "INSERT INTO schema_migrations (version, applied_at) VALUES ($1, $2)",
                &[&version, &super::now_ms()],
            )
            .await?;
            tracing::info!(version, "applied a database migration");
        }
        tx.commit().await?;
        Ok(())
    }

    async fn query_job(
        &self,
        sql: &str,
        params: &[&(dyn ToSql + Sync)],
    ) -> Result<Option<JobRecord>, StoreError> {
        let client = self.pool.get().await?;
        // Job reads are the polling hot path: a statement prepared once per connection saves
        // a round trip per read.
        let statement = client.prepare_cached(sql).await?;
        client
            .query_opt(&statement, params)
            .await?
            .as_ref()
            .map(job_of)
            .transpose()
    }
}

#[async_trait::async_trait]
impl Store for PostgresStore {
    async fn ping(&self) -> Result<(), StoreError> {
        let client = self.pool.get().await?;
        client.execute("SELECT 1", &[]).await?;
        Ok(())
    }

    async fn insert_capture(&self, capture: &CaptureRecord) -> Result<(), StoreError> {
        let client = self.pool.get().await?;
        client
            .execute(
                "INSERT INTO captures (id, views, kinds, warnings, size_bytes, created_at, account,
                                       width, height)
                 VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9)",
                &[
                    &capture.id,
                    &(capture.views as i64),
                    &to_json(&capture.kinds),
                    &to_json(&capture.warnings),
                    &(capture.size_bytes as i64),
                    &capture.created_at,
                    &capture.account,
                    &i64::from(capture.width),
                    &i64::from(capture.height),
                ],
            )
            .await?;
        Ok(())
    }

    async fn capture(&self, id: &str) -> Result<Option<CaptureRecord>, StoreError> {
        let client = self.pool.get().await?;
        let Some(row) = client
            .query_opt(
                "SELECT id, views, kinds, warnings, size_bytes, created_at, account, width, height
                 FROM captures WHERE id = $1",
                &[&id],
            )
            .await?
        else {
            return Ok(None);
        };
        RawCapture {
            id: row.try_get(0)?,
            views: row.try_get(1)?,
            kinds: row.try_get(2)?,
            warnings: row.try_get(3)?,
            size_bytes: row.try_get(4)?,
            created_at: row.try_get(5)?,
            account: row.try_get(6)?,
            width: row.try_get(7)?,
            height: row.try_get(8)?,
        }
        .parse()
        .map(Some)
    }

    async fn capture_ids(&self) -> Result<Vec<String>, StoreError> {
        let client = self.pool.get().await?;
        let rows = client.query("SELECT id FROM captures", &[]).await?;
        Ok(rows
            .iter()
            .map(|r| r.try_get(0))
            .collect::<Result<_, _>>()?)
    }

    async fn delete_capture(&self, id: &str) -> Result<DeleteOutcome, StoreError> {
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        // Locking the capture's row orders this against a concurrent delete of the same capture.
        let exists = tx
            .query_opt("SELECT 1 FROM captures WHERE id = $1 FOR UPDATE", &[&id])
            .await?
            .is_some();
        if !exists {
            return Ok(DeleteOutcome::NotFound);
        }
        let active: i64 = tx
            .query_one(
                "SELECT count(*) FROM jobs
                 WHERE capture_id = $1 AND state IN ('queued', 'running')",
                &[&id],
            )
            .await?
            .try_get(0)?;
        if active > 0 {
            return Ok(DeleteOutcome::InUse);
        }
        tx.execute("DELETE FROM captures WHERE id = $1", &[&id])
            .await?;
        tx.commit().await?;
        Ok(DeleteOutcome::Deleted)
    }

    async fn submit(
        &self,
        job: &NewJob,
        idempotency: Option<(&str, &str)>,
    ) -> Result<(JobRecord, bool), StoreError> {
        let progress = to_json(&Progress {
            iterations: job.iterations,
            ..Progress::default()
        });
        let spec = to_json(&job.spec);
        let (key, hash) = (idempotency.map(|(k, _)| k), idempotency.map(|(_, h)| h));
        let max_runtime = job
            .max_runtime_seconds
            .map(|s| s.min(i64::MAX as u64) as i64);
        let client = self.pool.get().await?;
        // A key used before (even by a request still in flight on another replica) makes the
        // insert a no-op; the job it names is then read back below.
        let inserted = client
            .query_opt(
                &format!(
                    "INSERT INTO jobs (id, capture_id, spec, state, progress, created_at,
                                       request_key, request_hash, account, webhook_url,
                                       priority, max_runtime_s)
                     VALUES ($1, $2, $3, 'queued', $4, $5, $6, $7, $8, $9, $10, $11)
                     ON CONFLICT ((COALESCE(account, '')), request_key)
                         WHERE request_key IS NOT NULL DO NOTHING
                     RETURNING {JOB_COLUMNS}"
                ),
                &[
                    &job.id,
                    &job.capture_id,
                    &spec,
                    &progress,
                    &job.created_at,
                    &key,
                    &hash,
                    &job.account,
                    &job.webhook_url,
                    &job.priority,
                    &max_runtime,
                ],
            )
            .await?;
        if let Some(row) = inserted {
            return Ok((job_of(&row)?, true));
        }
        let (Some(key), Some(hash)) = (key, hash) else {
            return Err(corrupt(
                &job.id,
                "id",
                "insert without a key returned no row",
            ));
        };
        let row = client
            .query_one(
                &format!(
                    "SELECT {JOB_COLUMNS}, request_hash FROM jobs
                     WHERE request_key = $1 AND account IS NOT DISTINCT FROM $2"
                ),
                &[&key, &job.account],
            )
            .await?;
        // request_hash follows the job's columns.
        let stored_hash: Option<String> = row.try_get(JOB_COLUMN_COUNT)?;
        if stored_hash.as_deref() != Some(hash) {
            return Err(StoreError::IdempotencyConflict(key.to_owned()));
        }
        Ok((job_of(&row)?, false))
    }

    async fn has_request_key(&self, account: Option<&str>, key: &str) -> Result<bool, StoreError> {
        let client = self.pool.get().await?;
        let row = client
            .query_one(
                "SELECT EXISTS (SELECT 1 FROM jobs
                                WHERE request_key = $1 AND account IS NOT DISTINCT FROM $2)",
                &[&key, &account],
            )
            .await?;
        Ok(row.try_get(0)?)
    }

    async fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError> {
        self.query_job(
            &format!("SELECT {JOB_COLUMNS} FROM jobs WHERE id = $1"),
            &[&id],
        )
        .await
    }

    async fn list_jobs(
        &self,
        limit: usize,
        account: Option<&str>,
    ) -> Result<Vec<JobRecord>, StoreError> {
        let client = self.pool.get().await?;
        let rows = client
            .query(
                &format!(
                    "SELECT {JOB_COLUMNS} FROM jobs WHERE $2::TEXT IS NULL OR account = $2
                     ORDER BY created_at DESC, seq DESC LIMIT $1"
                ),
                &[&(limit.min(i64::MAX as usize) as i64), &account],
            )
            .await?;
        rows.iter().map(job_of).collect()
    }

    async fn delete_job(&self, id: &str) -> Result<DeleteOutcome, StoreError> {
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        // Locking the row orders this against a concurrent claim, cancel or delete of the job.
        let Some(row) = tx
            .query_opt("SELECT state FROM jobs WHERE id = $1 FOR UPDATE", &[&id])
            .await?
        else {
            return Ok(DeleteOutcome::NotFound);
        };
        let state: String = row.try_get(0)?;
        let needed: i64 = tx
            .query_one(
                "SELECT count(*) FROM jobs WHERE state IN ('queued', 'running')
                 AND spec::jsonb ->> 'parent_job_id' = $1",
                &[&id],
            )
            .await?
            .try_get(0)?;
        if matches!(state.as_str(), "queued" | "running") || needed > 0 {
            return Ok(DeleteOutcome::InUse);
        }
        tx.execute("DELETE FROM jobs WHERE id = $1", &[&id]).await?;
        tx.execute("DELETE FROM job_events WHERE job_id = $1", &[&id])
            .await?;
        tx.commit().await?;
        Ok(DeleteOutcome::Deleted)
    }

    async fn jobs_ended_before(&self, before: i64) -> Result<Vec<String>, StoreError> {
        let client = self.pool.get().await?;
        let rows = client
            .query(
                "SELECT id FROM jobs AS ended
                 WHERE state IN ('succeeded', 'failed', 'cancelled') AND finished_at < $1
                 AND NOT EXISTS (SELECT 1 FROM jobs WHERE state IN ('queued', 'running')
                                 AND spec::jsonb ->> 'parent_job_id' = ended.id)
                 ORDER BY finished_at",
                &[&before],
            )
            .await?;
        Ok(rows
            .iter()
            .map(|r| r.try_get(0))
            .collect::<Result<_, _>>()?)
    }

    async fn unused_captures_before(&self, before: i64) -> Result<Vec<String>, StoreError> {
        let client = self.pool.get().await?;
        let rows = client
            .query(
                "SELECT id FROM captures WHERE created_at < $1
                 AND NOT EXISTS (SELECT 1 FROM jobs WHERE jobs.capture_id = captures.id)
                 ORDER BY created_at",
                &[&before],
            )
            .await?;
        Ok(rows
            .iter()
            .map(|r| r.try_get(0))
            .collect::<Result<_, _>>()?)
    }

    async fn claim_within(
        &self,
        owner: &str,
        now: i64,
        lease_until: i64,
        running: &RunningLimits,
    ) -> Result<Option<JobRecord>, StoreError> {
        // $4: {"account": limit, …}; $5: the limit of other accounts (NULL: none).
        let sql = format!(
            "UPDATE jobs SET state = 'running', owner = $1, lease_until = $2,
                    started_at = COALESCE(started_at, $3), attempts = attempts + 1
             WHERE id = (
                 SELECT id FROM jobs AS q WHERE state = 'queued'
                   AND (q.account IS NULL
                        OR COALESCE(($4::TEXT::JSONB ->> q.account)::BIGINT, $5) IS NULL
                        OR (SELECT COUNT(*) FROM jobs AS busy
                            WHERE busy.state = 'running' AND busy.account = q.account)
                           < COALESCE(($4::TEXT::JSONB ->> q.account)::BIGINT, $5))
                 ORDER BY priority DESC, created_at, seq LIMIT 1
                 FOR UPDATE SKIP LOCKED)
             RETURNING {JOB_COLUMNS}"
        );
        let (accounts, default) = (running.accounts_json(), running.default.map(i64::from));
        let params: [&(dyn ToSql + Sync); 5] = [&owner, &lease_until, &now, &accounts, &default];
        if running.default.is_none() && running.accounts.is_empty() {
            return self.query_job(&sql, &params).await;
        }
        // With running limits, claims take turns: each counts an account's running jobs after
        // the claim before it committed, so processes claiming at once cannot both take an
        // account's last slot. (A claim is a few milliseconds; the lock ends with the
        // transaction.)
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        tx.execute("SELECT pg_advisory_xact_lock($1)", &[&CLAIM_LOCK])
            .await?;
        let claimed = tx
            .query_opt(&sql, &params)
            .await?
            .as_ref()
            .map(job_of)
            .transpose()?;
        tx.commit().await?;
        Ok(claimed)
    }

    async fn account_usage(&self, account: &str) -> Result<AccountUsage, StoreError> {
        let client = self.pool.get().await?;
        let row = client
            .query_one(
                &format!(
                    "SELECT
                    (SELECT COUNT(*) FROM jobs WHERE account = $1 AND state = 'running'),
                    (SELECT COUNT(*) FROM jobs WHERE account = $1 AND state = 'queued'),
                    {STORED_BYTES}"
                ),
                &[&account, &super::now_ms()],
            )
            .await?;
        let count = |i: usize| -> Result<u32, StoreError> {
            Ok(row.try_get::<_, i64>(i)?.clamp(0, u32::MAX as i64) as u32)
        };
        Ok(AccountUsage {
            running: count(0)?,
            queued: count(1)?,
            stored_bytes: row.try_get::<_, i64>(2)?.max(0) as u64,
        })
    }

    async fn heartbeat(
        &self,
        id: &str,
        owner: &str,
        progress: &Progress,
        lease_until: i64,
    ) -> Result<bool, StoreError> {
        let client = self.pool.get().await?;
        let row = client
            .query_opt(
                "UPDATE jobs SET progress = $1, lease_until = $2
                 WHERE id = $3 AND owner = $4 AND state = 'running'
                 RETURNING cancel_requested",
                &[&to_json(progress), &lease_until, &id, &owner],
            )
            .await?
            .ok_or_else(|| StoreError::LeaseLost(id.to_owned()))?;
        Ok(row.try_get(0)?)
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
        let client = self.pool.get().await?;
        // A death fails the job when its previous attempt died the same way, else requeues it
        // and remembers how it died; other endings are written as they are.
        let changed = client
            .execute(
                "UPDATE jobs SET
                    state = CASE WHEN $5::TEXT IS NULL THEN $1::TEXT
                                 WHEN last_death IS NOT DISTINCT FROM $5 THEN 'failed'
                                 ELSE 'queued' END,
                    error = CASE WHEN $5::TEXT IS NULL OR last_death IS NOT DISTINCT FROM $5
                                 THEN $2::TEXT ELSE error END,
                    error_code = CASE WHEN $5::TEXT IS NULL OR last_death IS NOT DISTINCT FROM $5
                                      THEN $3::TEXT ELSE error_code END,
                    finished_at = CASE WHEN $5::TEXT IS NULL THEN $4::BIGINT
                                       WHEN last_death IS NOT DISTINCT FROM $5 THEN $6::BIGINT
                                       ELSE NULL END,
                    last_death = COALESCE($5, last_death),
                    owner = NULL, lease_until = NULL
                 WHERE id = $7 AND owner = $8 AND state = 'running'",
                &[
                    &columns.state,
                    &columns.error,
                    &columns.error_code,
                    &finished_at,
                    &columns.death,
                    &now,
                    &id,
                    &owner,
                ],
            )
            .await?;
        if changed == 0 {
            return Err(StoreError::LeaseLost(id.to_owned()));
        }
        Ok(())
    }

    async fn restart(
        &self,
        id: &str,
        spec: Option<&JobSpec>,
        fresh: Option<&Progress>,
    ) -> Result<Option<JobRecord>, StoreError> {
        let (spec, fresh) = (spec.map(to_json), fresh.map(to_json));
        // One statement: the update (when the job may restart) and the job as it is after it.
        self.query_job(
            &format!(
                "WITH restarted AS (
                     UPDATE jobs SET state = 'queued', error = NULL, error_code = NULL,
                            last_death = NULL, finished_at = NULL, cancel_requested = FALSE,
                            webhook_attempts = 0, webhook_status = NULL,
                            webhook_next_at = NULL, webhook_done = FALSE,
                            spec = COALESCE($2, spec),
                            attempts = CASE WHEN $3::TEXT IS NULL THEN attempts ELSE 0 END,
                            progress = COALESCE($3, progress)
                     WHERE id = $1 AND state IN ('failed', 'cancelled')
                     RETURNING {JOB_COLUMNS})
                 SELECT {JOB_COLUMNS} FROM restarted
                 UNION ALL
                 SELECT {JOB_COLUMNS} FROM jobs
                 WHERE id = $1 AND NOT EXISTS (SELECT 1 FROM restarted)"
            ),
            &[&id, &spec, &fresh],
        )
        .await
    }

    async fn request_cancel(&self, id: &str, now: i64) -> Result<Option<JobRecord>, StoreError> {
        self.query_job(
            &format!(
                "UPDATE jobs SET cancel_requested = cancel_requested OR state IN ('queued', 'running'),
                        state = CASE WHEN state = 'queued' THEN 'cancelled' ELSE state END,
                        finished_at = CASE WHEN state = 'queued' THEN $2 ELSE finished_at END
                 WHERE id = $1
                 RETURNING {JOB_COLUMNS}"
            ),
            &[&id, &now],
        )
        .await
    }

    async fn requeue_expired(
        &self,
        now: i64,
        max_attempts: u32,
    ) -> Result<Vec<String>, StoreError> {
        let client = self.pool.get().await?;
        let max_attempts = i32::try_from(max_attempts).unwrap_or(i32::MAX);
        let rows = client
            .query(
                "UPDATE jobs SET state = CASE
                        WHEN cancel_requested THEN 'cancelled'
                        WHEN attempts >= $2 THEN 'failed'
                        ELSE 'queued' END,
                    error = CASE WHEN NOT cancel_requested AND attempts >= $2 THEN $3
                                 ELSE error END,
                    error_code = CASE WHEN NOT cancel_requested AND attempts >= $2 THEN $4
                                      ELSE error_code END,
                    finished_at = CASE WHEN cancel_requested OR attempts >= $2 THEN $1
                                       ELSE finished_at END,
                    owner = NULL, lease_until = NULL
                 WHERE state = 'running' AND lease_until < $1
                 RETURNING id",
                &[
                    &now,
                    &max_attempts,
                    &abandoned_message(max_attempts as u32),
                    &ABANDONED,
                ],
            )
            .await?;
        Ok(rows
            .iter()
            .map(|r| r.try_get(0))
            .collect::<Result<_, _>>()?)
    }

    async fn append_events(
        &self,
        id: &str,
        first_seq: u64,
        events: &[String],
    ) -> Result<(), StoreError> {
        if events.is_empty() {
            return Ok(());
        }
        let seqs: Vec<i64> = (0..events.len())
            .map(|i| (first_seq + i as u64) as i64)
            .collect();
        let client = self.pool.get().await?;
        client
            .execute(
                "INSERT INTO job_events (job_id, seq, event)
                 SELECT $1, seq, event FROM UNNEST($2::BIGINT[], $3::TEXT[]) AS e(seq, event)
                 ON CONFLICT (job_id, seq) DO UPDATE SET event = EXCLUDED.event",
                &[&id, &seqs, &events],
            )
            .await?;
        Ok(())
    }

    async fn events(
        &self,
        id: &str,
        from: u64,
        limit: usize,
    ) -> Result<Vec<(u64, String)>, StoreError> {
        let client = self.pool.get().await?;
        let rows = client
            .query(
                "SELECT seq, event FROM job_events WHERE job_id = $1 AND seq >= $2
                 ORDER BY seq LIMIT $3",
                &[&id, &(from as i64), &(limit as i64)],
            )
            .await?;
        rows.iter()
            .map(|r| Ok((r.try_get::<_, i64>(0)?.max(0) as u64, r.try_get(1)?)))
            .collect()
    }

    async fn next_event_seq(&self, id: &str) -> Result<u64, StoreError> {
        let client = self.pool.get().await?;
        let row = client
            .query_one(
                "SELECT COALESCE(MAX(seq) + 1, 0) FROM job_events WHERE job_id = $1",
                &[&id],
            )
            .await?;
        Ok(row.try_get::<_, i64>(0)?.max(0) as u64)
    }

    async fn take_webhook(
        &self,
        now: i64,
        lease_until: i64,
        busy_accounts: &[String],
    ) -> Result<Option<WebhookDelivery>, StoreError> {
        let busy = busy_accounts.to_vec();
        let job = self
            .query_job(
                &format!(
                    "UPDATE jobs SET webhook_next_at = $2
                     WHERE id = (
                         SELECT id FROM jobs
                         WHERE webhook_url IS NOT NULL AND NOT webhook_done
                           AND state IN ('succeeded', 'failed', 'cancelled')
                           AND COALESCE(webhook_next_at, 0) <= $1
                           AND NOT (COALESCE(account, '') = ANY($3))
                         ORDER BY COALESCE(webhook_next_at, 0), finished_at
                         LIMIT 1 FOR UPDATE SKIP LOCKED)
                     RETURNING {JOB_COLUMNS}"
                ),
                &[&now, &lease_until, &busy],
            )
            .await?;
        Ok(job.and_then(WebhookDelivery::of))
    }

    async fn record_webhook(
        &self,
        id: &str,
        attempts: u32,
        status: &str,
        next_at: Option<i64>,
    ) -> Result<(), StoreError> {
        let client = self.pool.get().await?;
        client
            .execute(
                "UPDATE jobs SET webhook_attempts = $2, webhook_status = $3,
                        webhook_next_at = $4, webhook_done = ($4::BIGINT IS NULL)
                 WHERE id = $1",
                &[&id, &(attempts as i32), &status, &next_at],
            )
            .await?;
        Ok(())
    }

    async fn create_upload(&self, upload: &UploadRecord) -> Result<(), StoreError> {
        let client = self.pool.get().await?;
        client
            .execute(
                "INSERT INTO uploads (id, account, size, part_size, sha256, state, created_at,
                                      updated_at)
                 VALUES ($1, $2, $3, $4, $5, 'open', $6, $6)",
                &[
                    &upload.id,
                    &upload.account,
                    &(upload.size as i64),
                    &(upload.part_size as i64),
                    &upload.sha256,
                    &upload.created_at,
                ],
            )
            .await?;
        Ok(())
    }

    async fn upload(&self, id: &str) -> Result<Option<UploadRecord>, StoreError> {
        let client = self.pool.get().await?;
        let client: &tokio_postgres::Client = &client;
        upload_with(client, id).await
    }

    async fn record_part(
        &self,
        id: &str,
        part: &UploadPart,
        now: i64,
    ) -> Result<PartOutcome, StoreError> {
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        let state: Option<String> = tx
            .query_opt("SELECT state FROM uploads WHERE id = $1 FOR UPDATE", &[&id])
            .await?
            .map(|row| row.try_get(0))
            .transpose()?;
        match state.as_deref() {
            None => return Ok(PartOutcome::NotFound),
            Some("open") => {}
            Some(_) => return Ok(PartOutcome::Closed),
        }
        let index = part.index as i32;
        let replaced = tx
            .query_opt(
                "SELECT idx, size, sha256, copy_id FROM upload_parts
                 WHERE upload_id = $1 AND idx = $2",
                &[&id, &index],
            )
            .await?
            .map(|row| part_of(&row))
            .transpose()?;
        tx.execute(
            "INSERT INTO upload_parts (upload_id, idx, size, sha256, copy_id)
             VALUES ($1, $2, $3, $4, $5)
             ON CONFLICT (upload_id, idx) DO UPDATE SET size = $3, sha256 = $4, copy_id = $5",
            &[&id, &index, &(part.size as i64), &part.sha256, &part.copy],
        )
        .await?;
        tx.execute(
            "UPDATE uploads SET updated_at = $2 WHERE id = $1",
            &[&id, &now],
        )
        .await?;
        tx.commit().await?;
        Ok(PartOutcome::Recorded { replaced })
    }

    async fn begin_commit(
        &self,
        id: &str,
        now: i64,
        until: i64,
    ) -> Result<Option<UploadRecord>, StoreError> {
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        let taken = tx
            .execute(
                "UPDATE uploads SET state = 'committing', lease_until = $3, updated_at = $2
                 WHERE id = $1 AND (state = 'open' OR (state = 'committing' AND lease_until < $2))",
                &[&id, &now, &until],
            )
            .await?;
        if taken == 0 {
            return Ok(None);
        }
        let upload = {
            let tx: &tokio_postgres::Transaction<'_> = &tx;
            upload_with(tx, id).await?
        };
        tx.commit().await?;
        Ok(upload)
    }

    async fn end_commit(&self, id: &str, end: &UploadEnd, now: i64) -> Result<(), StoreError> {
        let (state, capture_id, code, error) = end.columns();
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        tx.execute(
            "UPDATE uploads SET state = $2, capture_id = $3, error_code = $4, error = $5,
                    lease_until = NULL, updated_at = $6
             WHERE id = $1",
            &[&id, &state, &capture_id, &code, &error, &now],
        )
        .await?;
        if state != "open" {
            tx.execute("DELETE FROM upload_parts WHERE upload_id = $1", &[&id])
                .await?;
        }
        if let UploadEnd::PartsLost { indexes } = end {
            let indexes: Vec<i32> = indexes.iter().map(|&i| i as i32).collect();
            tx.execute(
                "DELETE FROM upload_parts WHERE upload_id = $1 AND idx = ANY($2)",
                &[&id, &indexes],
            )
            .await?;
        }
        tx.commit().await?;
        Ok(())
    }

    async fn delete_upload(&self, id: &str) -> Result<bool, StoreError> {
        let client = self.pool.get().await?;
        // Its parts' records go with it (ON DELETE CASCADE).
        let deleted = client
            .execute("DELETE FROM uploads WHERE id = $1", &[&id])
            .await?;
        Ok(deleted > 0)
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
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        // The account's reservations take turns (across every process on this database):
        // none checks while another has checked and not yet written.
        tx.execute(
            "SELECT pg_advisory_xact_lock($1, hashtext($2))",
            &[&QUOTA_LOCK, &account],
        )
        .await?;
        tx.execute(
            "DELETE FROM reservations WHERE account = $1 AND id <> $3
             AND (expires_at <= $2 OR id IN (SELECT id FROM captures)
                  OR id IN (SELECT id FROM uploads))",
            &[&account, &now, &id],
        )
        .await?;
        let stored: i64 = tx
            .query_one(&format!("SELECT {STORED_BYTES}"), &[&account, &now])
            .await?
            .try_get(0)?;
        let stored = stored.max(0) as u64;
        let room = limit.saturating_sub(stored);
        let granted = match (bytes <= room, partial) {
            (true, _) => bytes,
            (false, true) => room,
            (false, false) => 0,
        };
        if granted > 0 {
            tx.execute(
                "INSERT INTO reservations (id, account, bytes, expires_at) VALUES ($1, $2, $3, $4)
                 ON CONFLICT (id) DO UPDATE
                 SET bytes = reservations.bytes + excluded.bytes, expires_at = excluded.expires_at",
                &[
                    &id,
                    &account,
                    &(granted.min(i64::MAX as u64) as i64),
                    &until,
                ],
            )
            .await?;
        }
        tx.commit().await?;
        Ok(Reserved {
            granted,
            stored_bytes: stored,
        })
    }

    async fn release_reservation(&self, id: &str) -> Result<(), StoreError> {
        let client = self.pool.get().await?;
        client
            .execute("DELETE FROM reservations WHERE id = $1", &[&id])
            .await?;
        Ok(())
    }

    async fn reserve_queue_place(
        &self,
        account: &str,
        job_id: &str,
        max_queued: u32,
        now: i64,
        until: i64,
    ) -> Result<Result<(), u32>, StoreError> {
        let mut client = self.pool.get().await?;
        let tx = client.transaction().await?;
        // One account's places are checked and written in turn, across processes.
        tx.execute(
            "SELECT pg_advisory_xact_lock($1, hashtext($2))",
            &[&(QUOTA_LOCK + 1), &account],
        )
        .await?;
        tx.execute(
            "DELETE FROM queue_places WHERE account = $1 AND expires_at <= $2",
            &[&account, &now],
        )
        .await?;
        let held: i64 = tx
            .query_one(&format!("SELECT {QUEUED_OR_PLACED}"), &[&account, &now])
            .await?
            .try_get(0)?;
        let held = held.clamp(0, u32::MAX as i64) as u32;
        if held >= max_queued {
            return Ok(Err(held));
        }
        tx.execute(
            "INSERT INTO queue_places (job_id, account, expires_at) VALUES ($1, $2, $3)
             ON CONFLICT (job_id) DO UPDATE SET expires_at = excluded.expires_at",
            &[&job_id, &account, &until],
        )
        .await?;
        tx.commit().await?;
        Ok(Ok(()))
    }

    async fn release_queue_place(&self, job_id: &str) -> Result<(), StoreError> {
        let client = self.pool.get().await?;
        client
            .execute("DELETE FROM queue_places WHERE job_id = $1", &[&job_id])
            .await?;
        Ok(())
    }

    async fn uploads_idle_before(&self, before: i64) -> Result<Vec<String>, StoreError> {
        let client = self.pool.get().await?;
        let rows = client
            .query("SELECT id FROM uploads WHERE updated_at < $1", &[&before])
            .await?;
        rows.iter()
            .map(|row| row.try_get(0).map_err(StoreError::from))
            .collect()
    }

    async fn counts(&self, account: Option<&str>) -> Result<QueueCounts, StoreError> {
        let client = self.pool.get().await?;
        let row = client
            .query_one(
                "SELECT count(*) FILTER (WHERE state = 'queued'),
                        count(*) FILTER (WHERE state = 'running')
                 FROM jobs WHERE state IN ('queued', 'running')
                 AND ($1::TEXT IS NULL OR account = $1)",
                &[&account],
            )
            .await?;
        Ok(QueueCounts {
            queued: row.try_get::<_, i64>(0)?.max(0) as u64,
            running: row.try_get::<_, i64>(1)?.max(0) as u64,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_job_column_count_is_the_columns_named() {
        assert_eq!(JOB_COLUMNS.split(',').count(), JOB_COLUMN_COUNT);
    }
}
