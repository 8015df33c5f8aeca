//! Above accounts and storage: the service at work — [`settings`] and [`state`] (what one
//! instance runs with and what its handlers and workers share), [`queue`] (this process's side of
//! the job queue) and [`worker`] (the workers), [`pipeline_seam`] (the `Pipeline` trait between
//! the service and the core) with its two runners, [`in_process_runner`] (the core called in
//! this process) and [`child_process_runner`] (each call in a child process of its own, the one
//! the service runs on), [`webhooks`] with [`webhook_targets`] and [`outbound`] (where they may
//! go), [`purge`] (removals and the retention sweeper) and [`metrics`].

pub mod child_process_runner;
pub mod in_process_runner;
pub mod metrics;
pub mod outbound;
pub mod pipeline_seam;
pub mod purge;
pub mod queue;
pub mod settings;
pub mod state;
pub mod webhook_targets;
pub mod webhooks;
pub mod worker;
