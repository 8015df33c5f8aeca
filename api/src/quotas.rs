//! Fair sharing between accounts: what each may hold and ask for (jobs running at once, jobs
//! queued, bytes stored, the priority of its jobs, a job's time limit), where the limits come
//! from (the tokens file's `key=value` words over the server's defaults) and the checks the
//! routes make before they accept work. The admin is held only to the server's bounds.
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

use std::collections::BTreeMap;

use axum::http::StatusCode;
use serde::Serialize;
use utoipa::ToSchema;

use crate::auth::Caller;
use crate::error::ApiError;
use crate::store::now_ms;
use crate::AppState;

/// How long a reservation counts unless released or renewed: longer than any upload takes.
const RESERVATION_LEASE_MS: i64 = 6 * 3600 * 1000;
/// Bytes a body without a Content-Length reserves at a time as it arrives.
const RESERVATION_STEP: u64 = 4 << 20;
const MIB: u64 = 1 << 20;

/// Lowest and highest priority a job may have; accounts are further held to their
/// `max_priority`.
pub const PRIORITY_RANGE: std::ops::RangeInclusive<i32> = -100..=100;

/// What one account may hold and ask for; `None`: no limit (priority: the server's default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, ToSchema)]
pub struct AccountLimits {
    /// Its jobs that run at once; more wait in the queue.
    #[schema(required = true)]
    pub max_running: Option<u32>,
    /// Its jobs waiting in the queue; a submit beyond is refused (429 queued_job_limit).
    #[schema(required = true)]
    pub max_queued: Option<u32>,
    /// Bytes of its captures and open uploads; an upload beyond is refused (403
    /// storage_quota_exceeded).
    #[schema(required = true)]
    pub max_storage_bytes: Option<u64>,
    /// Highest `priority` its jobs may ask for (the lowest is -100).
    #[schema(required = true)]
    pub max_priority: Option<i32>,
}

impl AccountLimits {
    /// These limits, with `defaults` where these set none.
    pub fn or(self, defaults: AccountLimits) -> AccountLimits {
        AccountLimits {
            max_running: self.max_running.or(defaults.max_running),
            max_queued: self.max_queued.or(defaults.max_queued),
            max_storage_bytes: self.max_storage_bytes.or(defaults.max_storage_bytes),
            max_priority: self.max_priority.or(defaults.max_priority),
        }
    }

    /// Sets one limit from a tokens-file word `key=value` (`max_storage_mb` in MiB).
    pub fn set(&mut self, word: &str) -> Result<(), String> {
        let (key, value) = word
            .split_once('=')
            .ok_or_else(|| format!("expected `key=value`, found `{word}`"))?;
        let number = |what: &str| -> Result<u64, String> {
            value
                .parse::<u64>()
                .map_err(|_| format!("`{key}` takes a whole number of {what}, found `{value}`"))
        };
        match key {
            "max_running" => self.max_running = Some(small(number("jobs")?, key)?),
            "max_queued" => self.max_queued = Some(small(number("jobs")?, key)?),
            "max_storage_mb" => {
                let mib = number("MiB")?;
                self.max_storage_bytes = Some(mib.checked_mul(1 << 20).ok_or_else(|| {
                    format!("`max_storage_mb` of {mib} MiB is more bytes than can be counted")
                })?);
            }
            "max_priority" => {
                let priority = value
                    .parse::<i32>()
                    .ok()
                    .filter(|p| PRIORITY_RANGE.contains(p))
                    .ok_or_else(|| {
                        format!(
                            "`max_priority` is a whole number from -100 to 100, found `{value}`"
                        )
                    })?;
                self.max_priority = Some(priority);
            }
            _ => {
                return Err(format!(
                    "unknown limit `{key}` (max_running, max_queued, max_storage_mb, max_priority)"
                ))
            }
        }
        Ok(())
    }
}

fn small(value: u64, key: &str) -> Result<u32, String> {
    u32::try_from(value).map_err(|_| format!("`{key}` of {value} is too large"))
}

