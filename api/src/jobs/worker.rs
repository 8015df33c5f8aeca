//! Workers: each is a tokio task that claims a job from the store, runs it on the blocking pool
//! (one thread per job) and records how it ended. Beside each running job a heartbeat task writes
//! its progress and extends its lease (at most every 100 ms while events arrive, at least every
//! third of the lease), and turns a cancel requested in the store into the job's cancel flag. One
//! reaper task requeues jobs whose lease expired (their process died).
//!
//! With a shared object store ([`crate::storage::bucket`]) a job's files travel through it: before
//! running, a worker fetches the capture (or a relight's inputs and its parent's model) that its
//! own data dir lacks, and, when it resumes a job, the job's model folder with the latest
//! checkpoint; every checkpoint it writes is uploaded, so a worker on another machine continues
//! where this one stopped. A store that cannot be reached puts the job back in the queue instead of
//! failing it.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use phygap::core::events::{Stage, TrainEvent};
use tokio::sync::Notify;
use tokio::task::JoinHandle;
use tokio_util::sync::CancellationToken;
use tracing::Instrument;

use crate::jobs::pipeline_seam::PipelineError;
use crate::jobs::queue::{CancelReason, JobControl};
use crate::jobs::state::AppState;
use crate::storage::object_keys;
use crate::storage::store::{now_ms, Finish, JobRecord, JobSpec, Progress, StoreError};

/// Starts the configured workers and the lease reaper.
pub fn spawn(state: &AppState) -> Vec<JoinHandle<()>> {
    let mut tasks: Vec<JoinHandle<()>> = (0..state.config.workers)
        .map(|index| tokio::spawn(worker_loop(state.clone(), index)))
        .collect();
    tasks.push(tokio::spawn(reaper_loop(state.clone())));
    tasks
}

fn lease_deadline(state: &AppState) -> i64 {
    now_ms() + state.config.lease.as_millis() as i64
}

async fn worker_loop(state: AppState, index: usize) {
    // The accounts' running limits, fixed for the process's life.
    let running_limits = state.config.quotas().running();
    loop {
        if state.shutdown.is_cancelled() {
            break;
        }
        let wake = state.runtime.wake().notified();
        tokio::pin!(wake);
        wake.as_mut().enable();
        match state
            .store
            .claim_within(
                state.runtime.owner(),
                now_ms(),
                lease_deadline(&state),
                &running_limits,
            )
            .await
        {
            Ok(Some(job)) => {
                let span = tracing::info_span!("job", job_id = %job.id, kind = job.spec.kind(), worker = index);
                run_job(&state, job, span.clone()).instrument(span).await;
                continue;
            }
            Ok(None) => {}
            Err(e) => tracing::error!(error = %e, "claiming a job failed"),
        }
        tokio::select! {
            _ = state.shutdown.cancelled() => break,
            _ = &mut wake => {}
            _ = tokio::time::sleep(state.config.poll_interval) => {}
        }
    }
}

async fn reaper_loop(state: AppState) {
    let period = (state.config.lease / 4).max(Duration::from_millis(100));
    loop {
        match state
            .store
            .requeue_expired(now_ms(), state.config.max_attempts)
            .await
        {
            Ok(ids) if !ids.is_empty() => {
                for id in &ids {
                    tracing::warn!(job_id = %id, "lease expired (worker died): job requeued");
                    state.runtime.changed(id);
                }
                state.runtime.wake_workers();
            }
            Ok(_) => {}
            Err(e) => tracing::error!(error = %e, "requeueing expired jobs failed"),
        }
        tokio::select! {
            _ = state.shutdown.cancelled() => break,
            _ = tokio::time::sleep(period) => {}
        }
    }
}

/// How the blocking part of a job ended.
enum Executed {
    Completed,
    Interrupted,
    /// The shared object store could not be reached: the job goes back to the queue.
    StorageUnavailable(String),
    /// The job's process died (`reason` is the death's code).
    Died {
        reason: &'static str,
        message: String,
    },
}

