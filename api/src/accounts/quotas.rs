//! Fair sharing between accounts: the checks the routes make before they accept work, against
//! what each account may hold and ask for ([`crate::accounts::limits`]: jobs running at once,
//! jobs queued, bytes stored, the priority of its jobs) and the server's longest job run time,
//! read through a [`Ledger`]. A check refuses with a [`Refusal`] ([`QuotaError`]). The admin is
//! held only to the server's bounds.
//!
//! Running jobs are limited where a worker claims (the store skips an account's queued jobs
//! while it runs its limit); queued jobs and storage where a request would add to them. Storage
//! is reserved, not just checked: a request writes a [`Reservation`] of the bytes it will keep
//! in the same store transaction as the check, before it keeps any, so concurrent uploads (in
//! one process or many on one database) cannot pass a quota together; a body without a
//! Content-Length reserves as it arrives and is cut off where it crosses the quota. A
//! reservation is released when its request ends (by then a recorded capture or upload counts
//! in its place), and one its process never released stops counting after a lease. Queued jobs
//! are reserved the same way: a submit, relight or restart holds a [`QueuePlace`] until its job
//! is in the queue.

use std::sync::Arc;
use std::time::Duration;

use thiserror::Error;

use crate::accounts::auth::Caller;
use crate::accounts::limits::{Quotas, PRIORITY_RANGE};
use crate::domain::refusal::{Refusal, RefusalKind};
use crate::storage::store::{now_ms, Reserved, Store, StoreError};

/// A check that refused, or a store that could not answer.
#[derive(Debug, Error)]
pub enum QuotaError {
    #[error(transparent)]
    Refused(#[from] Refusal),
    #[error(transparent)]
    Store(#[from] StoreError),
}

/// What the checks read and write: the store that holds the reservations, every account's
/// limits, and the longest run time the server allows a job.
pub struct Ledger {
    pub store: Arc<dyn Store>,
    pub quotas: Quotas,
    pub max_runtime: Option<Duration>,
}

/// How long a reservation counts unless released or renewed: longer than any upload takes.
const RESERVATION_LEASE_MS: i64 = 6 * 3600 * 1000;
/// Bytes a body without a Content-Length reserves at a time as it arrives.
const RESERVATION_STEP: u64 = 4 << 20;
const MIB: u64 = 1 << 20;

/// What a new job asks for, checked by [`admit_job`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JobRequestLimits {
    pub priority: i32,
    pub max_runtime_seconds: Option<u64>,
}

/// A place in an account's queue reserved for one job ([`admit_job`]), written in the store
/// transaction that checks `max_queued`, so concurrent submits cannot pass the limit together.
/// Dropping it releases it: by then its job is queued and counts instead, or was not submitted.
pub struct QueuePlace {
    store: Arc<dyn Store>,
    job_id: String,
}

impl Drop for QueuePlace {
    fn drop(&mut self) {
        let Ok(runtime) = tokio::runtime::Handle::try_current() else {
            return;
        };
        let (store, job_id) = (self.store.clone(), std::mem::take(&mut self.job_id));
        runtime.spawn(async move {
            if let Err(e) = store.release_queue_place(&job_id).await {
                // It stops counting when its job is queued, or when its lease ends.
                tracing::warn!(job_id, error = %e, "releasing a queue place failed");
            }
        });
    }
}

/// Whether `caller` may queue one more job, `job_id`, with these settings: the priority within
/// its bounds, the time limit within the server's, and room in its queue, where a place is
/// reserved for the job (hold the place until the job is submitted; `None`: no queue limit).
pub async fn admit_job(
    ledger: &Ledger,
    caller: &Caller,
    request: JobRequestLimits,
    job_id: &str,
) -> Result<Option<QueuePlace>, QuotaError> {
    let limits = caller.account().map(|a| ledger.quotas.of(a));
    let highest = limits
        .and_then(|l| l.max_priority)
        .unwrap_or(*PRIORITY_RANGE.end());
    if request.priority < *PRIORITY_RANGE.start() || request.priority > highest {
        return Err(Refusal::unprocessable(
            "priority_not_allowed",
            format!(
                "priority {} is outside the {} to {highest} this token may ask for",
                request.priority,
                PRIORITY_RANGE.start()
            ),
        )
        .into());
    }
    if let Some(seconds) = request.max_runtime_seconds {
        let server = ledger.max_runtime.map(|d| d.as_secs());
        if seconds == 0 || server.is_some_and(|s| seconds > s) {
            let bound = server.map_or("".into(), |s| format!(" and at most the server's {s}"));
            return Err(Refusal::unprocessable(
                "invalid_max_runtime",
                format!("max_runtime_seconds is at least 1{bound}, found {seconds}"),
            )
            .into());
        }
    }
    let (Some(account), Some(max_queued)) = (caller.account(), limits.and_then(|l| l.max_queued))
    else {
        return Ok(None);
    };
    let now = now_ms();
    let placed = ledger
        .store
        .reserve_queue_place(
            account,
            job_id,
            max_queued,
            now,
            now.saturating_add(RESERVATION_LEASE_MS),
        )
        .await?;
    if let Err(queued) = placed {
        return Err(Refusal::new(
            RefusalKind::TooMany,
            "queued_job_limit",
            format!(
                "account `{account}` has {queued} jobs queued (or being submitted), its limit; \
                 submit again when one starts"
            ),
        )
        .into());
    }
    Ok(Some(QueuePlace {
        store: ledger.store.clone(),
        job_id: job_id.to_owned(),
    }))
}

/// `bytes` in MiB as a person reads them: whole MiB bare, else with two decimals (`0.55`).
pub fn mib(bytes: u64) -> String {
    if bytes.is_multiple_of(MIB) {
        (bytes / MIB).to_string()
    } else {
        format!("{:.2}", bytes as f64 / MIB as f64)
    }
}

fn over_quota(account: &str, stored: u64, limit: u64, what: &str) -> QuotaError {
    QuotaError::Refused(Refusal::new(
        RefusalKind::Forbidden,
        "storage_quota_exceeded",
        format!(
            "account `{account}` stores {} MiB of its {} MiB; {what} (delete captures it no \
             longer needs)",
            mib(stored),
            mib(limit)
        ),
    ))
}

/// Storage reserved in the store for one capture or upload (`id`) while its bytes arrive,
/// written in the transaction that checks the account's quota. Dropping it releases it: by
/// then the capture or upload is recorded and counts instead, or it failed and its bytes are
/// free again.
pub struct Reservation {
    store: Arc<dyn Store>,
    id: String,
    account: String,
    limit: u64,
    /// Bytes reserved so far.
    granted: u64,
}

impl Reservation {
    /// An empty reservation for `id` in the account `caller` stores for, when that account has
    /// a storage limit.
    fn unreserved(ledger: &Ledger, caller: &Caller, id: &str) -> Option<Reservation> {
        let account = caller.account()?;
        let limit = ledger.quotas.of(account).max_storage_bytes?;
        Some(Reservation {
            store: ledger.store.clone(),
            id: id.to_owned(),
            account: account.to_owned(),
            limit,
            granted: 0,
        })
    }

