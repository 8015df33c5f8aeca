//! The child-process runner: jobs in processes of their own. [`ProcessPipeline`] is the
//! [`Pipeline`] the service runs on: each call (validating an upload, training, exporting,
//! relighting) starts `phygap-api stage` ([`child`]) with the job's limits, sends it the request
//! ([`protocol`]) and relays what it says. The child caps its own memory before reading anything;
//! the service holds the wall-clock limit and the thread count. Whatever an input makes the core do
//! (allocate 96 GB, abort, crash), only that process dies: the service reads why from its exit
//! status and answers with a [`PipelineError::Died`] naming the reason, and every other job and
//! request carries on.
//!
//! Threading: the calling (blocking) thread waits on a channel fed by one thread reading the
//! child's standard output; a second thread passes its standard error on to the service's own
//! (the child's logs) and notes an allocation failure announced there.

pub mod child;
pub mod protocol;

use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::{Duration, Instant};

use phygap::core::config::TrainConfig;
use phygap::core::events::TrainEvent;
use phygap::io::capture::CaptureLimits;

use self::protocol::{Answer, Message, Request, CANCEL_LINE};
use crate::jobs::pipeline_seam::{
    CaptureInfo, DeathReason, Engines, Pipeline, PipelineError, RunOutcome,
};
use crate::jobs::settings::{JobLimits, ServiceLimits};

/// Environment variables the job's process does not inherit: the service's secrets (the admin
/// token, the database and the object store's credentials); the child needs none of them.
const SECRET_VARIABLES: [&str; 6] = [
    "PHYGAP_TOKEN",
    "PHYGAP_DATABASE_URL",
    "PHYGAP_WEBHOOK_SECRET",
    "AWS_ACCESS_KEY_ID",
    "AWS_SECRET_ACCESS_KEY",
    "AWS_SESSION_TOKEN",
];

/// What Rust's default allocation-error handler prints before it aborts.
const ALLOCATION_FAILED: &str = "memory allocation of";

/// How often the waiting thread looks at the cancel flag and the clock.
const POLL: Duration = Duration::from_millis(50);

/// How long a child has to answer a cancel (it checkpoints at its next step) before it is
/// stopped: a stage still loading its capture or building its engine does not look at the flag,
/// and a user who pressed cancel expects the job to end.
const CANCEL_GRACE: Duration = Duration::from_secs(20);

/// Runs every stage in a child process: `executable stage …` (the `phygap-api` binary itself).
#[derive(Clone, Debug)]
pub struct ProcessPipeline {
    executable: PathBuf,
    limits: JobLimits,
    capture_limits: CaptureLimits,
    cancel_grace: Duration,
}

impl ProcessPipeline {
    pub fn new(executable: PathBuf, limits: JobLimits, capture_limits: CaptureLimits) -> Self {
        ProcessPipeline {
            executable,
            limits,
            capture_limits,
            cancel_grace: CANCEL_GRACE,
        }
    }

    /// The pipeline of a service with these limits, running `executable stage` (the
    /// `phygap-api` binary).
    pub fn for_service(executable: PathBuf, limits: &ServiceLimits) -> Self {
        Self::new(executable, limits.job, limits.capture)
    }

