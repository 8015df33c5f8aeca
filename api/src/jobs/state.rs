//! The state every handler and worker shares ([`AppState`]): the settings, the data dir's
//! folders, the job store, artifact storage and the object store, the pipeline, metrics, and
//! this process's side of the queue. Cheap to clone; built once by [`crate::Server::start`].

use std::sync::Arc;

use tokio_util::sync::CancellationToken;

use crate::accounts::quotas;
use crate::jobs::metrics::Metrics;
use crate::jobs::pipeline_seam::{self, Pipeline};
use crate::jobs::queue::Runtime;
use crate::jobs::settings::{Paths, ServiceConfig};
use crate::storage::artifacts::ArtifactStore;
use crate::storage::bucket::Bucket;
use crate::storage::store::Store;

/// Everything a handler or worker needs; cheap to clone.
#[derive(Clone)]
pub struct AppState {
    pub config: Arc<ServiceConfig>,
    pub paths: Arc<Paths>,
    pub store: Arc<dyn Store>,
    pub artifacts: Arc<dyn ArtifactStore>,
    /// The shared object store, where the deployment has one ([`crate::storage::bucket`]).
    pub bucket: Option<Arc<Bucket>>,
    pub pipeline: Arc<dyn Pipeline>,
    pub metrics: Arc<Metrics>,
    pub runtime: Arc<Runtime>,
    /// This machine's engines, probed once in a job's process on the first `GET /v1/info`.
    pub engines: Arc<tokio::sync::OnceCell<pipeline_seam::Engines>>,
    /// Cancelled when the server shuts down (stops workers claiming and ends event streams).
    pub shutdown: CancellationToken,
}

impl AppState {
    /// What the accounts' checks read and write ([`quotas::admit_job`], [`quotas::Reservation`]):
    /// the store, every account's limits and the server's longest job run time.
    pub fn ledger(&self) -> quotas::Ledger {
        quotas::Ledger {
            store: self.store.clone(),
            quotas: self.config.quotas(),
            max_runtime: self.config.limits.job.max_runtime,
        }
    }
}
