//! The job's side of [`crate::jobs::child_process_runner`]: `phygap-api stage` (hidden), the
//! process the service starts for each stage of a job. It caps its own memory first (`RLIMIT_DATA`,
//! before it reads anything), reads its [`Request`] from standard input, runs the stage on the core
//! ([`CorePipeline`]) and writes [`Message`]s to standard output. A `cancel` line raises the
//! training's cancel flag (it checkpoints and answers); the end of its input (the service is gone)
//! ends it at once.
//!
//! An allocation over the limit aborts this process, not the service; the service reads the
//! abort from the exit status and the message Rust prints (`memory allocation of N bytes
//! failed`) and fails the attempt as `out_of_memory`.

use std::io::{BufRead, Read, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use thiserror::Error;

use super::protocol::{Answer, Message, Request, CANCEL_LINE};
use crate::jobs::in_process_runner::CorePipeline;
use crate::jobs::pipeline_seam::{Pipeline, PipelineError};

/// Longest request line read (a training config is about 2 KB).
const MAX_REQUEST_BYTES: u64 = 1 << 20;

/// Why the stage could not even start.
#[derive(Debug, Error)]
pub enum StageError {
    #[error("setting the memory limit of {bytes} bytes: {source}")]
    MemoryLimit { bytes: u64, source: std::io::Error },
    #[error("reading the request: {0}")]
    Read(std::io::Error),
    #[error("the request is not a stage request: {0}")]
    Request(serde_json::Error),
    #[error("writing to the service: {0}")]
    Write(std::io::Error),
}

/// Caps this process's data segment and private writable mappings (the heap, whatever the
/// allocator) at `bytes`. Device memory a GPU driver maps is not counted.
pub fn limit_memory(bytes: u64) -> Result<(), StageError> {
    rlimit::setrlimit(rlimit::Resource::DATA, bytes, bytes)
        .map_err(|source| StageError::MemoryLimit { bytes, source })
}

/// Runs one stage as the service asked on standard input; the answer goes to standard output.
pub fn run(pipeline: &CorePipeline) -> Result<(), StageError> {
    let stdin = std::io::stdin();
    let mut line = String::new();
    stdin
        .lock()
        .take(MAX_REQUEST_BYTES)
        .read_line(&mut line)
        .map_err(StageError::Read)?;
    let request: Request = serde_json::from_str(&line).map_err(StageError::Request)?;
    let cancel = Arc::new(AtomicBool::new(false));
    watch_for_cancel(cancel.clone());
    let out = Arc::new(Mutex::new(std::io::stdout()));
    let send = |message: &Message| -> Result<(), StageError> {
        let mut out = out.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        writeln!(out, "{}", message.to_line())
            .and_then(|()| out.flush())
            .map_err(StageError::Write)
    };
    let stage = request.stage();
    let request_folders: Vec<std::path::PathBuf> = request
        .folders()
        .into_iter()
        .map(|p| p.to_owned())
        .collect();
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        execute(pipeline, request, &cancel, &mut |event| {
            // A closed output means the service is gone; the run still checkpoints and stops.
            if send(&Message::Event(event.clone())).is_err() {
                cancel.store(true, Ordering::SeqCst);
            }
        })
    }))
    .unwrap_or_else(|panic| {
        let detail = panic
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| panic.downcast_ref::<&str>().copied())
            .unwrap_or("a panic without a message");
        Err(PipelineError::Failed {
            stage: stage.to_owned(),
            message: format!("internal error: {detail}"),
        })
    });
    send(&match result {
        Ok(answer) => Message::Done(answer),
        Err(error) => {
            let folders: Vec<&std::path::Path> =
                request_folders.iter().map(|p| p.as_path()).collect();
            Message::Error(error.relative_to(&folders))
        }
    })
}

/// The exit status of a stage whose service went away.
const EXIT_SERVICE_GONE: i32 = 3;

/// Raises `cancel` on a `cancel` line; at the end of standard input (the service died, or was
/// killed) exits at once without writing anything more, as the service's own process would have:
/// the job resumes from its last periodic checkpoint wherever it is claimed next, and no orphan
/// writes beside the worker that takes it over.
fn watch_for_cancel(cancel: Arc<AtomicBool>) {
    std::thread::spawn(move || {
        let stdin = std::io::stdin();
        for line in stdin.lock().lines() {
            match line {
                Ok(line) if line.trim() == CANCEL_LINE => {
                    cancel.store(true, Ordering::SeqCst);
                }
                Ok(_) => continue,
                Err(_) => break,
            }
        }
        std::process::exit(EXIT_SERVICE_GONE);
    });
}

fn execute(
    pipeline: &CorePipeline,
    request: Request,
    cancel: &AtomicBool,
    on_event: &mut dyn FnMut(&phygap::core::events::TrainEvent),
) -> Result<Answer, PipelineError> {
    Ok(match request {
        Request::Describe => Answer::Described {
            engines: pipeline.engines()?,
        },
        Request::Inspect { capture_dir } => Answer::Inspected {
            info: pipeline.inspect(&capture_dir)?,
        },
        Request::Train {
            capture_dir,
            model_dir,
            config,
            resume,
        } => Answer::Trained {
            outcome: pipeline.train(&capture_dir, &model_dir, &config, resume, cancel, on_event)?,
        },
        Request::Export {
            model_dir,
            capture_dir,
            out_dir,
        } => Answer::Files {
            files: pipeline.export(&model_dir, capture_dir.as_deref(), &out_dir)?,
        },
        Request::Relight {
            model_dir,
            envmap,
            cameras,
            out_dir,
            rotate_deg,
        } => Answer::Files {
            files: pipeline.relight(
                &model_dir,
                &envmap,
                cameras.as_deref(),
                &out_dir,
                rotate_deg,
            )?,
        },
    })
}