    /// The child's command line: the hidden `stage` subcommand with the limits as flags.
    fn command(&self) -> Command {
        let mut command = Command::new(&self.executable);
        command
            .arg("stage")
            .arg("--max-views")
            .arg(self.capture_limits.max_views.to_string())
            .arg("--max-pixels-per-view")
            .arg(self.capture_limits.max_pixels_per_view.to_string())
            .arg("--max-decoded-bytes")
            .arg(self.capture_limits.max_decoded_bytes.to_string());
        if let Some(bytes) = self.limits.memory_bytes {
            command.arg("--memory-bytes").arg(bytes.to_string());
        }
        if let Some(threads) = self.limits.threads {
            command.env("RAYON_NUM_THREADS", threads.to_string());
        }
        for name in SECRET_VARIABLES {
            command.env_remove(name);
        }
        if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
            // Mesa's device-select layer looks for a display server through XDG_RUNTIME_DIR and
            // prints an error on every adapter probe without one; a service has no display.
            command.env("NODEVICE_SELECT", "1");
        }
        command
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        command
    }

    /// Runs `request` in a child process until it answers or dies. Training events go to
    /// `on_event`; `cancel` is forwarded (the child checkpoints and answers).
    fn run(
        &self,
        request: &Request,
        cancel: Option<&AtomicBool>,
        on_event: &mut dyn FnMut(&TrainEvent),
    ) -> Result<Answer, PipelineError> {
        let stage = request.stage();
        let spawn_failed = |e: std::io::Error| PipelineError::Failed {
            stage: stage.to_owned(),
            message: format!("cannot start the job's process: {e}"),
        };
        let mut child = self.command().spawn().map_err(spawn_failed)?;
        let _span = tracing::info_span!("job_process", pid = child.id(), stage).entered();
        let log = relay_stderr(&mut child);
        let messages = read_messages(&mut child);
        let mut stdin = child.stdin.take();
        let request_line = serde_json::to_string(request).map_err(|e| PipelineError::Failed {
            stage: stage.to_owned(),
            message: format!("cannot encode the request: {e}"),
        })?;
        // A child that dies at once closes its input; its exit status says why, below.
        let _ = send_line(&mut stdin, &request_line);
        let deadline = self.limits.max_runtime.map(|limit| Instant::now() + limit);
        let mut answer = None;
        let mut cancel_sent_at: Option<Instant> = None;
        let mut stopped = false;
        let mut timed_out = false;
        loop {
            match messages.recv_timeout(POLL) {
                Ok(Message::Event(event)) => on_event(&event),
                Ok(Message::Done(done)) => answer = Some(Ok(done)),
                Ok(Message::Error(error)) => answer = Some(Err(error)),
                Err(RecvTimeoutError::Disconnected) => break,
                Err(RecvTimeoutError::Timeout) => {}
            }
            match cancel_sent_at {
                None if cancel.is_some_and(|c| c.load(Ordering::SeqCst)) => {
                    cancel_sent_at = Some(Instant::now());
                    let _ = send_line(&mut stdin, CANCEL_LINE);
                }
                Some(sent)
                    if !stopped && answer.is_none() && sent.elapsed() >= self.cancel_grace =>
                {
                    tracing::warn!("the job's process did not answer its cancel; stopping it");
                    stopped = true;
                    let _ = child.kill();
                }
                _ => {}
            }
            if deadline.is_some_and(|d| Instant::now() >= d) && !timed_out {
                timed_out = true;
                tracing::warn!("the job's process ran past its time limit; stopping it");
                let _ = child.kill();
            }
        }
        drop(stdin);
        let status = child.wait().map_err(|e| PipelineError::Failed {
            stage: stage.to_owned(),
            message: format!("waiting for the job's process: {e}"),
        })?;
        // The child has exited, so its standard error is at its end: every line is in.
        let last_words = log.and_then(|relay| relay.join().ok()).unwrap_or_default();
        match answer {
            Some(answer) if status.success() => answer,
            _ => {
                let reason = death_reason(status, timed_out, &last_words);
                let detail = describe_death(stage, reason, status, &last_words, self.limits);
                tracing::warn!(reason = reason.code(), %detail, "the job's process died");
                Err(PipelineError::Died { reason, detail })
            }
        }
    }
}

/// Writes one line to the child's input; `None` once it is closed.
fn send_line(stdin: &mut Option<ChildStdin>, line: &str) -> std::io::Result<()> {
    match stdin {
        Some(pipe) => writeln!(pipe, "{line}").and_then(|()| pipe.flush()),
        None => Err(std::io::ErrorKind::BrokenPipe.into()),
    }
}

/// What the child said on its standard error that tells how it died.
#[derive(Debug, Default)]
struct LastWords {
    /// Rust's `memory allocation of N bytes failed`, wherever it came (a backtrace may follow).
    allocation_failure: Option<String>,
}

/// Passes the child's standard error on to the service's; the thread ends with the child's
/// output and returns its [`LastWords`].
fn relay_stderr(child: &mut Child) -> Option<std::thread::JoinHandle<LastWords>> {
    let stderr = child.stderr.take()?;
    Some(std::thread::spawn(move || {
        let mut words = LastWords::default();
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            eprintln!("{line}");
            if words.allocation_failure.is_none() && line.contains(ALLOCATION_FAILED) {
                words.allocation_failure = Some(line.trim().to_owned());
            }
        }
        words
    }))
}

/// The child's messages, read line by line on a thread of their own; other lines are logged.
fn read_messages(child: &mut Child) -> mpsc::Receiver<Message> {
    let (sender, receiver) = mpsc::channel();
    if let Some(stdout) = child.stdout.take() {
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                match Message::parse(&line) {
                    Some(message) => {
                        if sender.send(message).is_err() {
                            break;
                        }
                    }
                    None => tracing::info!(target: "job_process", "{line}"),
                }
            }
        });
    }
    receiver
}

/// Why a child that gave no answer (or exited with a failure) ended.
fn death_reason(status: ExitStatus, timed_out: bool, last_words: &LastWords) -> DeathReason {
    use std::os::unix::process::ExitStatusExt;
    if timed_out {
        DeathReason::TimeLimit
    } else if last_words.allocation_failure.is_some() {
        DeathReason::OutOfMemory
    } else if status.signal() == Some(libc::SIGKILL) {
        DeathReason::Killed
    } else {
        DeathReason::Crashed
    }
}

