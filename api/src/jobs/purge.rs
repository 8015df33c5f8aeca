//! Removing captures and jobs together with everything stored for them — records, extracted
//! captures, relight inputs, checkpoints, artifacts, in the data dir and in the object store —
//! on request (`DELETE`) and by the retention sweeper, which removes jobs that ended more than
//! `--retention-days` ago and captures that old that no job uses any more, and resumable uploads
//! idle for `--upload-expiry-hours` ([`sweep_idle`]).

use std::time::Duration;

use thiserror::Error;
use tokio::task::JoinHandle;

use crate::jobs::state::AppState;
use crate::storage::artifacts::ArtifactError;
use crate::storage::bucket::BucketError;
use crate::storage::object_keys;
use crate::storage::store::{now_ms, DeleteOutcome, StoreError};
use crate::storage::upload_parts::PartStorage;

/// A removal that could not be completed (the record may already be gone: the files are then
/// removed by the next attempt of the sweeper, or are unreachable leftovers).
#[derive(Debug, Error)]
pub enum PurgeError {
    #[error(transparent)]
    Store(#[from] StoreError),
    #[error(transparent)]
    Artifacts(#[from] ArtifactError),
    #[error(transparent)]
    Bucket(#[from] BucketError),
    #[error("removing `{path}`: {source}")]
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
}

async fn remove_local(dir: std::path::PathBuf) -> Result<(), PurgeError> {
    match tokio::fs::remove_dir_all(&dir).await {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(PurgeError::Io {
            path: dir,
            source: e,
        }),
        _ => Ok(()),
    }
}

/// Deletes an ended job's record, then its artifacts, checkpoints and inputs.
pub async fn delete_job(state: &AppState, id: &str) -> Result<DeleteOutcome, PurgeError> {
    let outcome = state.store.delete_job(id).await?;
    if outcome == DeleteOutcome::Deleted {
        state.artifacts.delete(id).await?;
        if let Some(bucket) = &state.bucket {
            bucket.delete_folder(&object_keys::job(id)).await?;
        }
        remove_local(state.paths.jobs.join(id)).await?;
        tracing::info!(job_id = id, "job deleted");
    }
    Ok(outcome)
}

/// Deletes a capture's record unless a queued or running job uses it, then its files.
pub async fn delete_capture(state: &AppState, id: &str) -> Result<DeleteOutcome, PurgeError> {
    let outcome = state.store.delete_capture(id).await?;
    if outcome == DeleteOutcome::Deleted {
        if let Some(bucket) = &state.bucket {
            bucket.delete_folder(&object_keys::capture(id)).await?;
        }
        remove_local(state.paths.capture_dir(id)).await?;
        tracing::info!(capture_id = id, "capture deleted");
    }
    Ok(outcome)
}

/// One pass of the retention policy at `now` (unix ms): returns how many jobs and captures went.
pub async fn sweep(
    state: &AppState,
    retention: Duration,
    now: i64,
) -> Result<(usize, usize), PurgeError> {
    let before = now.saturating_sub(i64::try_from(retention.as_millis()).unwrap_or(i64::MAX));
    let mut jobs = 0;
    for id in state.store.jobs_ended_before(before).await? {
        if delete_job(state, &id).await? == DeleteOutcome::Deleted {
            jobs += 1;
        }
    }
    let mut captures = 0;
    for id in state.store.unused_captures_before(before).await? {
        if delete_capture(state, &id).await? == DeleteOutcome::Deleted {
            captures += 1;
        }
    }
    Ok((jobs, captures))
}

/// Removes uploads (and their parts) untouched for longer than the service's upload expiry;
/// returns how many.
pub async fn sweep_idle(state: &AppState, now: i64) -> Result<usize, StoreError> {
    let expiry = i64::try_from(state.config.upload_expiry.as_millis()).unwrap_or(i64::MAX);
    let mut removed = 0;
    for id in state
        .store
        .uploads_idle_before(now.saturating_sub(expiry))
        .await?
    {
        if state.store.delete_upload(&id).await? {
            let parts = PartStorage {
                bucket: state.bucket.as_deref(),
                data_dir: &state.paths.root,
            };
            parts.discard_all(&id).await;
            removed += 1;
        }
    }
    Ok(removed)
}

/// The sweeper: a pass every `config.retention_sweep` until shutdown, removing idle uploads,
/// and old jobs and captures when there is a retention setting. Only processes serving the API
/// run it (they hold the uploads' parts when there is no object store).
pub fn spawn_sweeper(state: &AppState) -> Option<JoinHandle<()>> {
    if !state.config.api {
        return None;
    }
    let state = state.clone();
    Some(tokio::spawn(async move {
        loop {
            if let Some(retention) = state.config.retention {
                match sweep(&state, retention, now_ms()).await {
                    Ok((0, 0)) => {}
                    Ok((jobs, captures)) => tracing::info!(jobs, captures, "retention: removed"),
                    Err(e) => tracing::error!(error = %e, "retention sweep failed"),
                }
            }
            match sweep_idle(&state, now_ms()).await {
                Ok(0) => {}
                Ok(uploads) => tracing::info!(uploads, "idle uploads removed"),
                Err(e) => tracing::error!(error = %e, "sweeping idle uploads failed"),
            }
            tokio::select! {
                _ = state.shutdown.cancelled() => break,
                _ = tokio::time::sleep(state.config.retention_sweep) => {}
            }
        }
    }))
}
