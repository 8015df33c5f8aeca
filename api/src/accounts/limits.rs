//! What each account may hold and ask for ([`AccountLimits`]: jobs running at once, jobs queued,
//! bytes stored, the priority of its jobs) and where the limits come from: the tokens file's
//! `key=value` words over the server's defaults ([`Quotas`]). The checks are
//! [`crate::accounts::quotas`].

use std::collections::BTreeMap;

use serde::Serialize;
use utoipa::ToSchema;

use crate::storage::store::RunningLimits;

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
