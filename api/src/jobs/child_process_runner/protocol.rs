//! What the service and a job's process say to each other, one JSON object a line. The service
//! writes a [`Request`] on the child's standard input, then a `cancel` line when the job is to
//! checkpoint and stop (closing the input means the service is gone: the child exits at once,
//! writing nothing more). The child answers on its
//! standard output with [`Message`]s: events while it trains, then exactly one `done` or `error`.
//! Lines that are not messages (a library printing to stdout) are passed on as log lines.

use std::path::PathBuf;

use phygap::core::config::TrainConfig;
use phygap::core::events::TrainEvent;
use serde::{Deserialize, Serialize};

use crate::jobs::pipeline_seam::{CaptureInfo, Engines, PipelineError, RunOutcome};

/// The stage a job's process runs, with everything it needs (paths are absolute).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "stage", rename_all = "snake_case")]
pub enum Request {
    /// What this machine's engines are (`GET /v1/info`): adapters are probed in a job's process,
    /// so the service itself never loads a GPU driver.
    Describe,
    Inspect {
        capture_dir: PathBuf,
    },
    Train {
        capture_dir: PathBuf,
        model_dir: PathBuf,
        config: Box<TrainConfig>,
        resume: bool,
    },
    Export {
        model_dir: PathBuf,
        capture_dir: Option<PathBuf>,
        out_dir: PathBuf,
    },
    Relight {
        model_dir: PathBuf,
        envmap: PathBuf,
        cameras: Option<PathBuf>,
        out_dir: PathBuf,
        rotate_deg: f64,
    },
}

impl Request {
    /// The folders and files the request names, which its error messages name relative to.
    pub fn folders(&self) -> Vec<&std::path::Path> {
        match self {
            Request::Describe => Vec::new(),
            Request::Inspect { capture_dir } => vec![capture_dir],
            Request::Train {
                capture_dir,
                model_dir,
                ..
            } => vec![capture_dir, model_dir],
            Request::Export {
                model_dir,
                capture_dir,
                out_dir,
            } => {
                let mut folders = vec![model_dir.as_path(), out_dir.as_path()];
                folders.extend(capture_dir.as_deref());
                folders
            }
            Request::Relight {
                model_dir,
                envmap,
                cameras,
                out_dir,
                ..
            } => {
                let mut folders = vec![model_dir.as_path(), out_dir.as_path()];
                folders.extend(envmap.parent());
                folders.extend(cameras.as_deref().and_then(std::path::Path::parent));
                folders
            }
        }
    }

    /// The stage's name, for logs and failure messages.
    pub fn stage(&self) -> &'static str {
        match self {
            Request::Describe => "description",
            Request::Inspect { .. } => "validation",
            Request::Train { .. } => "training",
            Request::Export { .. } => "export",
            Request::Relight { .. } => "relighting",
        }
    }
}

/// What a stage returns when it succeeds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Answer {
    Described { engines: Engines },
    Inspected { info: CaptureInfo },
    Trained { outcome: RunOutcome },
    Files { files: Vec<PathBuf> },
}

/// One line from the child.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Message {
    /// A training event (forwarded to the job's progress as it happens).
    Event(TrainEvent),
    /// The stage finished.
    Done(Answer),
    /// The stage failed.
    Error(PipelineError),
}

/// What the service writes to ask the child to checkpoint and stop.
pub const CANCEL_LINE: &str = "cancel";

impl Message {
    /// The message a line holds, or `None` for any other output.
    pub fn parse(line: &str) -> Option<Message> {
        serde_json::from_str(line).ok()
    }

    /// The message as one line (without its newline).
    pub fn to_line(&self) -> String {
        // These types serialize to plain JSON objects (no maps with non-string keys).
        serde_json::to_string(self).unwrap_or_else(|e| {
            format!(r#"{{"error":{{"kind":"failed","stage":"protocol","message":"{e}"}}}}"#)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_round_trip_as_single_lines() {
        let messages = [
            Message::Event(TrainEvent::Checkpoint { iteration: 7 }),
            Message::Done(Answer::Trained {
                outcome: RunOutcome::Interrupted { iteration: 7 },
            }),
            Message::Done(Answer::Inspected {
                info: CaptureInfo {
                    views: 3,
                    kinds: vec!["stokes".into()],
                    warnings: vec![],
                    width: 8,
                    height: 6,
                },
            }),
            Message::Error(PipelineError::InvalidCapture {
                message: "bad".into(),
                problems: vec![phygap::io::capture::Problem::new("top level", "w", "no")],
            }),
            Message::Error(PipelineError::CaptureTooLarge {
                limit: "max_views".into(),
                message: "8000 views".into(),
            }),
        ];
        for message in messages {
            let line = message.to_line();
            assert!(!line.contains('\n'), "{line}");
            assert_eq!(Message::parse(&line), Some(message));
        }
        assert_eq!(Message::parse("progress 50%"), None);
        let request = Request::Train {
            capture_dir: "/c".into(),
            model_dir: "/m".into(),
            config: Box::default(),
            resume: true,
        };
        let text = serde_json::to_string(&request).unwrap();
        assert_eq!(serde_json::from_str::<Request>(&text).unwrap(), request);
    }
}