/// Why the blocking part of a job stopped early.
enum Stop {
    /// The job's own failure: a stable code and a message for its `error` field.
    Failed { code: &'static str, message: String },
    /// The shared object store could not be reached.
    Storage(crate::storage::bucket::BucketError),
    /// The job's process died.
    Died {
        reason: &'static str,
        message: String,
    },
}

impl Stop {
    /// A failure of the service's own doing around the job (files, folders).
    fn internal(message: String) -> Stop {
        Stop::Failed {
            code: "internal",
            message,
        }
    }
}

impl From<crate::storage::bucket::BucketError> for Stop {
    fn from(e: crate::storage::bucket::BucketError) -> Self {
        Stop::Storage(e)
    }
}

impl From<PipelineError> for Stop {
    fn from(e: PipelineError) -> Self {
        let code = match &e {
            PipelineError::InvalidCapture { .. } => "invalid_capture",
            PipelineError::CaptureTooLarge { .. } => "capture_too_large",
            PipelineError::InvalidInput(_) => "invalid_input",
            PipelineError::Failed { stage, .. } => match stage.as_str() {
                "training" => "training_failed",
                "export" => "export_failed",
                "relighting" => "relighting_failed",
                _ => "failed",
            },
            PipelineError::Died { reason, .. } => {
                return Stop::Died {
                    reason: reason.code(),
                    message: e.to_string(),
                }
            }
        };
        Stop::Failed {
            code,
            message: e.to_string(),
        }
    }
}

/// Runs an object-store transfer from a job's blocking thread.
fn block_on<F: std::future::Future>(future: F) -> F::Output {
    tokio::runtime::Handle::current().block_on(future)
}

/// Shared between the blocking job thread and its heartbeat task.
struct Live {
    progress: Mutex<Progress>,
    /// Events not yet recorded in the store (JSON), with the number the first of them gets.
    events: Mutex<(u64, Vec<String>)>,
    dirty: Notify,
}

impl Live {
    fn update(&self, f: impl FnOnce(&mut Progress)) {
        if let Ok(mut progress) = self.progress.lock() {
            f(&mut progress);
        }
        self.dirty.notify_one();
    }

    /// Folds a training event into the progress and queues it for the job's history.
    fn record(&self, event: &TrainEvent) {
        if let (Ok(mut events), Ok(json)) = (self.events.lock(), serde_json::to_string(event)) {
            events.1.push(json);
        }
        self.update(|p| apply_event(p, event));
    }

    /// The events to record, with the number of the first; they count as recorded from now.
    fn take_events(&self) -> (u64, Vec<String>) {
        match self.events.lock() {
            Ok(mut events) => {
                let taken = std::mem::take(&mut events.1);
                let first = events.0;
                events.0 += taken.len() as u64;
                (first, taken)
            }
            Err(_) => (0, Vec::new()),
        }
    }

    fn snapshot(&self) -> Progress {
        self.progress.lock().map(|p| p.clone()).unwrap_or_default()
    }
}

fn stage_name(stage: Stage) -> &'static str {
    match stage {
        Stage::Geometry => "geometry",
        Stage::Material => "material",
        Stage::Polar => "polar",
    }
}

/// Folds a training event into the job's progress.
pub fn apply_event(progress: &mut Progress, event: &TrainEvent) {
    match event {
        TrainEvent::Started {
            iterations,
            resumed_from,
            backend,
            resolution,
            ..
        } => {
            progress.iterations = *iterations;
            progress.iteration = resumed_from.unwrap_or(0);
            progress.resumed_from = *resumed_from;
            progress.backend = Some(backend.clone());
            progress.resolution = Some(resolution.clone()).filter(|r| !r.is_empty());
            // A new process: its peak starts over.
            progress.peak_rss_bytes = None;
        }
        TrainEvent::Step {
            iteration,
            iterations,
            stage,
            loss,
            losses,
            eta_seconds,
            peak_rss_bytes,
            ..
        } => {
            progress.iteration = *iteration;
            progress.iterations = *iterations;
            progress.stage = Some(stage_name(*stage).to_owned());
            progress.losses = losses.clone();
            progress.losses.insert("total".into(), *loss);
            progress.eta_seconds = Some(*eta_seconds);
            progress.peak_rss_bytes = peak_rss_bytes.or(progress.peak_rss_bytes);
        }
        TrainEvent::Evaluated { test_psnr, .. } => progress.test_psnr = Some(*test_psnr),
        TrainEvent::Checkpoint { iteration } => progress.checkpoint_iteration = Some(*iteration),
        // Kept in the job's event history, which the progress pages give.
        TrainEvent::Decided { .. } => {}
        TrainEvent::Warning { iteration, message } => {
            progress.warning = Some(format!("iteration {iteration}: {message}"));
        }
        TrainEvent::Finished {
            iteration,
            peak_rss_bytes,
            ..
        } => {
            progress.iteration = *iteration;
            progress.eta_seconds = Some(0.0);
            progress.peak_rss_bytes = peak_rss_bytes.or(progress.peak_rss_bytes);
        }
    }
}

