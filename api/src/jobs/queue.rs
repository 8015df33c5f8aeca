//! In-process side of the job queue: the cancel controls of the jobs this process runs, the owner
//! token that identifies this process in the store's leases, a wake-up for idle workers and a
//! change feed that event streams listen to. The durable side is in [`crate::storage::store`].

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
use std::sync::{Arc, Mutex};

use tokio::sync::{broadcast, Notify};

use crate::domain::ids::new_id;

/// Why a running job was asked to stop; the first reason given wins.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum CancelReason {
    /// `POST /v1/jobs/{id}/cancel`: the job ends `cancelled`.
    User = 1,
    /// The server is shutting down: the job checkpoints and goes back to the queue.
    Shutdown = 2,
    /// Another worker took over the job after this one's lease expired: stop without writing.
    LeaseLost = 3,
    /// The job ran past its own `max_runtime_seconds`: it checkpoints and fails `time_limit`.
    TimeLimit = 4,
}

/// The cancel flag handed to the pipeline, with the reason it was raised.
#[derive(Debug, Default)]
pub struct JobControl {
    pub cancel: AtomicBool,
    reason: AtomicU8,
}

impl JobControl {
    pub fn cancel(&self, reason: CancelReason) {
        let _ = self
            .reason
            .compare_exchange(0, reason as u8, Ordering::SeqCst, Ordering::SeqCst);
        self.cancel.store(true, Ordering::SeqCst);
    }

    pub fn reason(&self) -> Option<CancelReason> {
        match self.reason.load(Ordering::SeqCst) {
            1 => Some(CancelReason::User),
            2 => Some(CancelReason::Shutdown),
            3 => Some(CancelReason::LeaseLost),
            4 => Some(CancelReason::TimeLimit),
            _ => None,
        }
    }
}

/// Per-process queue state.
pub struct Runtime {
    owner: String,
    running: Mutex<HashMap<String, Arc<JobControl>>>,
    changes: broadcast::Sender<String>,
    wake: Notify,
}

impl Default for Runtime {
    fn default() -> Self {
        Self::new()
    }
}

impl Runtime {
    pub fn new() -> Self {
        Runtime {
            owner: new_id("owner"),
            running: Mutex::new(HashMap::new()),
            changes: broadcast::channel(1024).0,
            wake: Notify::new(),
        }
    }

    /// This process's lease owner token.
    pub fn owner(&self) -> &str {
        &self.owner
    }

    pub fn register(&self, job_id: &str) -> Arc<JobControl> {
        let control = Arc::new(JobControl::default());
        if let Ok(mut map) = self.running.lock() {
            map.insert(job_id.to_owned(), control.clone());
        }
        control
    }

    pub fn unregister(&self, job_id: &str) {
        if let Ok(mut map) = self.running.lock() {
            map.remove(job_id);
        }
    }

    /// Raises the cancel flag of a job running in this process; false if it runs elsewhere.
    pub fn cancel(&self, job_id: &str, reason: CancelReason) -> bool {
        let control = self
            .running
            .lock()
            .ok()
            .and_then(|map| map.get(job_id).cloned());
        match control {
            Some(control) => {
                control.cancel(reason);
                true
            }
            None => false,
        }
    }

    pub fn cancel_all(&self, reason: CancelReason) {
        if let Ok(map) = self.running.lock() {
            for control in map.values() {
                control.cancel(reason);
            }
        }
    }

    /// Tells event streams that `job_id` changed.
    pub fn changed(&self, job_id: &str) {
        let _ = self.changes.send(job_id.to_owned());
    }

    pub fn subscribe(&self) -> broadcast::Receiver<String> {
        self.changes.subscribe()
    }

    /// Wakes idle workers (a job was queued).
    pub fn wake_workers(&self) {
        self.wake.notify_waiters();
    }

    pub fn wake(&self) -> &Notify {
        &self.wake
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_cancel_reason_wins() {
        let control = JobControl::default();
        assert_eq!(control.reason(), None);
        control.cancel(CancelReason::User);
        control.cancel(CancelReason::Shutdown);
        assert!(control.cancel.load(Ordering::SeqCst));
        assert_eq!(control.reason(), Some(CancelReason::User));
    }

    #[test]
    fn ids_are_prefixed_and_distinct() {
        let a = new_id("job");
        assert!(a.starts_with("job_") && a.len() == 28, "{a}");
        assert_ne!(a, new_id("job"));
    }
}