/// The specifics of a death for the job's `error` (no paths: the child's own words are quoted
/// only for an allocation failure, which names a byte count).
fn describe_death(
    stage: &str,
    reason: DeathReason,
    status: ExitStatus,
    last_words: &LastWords,
    limits: JobLimits,
) -> String {
    use std::os::unix::process::ExitStatusExt;
    let how = match (status.signal(), status.code()) {
        (Some(signal), _) => format!("ended by signal {signal}"),
        (None, Some(code)) => format!("exited with status {code} without an answer"),
        (None, None) => "ended without an answer".to_owned(),
    };
    match reason {
        DeathReason::OutOfMemory => {
            let words = last_words
                .allocation_failure
                .as_deref()
                .unwrap_or("an allocation failed");
            match limits.memory_bytes {
                Some(bytes) => format!(
                    "{words} during {stage}; the job's memory limit is {} MiB",
                    bytes >> 20
                ),
                None => format!("{words} during {stage}"),
            }
        }
        DeathReason::TimeLimit => format!(
            "{stage} was stopped at the job's time limit of {} s",
            limits.max_runtime.unwrap_or_default().as_secs()
        ),
        DeathReason::Killed | DeathReason::Crashed => format!("{stage} {how}"),
    }
}

impl Pipeline for ProcessPipeline {
    /// Probed in a process of its own: the service never loads a GPU driver.
    fn engines(&self) -> Result<Engines, PipelineError> {
        match self.run(&Request::Describe, None, &mut |_| {})? {
            Answer::Described { engines } => Ok(engines),
            other => Err(unexpected(&Request::Describe, &other)),
        }
    }

    fn inspect(&self, capture_dir: &Path) -> Result<CaptureInfo, PipelineError> {
        let request = Request::Inspect {
            capture_dir: capture_dir.to_owned(),
        };
        match self.run(&request, None, &mut |_| {})? {
            Answer::Inspected { info } => Ok(info),
            other => Err(unexpected(&request, &other)),
        }
    }

    fn train(
        &self,
        capture_dir: &Path,
        model_dir: &Path,
        config: &TrainConfig,
        resume: bool,
        cancel: &AtomicBool,
        on_event: &mut dyn FnMut(&TrainEvent),
    ) -> Result<RunOutcome, PipelineError> {
        let request = Request::Train {
            capture_dir: capture_dir.to_owned(),
            model_dir: model_dir.to_owned(),
            config: Box::new(config.clone()),
            resume,
        };
        match self.run(&request, Some(cancel), on_event)? {
            Answer::Trained { outcome } => Ok(outcome),
            other => Err(unexpected(&request, &other)),
        }
    }

    fn export(
        &self,
        model_dir: &Path,
        capture_dir: Option<&Path>,
        out_dir: &Path,
    ) -> Result<Vec<PathBuf>, PipelineError> {
        let request = Request::Export {
            model_dir: model_dir.to_owned(),
            capture_dir: capture_dir.map(Path::to_owned),
            out_dir: out_dir.to_owned(),
        };
        match self.run(&request, None, &mut |_| {})? {
            Answer::Files { files } => Ok(files),
            other => Err(unexpected(&request, &other)),
        }
    }

    fn relight(
        &self,
        model_dir: &Path,
        envmap: &Path,
        cameras: Option<&Path>,
        out_dir: &Path,
        rotate_deg: f64,
    ) -> Result<Vec<PathBuf>, PipelineError> {
        let request = Request::Relight {
            model_dir: model_dir.to_owned(),
            envmap: envmap.to_owned(),
            cameras: cameras.map(Path::to_owned),
            out_dir: out_dir.to_owned(),
            rotate_deg,
        };
        match self.run(&request, None, &mut |_| {})? {
            Answer::Files { files } => Ok(files),
            other => Err(unexpected(&request, &other)),
        }
    }
}

/// A child that answered another stage's kind of result (a version mismatch).
fn unexpected(request: &Request, answer: &Answer) -> PipelineError {
    PipelineError::Failed {
        stage: request.stage().to_owned(),
        message: format!(
            "the job's process answered {answer:?} to a {} request",
            request.stage()
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::PermissionsExt;

    /// A child that reads its request and then neither answers nor looks at its input again.
    fn deaf_child(dir: &Path) -> PathBuf {
        let path = dir.join("deaf-stage");
        std::fs::write(&path, "#!/bin/sh\nread request\nexec sleep 600\n").unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
        path
    }

    #[test]
    fn a_child_deaf_to_its_cancel_is_stopped_after_the_grace() {
        let dir = tempfile::tempdir().unwrap();
        let mut pipeline = ProcessPipeline::new(
            deaf_child(dir.path()),
            JobLimits::NONE,
            CaptureLimits::DEFAULT,
        );
        pipeline.cancel_grace = Duration::from_millis(300);
        let cancel = AtomicBool::new(true);
        let started = Instant::now();
        let result = pipeline.train(
            dir.path(),
            dir.path(),
            &TrainConfig::default(),
            false,
            &cancel,
            &mut |_| {},
        );
        match result {
            Err(PipelineError::Died { reason, .. }) => assert_eq!(reason, DeathReason::Killed),
            other => panic!("expected the child killed, got {other:?}"),
        }
        // Stopped after the grace, long before the child's own 600 s.
        assert!(started.elapsed() < Duration::from_secs(60));
    }
}