async fn run_job(state: &AppState, job: JobRecord, span: tracing::Span) {
    let started = Instant::now();
    let control = state.runtime.register(&job.id);
    if state.shutdown.is_cancelled() {
        control.cancel(CancelReason::Shutdown);
    }
    if job.cancel_requested {
        control.cancel(CancelReason::User);
    }
    tracing::info!(attempt = job.attempts, "job started");
    // The run's events follow the job's earlier runs' in its history.
    let first_event = match state.store.next_event_seq(&job.id).await {
        Ok(seq) => seq,
        Err(e) => {
            tracing::warn!(error = %e, "reading the job's history failed");
            0
        }
    };
    let live = Arc::new(Live {
        progress: Mutex::new(Progress {
            stage: Some("starting".into()),
            ..job.progress.clone()
        }),
        events: Mutex::new((first_event, Vec::new())),
        dirty: Notify::new(),
    });
    let done = CancellationToken::new();
    if let Some(limit) = job.max_runtime_seconds {
        tokio::spawn(stop_at_time_limit(
            Duration::from_secs(limit),
            control.clone(),
            done.clone(),
        ));
    }
    let heartbeat = tokio::spawn(
        heartbeat_loop(
            state.clone(),
            job.id.clone(),
            live.clone(),
            control.clone(),
            done.clone(),
        )
        .instrument(span.clone()),
    );
    let result = {
        let (state, job, control, live) =
            (state.clone(), job.clone(), control.clone(), live.clone());
        tokio::task::spawn_blocking(move || {
            let _entered = span.enter();
            execute(&state, &job, &control, &live)
        })
        .await
    };
    let finish = match result {
        Ok(Ok(Executed::Completed)) => {
            live.update(|p| p.stage = Some("done".into()));
            Some(Finish::Succeeded)
        }
        Ok(Ok(Executed::StorageUnavailable(message))) => {
            tracing::warn!(error = %message, "object store unavailable; job requeued");
            Some(Finish::Requeue)
        }
        Ok(Ok(Executed::Interrupted)) => match control.reason() {
            Some(CancelReason::User) => Some(Finish::Cancelled),
            Some(CancelReason::TimeLimit) => Some(past_time_limit(&job, true)),
            Some(CancelReason::LeaseLost) => None,
            Some(CancelReason::Shutdown) | None => Some(Finish::Requeue),
        },
        Ok(Ok(Executed::Died { reason, message })) => match control.reason() {
            // Stopped on purpose (a cancel or shutdown the process could not answer in time).
            Some(CancelReason::User) => Some(Finish::Cancelled),
            Some(CancelReason::TimeLimit) => Some(past_time_limit(&job, false)),
            Some(CancelReason::LeaseLost) => None,
            Some(CancelReason::Shutdown) => Some(Finish::Requeue),
            None => Some(Finish::Died { reason, message }),
        },
        Ok(Err((code, message))) => Some(Finish::Failed { code, message }),
        Err(join_error) => Some(Finish::Failed {
            code: "internal",
            message: format!("the job panicked: {join_error}"),
        }),
    };
    done.cancel();
    if let Err(e) = heartbeat.await {
        tracing::error!(error = %e, "heartbeat task ended abnormally");
    }
    let outcome = match &finish {
        Some(Finish::Succeeded) => "succeeded",
        Some(Finish::Failed { .. }) => "failed",
        Some(Finish::Cancelled) => "cancelled",
        Some(Finish::Requeue) => "requeued",
        Some(Finish::Died { .. }) => "died",
        None => "lease_lost",
    };
    if let Some(finish) = &finish {
        match state
            .store
            .finish(&job.id, state.runtime.owner(), finish, now_ms())
            .await
        {
            Ok(()) => {}
            Err(StoreError::LeaseLost(_)) => {
                tracing::warn!("lease lost before the job could be recorded as {outcome}")
            }
            Err(e) => tracing::error!(error = %e, "recording the job's end failed"),
        }
    }
    match &finish {
        Some(Finish::Failed { code, message }) => {
            tracing::warn!(code, error = %message, "job failed")
        }
        Some(Finish::Died { reason, message }) => {
            tracing::warn!(reason, error = %message, "the job's process died")
        }
        _ => {}
    }
    tracing::info!(
        outcome,
        seconds = started.elapsed().as_secs_f64(),
        "job run ended"
    );
    state
        .metrics
        .observe_job(job.spec.kind(), outcome, started.elapsed());
    state.runtime.unregister(&job.id);
    state.runtime.changed(&job.id);
}