/// Every account's limits: the server's defaults and each account's own.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Quotas {
    /// Limits of an account that sets none of its own (CLI `--account-max-*`).
    pub defaults: AccountLimits,
    /// Limits the tokens file gives accounts, by account.
    pub accounts: BTreeMap<String, AccountLimits>,
}

impl Quotas {
    /// What `account` may hold and ask for.
    pub fn of(&self, account: &str) -> AccountLimits {
        self.accounts
            .get(account)
            .copied()
            .unwrap_or_default()
            .or(self.defaults)
    }

    /// The running-job limit of each account, for the store's claim: the default, and the
    /// accounts whose own limit differs from it.
    pub fn running(&self) -> RunningLimits {
        RunningLimits {
            default: self.defaults.max_running,
            accounts: self
                .accounts
                .iter()
                .filter_map(|(name, limits)| Some((name.clone(), limits.max_running?)))
                .collect(),
        }
    }
}

/// Jobs each account may run at once, as the store's claim reads them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RunningLimits {
    /// An account without a limit of its own; `None`: unlimited.
    pub default: Option<u32>,
    /// Accounts with a limit of their own.
    pub accounts: BTreeMap<String, u32>,
}

impl RunningLimits {
    /// The per-account limits as a JSON object (`{"alice": 2}`), which both stores' SQL reads.
    pub fn accounts_json(&self) -> String {
        serde_json::to_string(&self.accounts).unwrap_or_else(|_| "{}".into())
    }
}

/// What an account holds now.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, ToSchema)]
pub struct AccountUsage {
    pub running: u32,
    pub queued: u32,
    /// Bytes of its captures and of its open uploads (as declared).
    pub stored_bytes: u64,
}

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
    state: AppState,
    job_id: String,
}