    /// Reserves `bytes` for `id`, or refuses (403 `storage_quota_exceeded`) when they do not
    /// fit; `None` when `caller` has no storage limit.
    pub async fn exactly(
        ledger: &Ledger,
        caller: &Caller,
        id: &str,
        bytes: u64,
    ) -> Result<Option<Reservation>, QuotaError> {
        let Some(mut reservation) = Self::unreserved(ledger, caller, id) else {
            return Ok(None);
        };
        let reserved = reservation.reserve(bytes, false).await?;
        if reserved.granted < bytes {
            return Err(over_quota(
                &reservation.account,
                reserved.stored_bytes,
                reservation.limit,
                &format!("{} MiB more do not fit", mib(bytes)),
            ));
        }
        Ok(Some(reservation))
    }

    /// For a body of unknown length: reserves a first step (what fits of it), refusing at once
    /// an account with no room left; [`Reservation::cover`] reserves more as the body arrives.
    /// `None` when `caller` has no storage limit.
    pub async fn growing(
        ledger: &Ledger,
        caller: &Caller,
        id: &str,
    ) -> Result<Option<Reservation>, QuotaError> {
        let Some(mut reservation) = Self::unreserved(ledger, caller, id) else {
            return Ok(None);
        };
        let reserved = reservation.reserve(RESERVATION_STEP, true).await?;
        if reserved.granted == 0 {
            return Err(over_quota(
                &reservation.account,
                reserved.stored_bytes,
                reservation.limit,
                "nothing more fits",
            ));
        }
        Ok(Some(reservation))
    }

    /// Makes sure the `total` bytes received so far are reserved, reserving more as needed;
    /// 403 `storage_quota_exceeded` once they cross what the account has left.
    pub async fn cover(&mut self, total: u64) -> Result<(), QuotaError> {
        if total <= self.granted {
            return Ok(());
        }
        let want = (total - self.granted).max(RESERVATION_STEP);
        let reserved = self.reserve(want, true).await?;
        if total <= self.granted {
            return Ok(());
        }
        Err(over_quota(
            &self.account,
            reserved
                .stored_bytes
                .saturating_sub(self.granted - reserved.granted),
            self.limit,
            &format!(
                "this upload, sent without a Content-Length, passed what is left after {} MiB",
                mib(total)
            ),
        ))
    }

    async fn reserve(&mut self, bytes: u64, partial: bool) -> Result<Reserved, QuotaError> {
        let now = now_ms();
        let reserved = self
            .store
            .reserve_bytes(
                &self.account,
                &self.id,
                bytes,
                partial,
                self.limit,
                now,
                now.saturating_add(RESERVATION_LEASE_MS),
            )
            .await?;
        self.granted += reserved.granted;
        Ok(reserved)
    }
}

impl Drop for Reservation {
    fn drop(&mut self) {
        if self.granted == 0 {
            return;
        }
        let Ok(runtime) = tokio::runtime::Handle::try_current() else {
            return;
        };
        let (store, id) = (self.store.clone(), std::mem::take(&mut self.id));
        runtime.spawn(async move {
            if let Err(e) = store.release_reservation(&id).await {
                // It stops counting when its lease ends.
                tracing::warn!(id, error = %e, "releasing a storage reservation failed");
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_shown_in_mib_with_decimals_where_needed() {
        assert_eq!(mib(2 << 20), "2");
        assert_eq!(mib(0), "0");
        assert_eq!(mib(576_717), "0.55");
        assert_eq!(mib((3 << 20) + 1), "3.00");
    }
}