/// Raises the job's cancel flag (as [`CancelReason::TimeLimit`]) when `limit` has passed,
/// unless the job ended first.
async fn stop_at_time_limit(limit: Duration, control: Arc<JobControl>, done: CancellationToken) {
    tokio::select! {
        _ = tokio::time::sleep(limit) => {
            tracing::warn!(seconds = limit.as_secs(), "the job ran past its time limit; stopping it");
            control.cancel(CancelReason::TimeLimit);
        }
        _ = done.cancelled() => {}
    }
}

/// How a job stopped at its own time limit ends: failed `time_limit`, resumable by a restart
/// when it checkpointed first.
fn past_time_limit(job: &JobRecord, checkpointed: bool) -> Finish {
    let seconds = job.max_runtime_seconds.unwrap_or_default();
    let after = if checkpointed {
        format!(
            "; its model was checkpointed (POST /v1/jobs/{}/restart goes on from there)",
            job.id
        )
    } else {
        String::new()
    };
    Finish::Failed {
        code: "time_limit",
        message: format!("the job ran past its max_runtime_seconds of {seconds} s{after}"),
    }
}

async fn heartbeat_loop(
    state: AppState,
    job_id: String,
    live: Arc<Live>,
    control: Arc<JobControl>,
    done: CancellationToken,
) {
    let beat = (state.config.lease / 3).max(Duration::from_millis(50));
    loop {
        let last = tokio::select! {
            biased;
            _ = done.cancelled() => true,
            _ = live.dirty.notified() => false,
            _ = tokio::time::sleep(beat) => false,
        };
        let progress = live.snapshot();
        let (first, events) = live.take_events();
        if !events.is_empty() {
            if let Err(e) = state.store.append_events(&job_id, first, &events).await {
                tracing::warn!(error = %e, "recording progress events failed");
            }
        }
        match state
            .store
            .heartbeat(
                &job_id,
                state.runtime.owner(),
                &progress,
                lease_deadline(&state),
            )
            .await
        {
            Ok(true) => control.cancel(CancelReason::User),
            Ok(false) => {}
            Err(StoreError::LeaseLost(_)) => {
                if !last {
                    tracing::error!("lease lost: another worker owns this job now; stopping");
                }
                control.cancel(CancelReason::LeaseLost);
            }
            Err(e) => tracing::error!(error = %e, "heartbeat failed"),
        }
        state.runtime.changed(&job_id);
        if last {
            break;
        }
        tokio::select! {
            _ = done.cancelled() => {}
            _ = tokio::time::sleep(Duration::from_millis(100)) => {}
        }
    }
}

fn replace_dir(dir: &std::path::Path) -> Result<(), Stop> {
    if dir.exists() {
        std::fs::remove_dir_all(dir)
            .map_err(|e| Stop::internal(format!("clearing a folder: {e}")))?;
    }
    std::fs::create_dir_all(dir).map_err(|e| Stop::internal(format!("creating a folder: {e}")))
}