impl Drop for QueuePlace {
    fn drop(&mut self) {
        let Ok(runtime) = tokio::runtime::Handle::try_current() else {
            return;
        };
        let (store, job_id) = (self.state.store.clone(), std::mem::take(&mut self.job_id));
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
    state: &AppState,
    caller: &Caller,
    request: JobRequestLimits,
    job_id: &str,
) -> Result<Option<QueuePlace>, ApiError> {
    let limits = caller.account().map(|a| state.config.quotas().of(a));
    let highest = limits
        .and_then(|l| l.max_priority)
        .unwrap_or(*PRIORITY_RANGE.end());
    if request.priority < *PRIORITY_RANGE.start() || request.priority > highest {
        return Err(ApiError::unprocessable(
            "priority_not_allowed",
            format!(
                "priority {} is outside the {} to {highest} this token may ask for",
                request.priority,
                PRIORITY_RANGE.start()
            ),
        ));
    }
    if let Some(seconds) = request.max_runtime_seconds {
        let server = state.config.limits.job.max_runtime.map(|d| d.as_secs());
        if seconds == 0 || server.is_some_and(|s| seconds > s) {
            let bound = server.map_or("".into(), |s| format!(" and at most the server's {s}"));
            return Err(ApiError::unprocessable(
                "invalid_max_runtime",
                format!("max_runtime_seconds is at least 1{bound}, found {seconds}"),
            ));
        }
    }
    let (Some(account), Some(max_queued)) = (caller.account(), limits.and_then(|l| l.max_queued))
    else {
        return Ok(None);
    };
    let now = now_ms();
    let placed = state
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
        return Err(ApiError::new(
            StatusCode::TOO_MANY_REQUESTS,
            "queued_job_limit",
            format!(
                "account `{account}` has {queued} jobs queued (or being submitted), its limit; \
                 submit again when one starts"
            ),
        ));
    }
    Ok(Some(QueuePlace {
        state: state.clone(),
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

fn over_quota(account: &str, stored: u64, limit: u64, what: &str) -> ApiError {
    ApiError::new(
        StatusCode::FORBIDDEN,
        "storage_quota_exceeded",
        format!(
            "account `{account}` stores {} MiB of its {} MiB; {what} (delete captures it no \
             longer needs)",
            mib(stored),
            mib(limit)
        ),
    )
}

/// Storage reserved in the store for one capture or upload (`id`) while its bytes arrive,
/// written in the transaction that checks the account's quota. Dropping it releases it: by
/// then the capture or upload is recorded and counts instead, or it failed and its bytes are
/// free again.
pub struct Reservation {
    state: AppState,
    id: String,
    account: String,
    limit: u64,
    /// Bytes reserved so far.
    granted: u64,
}

impl Reservation {
    /// An empty reservation for `id` in the account `caller` stores for, when that account has
    /// a storage limit.
    fn unreserved(state: &AppState, caller: &Caller, id: &str) -> Option<Reservation> {
        let account = caller.account()?;
        let limit = state.config.quotas().of(account).max_storage_bytes?;
        Some(Reservation {
            state: state.clone(),
            id: id.to_owned(),
            account: account.to_owned(),
            limit,
            granted: 0,
        })
    }

    /// Reserves `bytes` for `id`, or refuses (403 `storage_quota_exceeded`) when they do not
    /// fit; `None` when `caller` has no storage limit.
    pub async fn exactly(
        state: &AppState,
        caller: &Caller,
        id: &str,
        bytes: u64,
    ) -> Result<Option<Reservation>, ApiError> {
        let Some(mut reservation) = Self::unreserved(state, caller, id) else {
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
        state: &AppState,
        caller: &Caller,
        id: &str,
    ) -> Result<Option<Reservation>, ApiError> {
        let Some(mut reservation) = Self::unreserved(state, caller, id) else {
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
    pub async fn cover(&mut self, total: u64) -> Result<(), ApiError> {
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

    async fn reserve(
        &mut self,
        bytes: u64,
        partial: bool,
    ) -> Result<crate::store::Reserved, ApiError> {
        let now = now_ms();
        let reserved = self
            .state
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
        let (store, id) = (self.state.store.clone(), std::mem::take(&mut self.id));
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
    fn an_accounts_limits_win_over_the_defaults() {
        let mut alice = AccountLimits::default();
        for word in ["max_running=2", "max_storage_mb=10", "max_priority=5"] {
            alice.set(word).unwrap();
        }
        let quotas = Quotas {
            defaults: AccountLimits {
                max_running: Some(1),
                max_queued: Some(4),
                max_storage_bytes: None,
                max_priority: Some(0),
            },
            accounts: [("alice".to_owned(), alice)].into(),
        };
        let limits = quotas.of("alice");
        assert_eq!(limits.max_running, Some(2));
        assert_eq!(limits.max_queued, Some(4));
        assert_eq!(limits.max_storage_bytes, Some(10 << 20));
        assert_eq!(limits.max_priority, Some(5));
        assert_eq!(quotas.of("bob"), quotas.defaults);
        let running = quotas.running();
        assert_eq!(
            (running.default, running.accounts_json()),
            (Some(1), r#"{"alice":2}"#.into())
        );
    }

    #[test]
    fn sizes_are_shown_in_mib_with_decimals_where_needed() {
        assert_eq!(mib(2 << 20), "2");
        assert_eq!(mib(0), "0");
        assert_eq!(mib(576_717), "0.55");
        assert_eq!(mib((3 << 20) + 1), "3.00");
    }

    #[test]
    fn bad_limit_words_are_named() {
        let mut limits = AccountLimits::default();
        for (word, problem) in [
            ("max_running", "key=value"),
            ("max_running=-1", "whole number"),
            ("max_priority=101", "-100 to 100"),
            ("max_storage_mb=18446744073709551615", "more bytes"),
            ("max_jobs=3", "unknown limit"),
        ] {
            let error = limits.set(word).unwrap_err();
            assert!(error.contains(problem), "{word}: {error}");
        }
        assert_eq!(limits, AccountLimits::default());
    }
}