/// The blocking body of a job. Errors are a code and a message for the job's `error` fields.
fn execute(
    state: &AppState,
    job: &JobRecord,
    control: &JobControl,
    live: &Live,
) -> Result<Executed, (&'static str, String)> {
    match execute_steps(state, job, control, live) {
        Ok(executed) => Ok(executed),
        Err(Stop::Failed { code, message }) => Err((code, message)),
        Err(Stop::Storage(e)) => Ok(Executed::StorageUnavailable(e.to_string())),
        Err(Stop::Died { reason, message }) => Ok(Executed::Died { reason, message }),
    }
}

/// Fetches `folder` of the object store into `dir` unless `dir` already exists (or the
/// deployment has no object store).
fn fetch_missing(state: &AppState, folder: &str, dir: &std::path::Path) -> Result<(), Stop> {
    match &state.bucket {
        Some(bucket) if !dir.is_dir() => {
            let files = block_on(bucket.download_dir(folder, dir))?;
            tracing::info!(folder, files, "fetched from the object store");
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Uploads a job's model folder (its checkpoint) to the object store, if there is one.
fn upload_model(state: &AppState, job_id: &str, model_dir: &std::path::Path) -> Result<(), Stop> {
    if let Some(bucket) = &state.bucket {
        block_on(bucket.upload_dir(&object_keys::job_model(job_id), model_dir))?;
    }
    Ok(())
}

fn execute_steps(
    state: &AppState,
    job: &JobRecord,
    control: &JobControl,
    live: &Live,
) -> Result<Executed, Stop> {
    let paths = &state.paths;
    let staging = paths.staging_dir(&job.id);
    match &job.spec {
        JobSpec::Train { config } => {
            let capture_dir = paths.capture_dir(&job.capture_id);
            fetch_missing(state, &object_keys::capture(&job.capture_id), &capture_dir)?;
            if !capture_dir.is_dir() {
                return Err(Stop::Failed {
                    code: "capture_missing",
                    message: format!("capture `{}` no longer exists", job.capture_id),
                });
            }
            let model_dir = paths.model_dir(&job.id);
            let resume = job.attempts > 1;
            if let (true, Some(bucket)) = (resume, &state.bucket) {
                // The object store holds the latest checkpoint, wherever the job ran before.
                let files =
                    block_on(bucket.download_dir(&object_keys::job_model(&job.id), &model_dir))?;
                tracing::info!(files, "fetched the job's checkpoint from the object store");
            }
            std::fs::create_dir_all(&model_dir)
                .map_err(|e| Stop::internal(format!("creating the model folder: {e}")))?;
            let mut on_event = |event: &TrainEvent| {
                live.record(event);
                if let TrainEvent::Checkpoint { iteration } = event {
                    if let Err(Stop::Storage(e)) = upload_model(state, &job.id, &model_dir) {
                        // The next checkpoint tries again; a resume starts from the last upload.
                        tracing::warn!(iteration, error = %e, "checkpoint not uploaded");
                    }
                }
            };
            let outcome = state.pipeline.train(
                &capture_dir,
                &model_dir,
                config,
                resume,
                &control.cancel,
                &mut on_event,
            )?;
            // The final (or interrupted) state, for a resume or a relight on another machine.
            upload_model(state, &job.id, &model_dir)?;
            if let crate::jobs::pipeline_seam::RunOutcome::Interrupted { iteration } = outcome {
                tracing::info!(iteration, reason = ?control.reason(), "training interrupted at a checkpoint");
                return Ok(Executed::Interrupted);
            }
            live.update(|p| p.stage = Some("exporting".into()));
            replace_dir(&staging)?;
            state
                .pipeline
                .export(&model_dir, Some(&capture_dir), &staging)?;
            // What the export went without (a mesh that could not be extracted) shows on the job.
            for message in phygap::pipeline::export::warnings(&staging) {
                let iteration = live.progress.lock().map_or(0, |p| p.iteration);
                live.record(&TrainEvent::Warning { iteration, message });
            }
        }
        JobSpec::Relight {
            parent_job_id,
            envmap_file,
            cameras_file,
            rotate_deg,
        } => {
            if control.cancel.load(std::sync::atomic::Ordering::SeqCst) {
                return Ok(Executed::Interrupted);
            }
            live.update(|p| p.stage = Some("relighting".into()));
            let input = paths.input_dir(&job.id);
            fetch_missing(state, &object_keys::job_input(&job.id), &input)?;
            let parent_model = paths.model_dir(parent_job_id);
            fetch_missing(state, &object_keys::job_model(parent_job_id), &parent_model)?;
            let cameras = cameras_file.as_ref().map(|name| input.join(name));
            replace_dir(&staging)?;
            state.pipeline.relight(
                &parent_model,
                &input.join(envmap_file),
                cameras.as_deref(),
                &staging,
                *rotate_deg,
            )?;
        }
    }
    let published = match block_on(state.artifacts.publish(&job.id, &staging)) {
        Ok(published) => published,
        Err(crate::storage::artifacts::ArtifactError::Bucket(e)) => return Err(e.into()),
        Err(e) => return Err(Stop::internal(format!("publishing the artifacts: {e}"))),
    };
    let _ = std::fs::remove_dir_all(&staging);
    tracing::info!(artifacts = published.len(), "artifacts published");
    Ok(Executed::Completed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[test]
    fn events_fold_into_progress() {
        // An earlier attempt's peak: a new run (a new process) starts it over.
        let mut p = Progress {
            peak_rss_bytes: Some(900),
            ..Progress::default()
        };
        apply_event(
            &mut p,
            &TrainEvent::Started {
                iterations: 300,
                mode: "full".into(),
                backend: "cpu (2 threads)".into(),
                train_views: 7,
                test_views: 1,
                resumed_from: Some(100),
                resolution: "306×256 (1224×1024 ÷ 4)".into(),
                radiance_scale: 0.5,
            },
        );
        assert_eq!(p.resolution.as_deref(), Some("306×256 (1224×1024 ÷ 4)"));
        assert_eq!(
            (p.iteration, p.iterations, p.resumed_from),
            (100, 300, Some(100))
        );
        assert_eq!(p.backend.as_deref(), Some("cpu (2 threads)"));
        assert_eq!(p.peak_rss_bytes, None);
        apply_event(
            &mut p,
            &TrainEvent::Step {
                iteration: 150,
                iterations: 300,
                stage: Stage::Material,
                loss: 0.5,
                losses: BTreeMap::from([("l1".to_string(), 0.25)]),
                num_surfels: 10,
                elapsed_seconds: 1.0,
                eta_seconds: 2.0,
                peak_rss_bytes: Some(500),
            },
        );
        assert_eq!(p.peak_rss_bytes, Some(500));
        assert_eq!(p.stage.as_deref(), Some("material"));
        assert_eq!(p.losses.get("total"), Some(&0.5));
        assert_eq!(p.losses.get("l1"), Some(&0.25));
        apply_event(
            &mut p,
            &TrainEvent::Evaluated {
                iteration: 150,
                test_psnr: 27.5,
            },
        );
        apply_event(&mut p, &TrainEvent::Checkpoint { iteration: 150 });
        apply_event(
            &mut p,
            &TrainEvent::Warning {
                iteration: 160,
                message: "GridMap mesh extraction failed".into(),
            },
        );
        assert_eq!(
            p.warning.as_deref(),
            Some("iteration 160: GridMap mesh extraction failed")
        );
        assert_eq!(
            (p.test_psnr, p.checkpoint_iteration),
            (Some(27.5), Some(150))
        );
        apply_event(
            &mut p,
            &TrainEvent::Finished {
                iteration: 300,
                seconds: 3.0,
                peak_rss_bytes: Some(700),
            },
        );
        assert_eq!((p.iteration, p.eta_seconds), (300, Some(0.0)));
        assert_eq!(p.peak_rss_bytes, Some(700));
        // A system that does not say keeps the last figure.
        apply_event(
            &mut p,
            &TrainEvent::Finished {
                iteration: 300,
                seconds: 3.0,
                peak_rss_bytes: None,
            },
        );
        assert_eq!(p.peak_rss_bytes, Some(700));
    }
}
