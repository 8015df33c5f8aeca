//! The store test-suite, run against both backends: the embedded SQLite file and a real
//! PostgreSQL server (started from Debian's package on a loopback port; skipped with a notice
//! where it is not installed, a failure under `CI=true`). Each check takes a fresh, empty store.

mod common;

use std::collections::HashSet;
use std::sync::Arc;

use common::postgres::TempPostgres;
use phygap::core::config::TrainConfig;
use phygap_api::storage::store::RunningLimits;
use phygap_api::storage::store::{
    CaptureRecord, DeleteOutcome, Finish, JobSpec, JobState, NewJob, PartOutcome, PostgresStore,
    Progress, QueueCounts, SqliteStore, Store, StoreError, UploadEnd, UploadPart, UploadRecord,
    UploadState,
};

fn new_job(id: &str, created_at: i64) -> NewJob {
    NewJob {
        id: id.into(),
        capture_id: "cap_1".into(),
        spec: JobSpec::Train {
            config: TrainConfig::default(),
        },
        iterations: 100,
        created_at,
        account: None,
        webhook_url: None,
        priority: 0,
        max_runtime_seconds: None,
    }
}

fn relight_of(id: &str, parent: &str, created_at: i64) -> NewJob {
    NewJob {
        spec: JobSpec::Relight {
            parent_job_id: parent.into(),
            envmap_file: "envmap.exr".into(),
            cameras_file: None,
            rotate_deg: 0.0,
        },
        ..new_job(id, created_at)
    }
}

async fn claim_is_exclusive_and_fifo(s: &dyn Store) {
    s.submit(&new_job("job_b", 2), None).await.unwrap();
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    // Same creation time: the one submitted first goes first.
    s.submit(&new_job("job_d", 3), None).await.unwrap();
    s.submit(&new_job("job_c", 3), None).await.unwrap();
    let mut order = Vec::new();
    while let Some(job) = s.claim("w", 10, 1000).await.unwrap() {
        assert_eq!((job.state, job.attempts), (JobState::Running, 1));
        assert_eq!(job.started_at, Some(10));
        order.push(job.id);
    }
    assert_eq!(order, ["job_a", "job_b", "job_d", "job_c"]);
    assert_eq!(
        s.counts(None).await.unwrap(),
        QueueCounts {
            queued: 0,
            running: 4
        }
    );
    let listed: Vec<String> = s
        .list_jobs(3, None)
        .await
        .unwrap()
        .into_iter()
        .map(|j| j.id)
        .collect();
    assert_eq!(listed, ["job_c", "job_d", "job_b"], "newest first");
}

async fn concurrent_claims_take_each_job_once(s: Arc<dyn Store>) {
    for i in 0..40 {
        s.submit(&new_job(&format!("job_{i:02}"), i), None)
            .await
            .unwrap();
    }
    let claimers = (0..8).map(|w| {
        let s = s.clone();
        tokio::spawn(async move {
            let mut mine = Vec::new();
            while let Some(job) = s.claim(&format!("w{w}"), 10, 1000).await.unwrap() {
                mine.push(job.id);
            }
            mine
        })
    });
    let mut claimed = Vec::new();
    for claimer in claimers {
        claimed.extend(claimer.await.unwrap());
    }
    let distinct: HashSet<&String> = claimed.iter().collect();
    assert_eq!((claimed.len(), distinct.len()), (40, 40), "{claimed:?}");
}

/// Claimers racing under running limits (each its own connection on PostgreSQL) never take an
/// account past its limit: every account ends with exactly its limit running.
async fn concurrent_claims_keep_accounts_within_their_running_limits(s: Arc<dyn Store>) {
    for (a, account) in ["alice", "bob", "carol"].into_iter().enumerate() {
        for i in 0..10 {
            let job = NewJob {
                account: Some(account.into()),
                ..new_job(&format!("job_{account}_{i}"), (a * 10 + i) as i64)
            };
            s.submit(&job, None).await.unwrap();
        }
    }
    let limits = RunningLimits {
        default: Some(2),
        accounts: [("carol".to_owned(), 3)].into(),
    };
    let claimers = (0..8).map(|w| {
        let (s, limits) = (s.clone(), limits.clone());
        tokio::spawn(async move {
            let mut mine = 0;
            while s
                .claim_within(&format!("w{w}"), 10, 1000, &limits)
                .await
                .unwrap()
                .is_some()
            {
                mine += 1;
            }
            mine
        })
    });
    let mut claimed = 0;
    for claimer in claimers {
        claimed += claimer.await.unwrap();
    }
    assert_eq!(claimed, 2 + 2 + 3);
    for (account, limit) in [("alice", 2), ("bob", 2), ("carol", 3)] {
        let usage = s.account_usage(account).await.unwrap();
        assert_eq!(
            (usage.running, usage.queued),
            (limit, 10 - limit),
            "{account}"
        );
    }
}

async fn only_the_owner_can_heartbeat_and_finish(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    s.claim("w1", 10, 1000).await.unwrap().unwrap();
    let progress = Progress {
        iteration: 7,
        iterations: 100,
        stage: Some("geometry".into()),
        losses: [("l1".to_string(), 0.25)].into(),
        warning: Some("careful".into()),
        ..Progress::default()
    };
    assert!(matches!(
        s.heartbeat("job_a", "intruder", &progress, 2000).await,
        Err(StoreError::LeaseLost(_))
    ));
    assert!(!s.heartbeat("job_a", "w1", &progress, 2000).await.unwrap());
    assert!(s
        .finish("job_a", "intruder", &Finish::Succeeded, 50)
        .await
        .is_err());
    s.finish("job_a", "w1", &Finish::Succeeded, 50)
        .await
        .unwrap();
    let job = s.job("job_a").await.unwrap().unwrap();
    assert_eq!(job.state, JobState::Succeeded);
    assert_eq!(job.progress, progress);
    assert_eq!(job.finished_at, Some(50));
    // Finished: no more heartbeats or finishes, even by the former owner.
    assert!(s.heartbeat("job_a", "w1", &progress, 3000).await.is_err());
    assert!(s
        .finish(
            "job_a",
            "w1",
            &Finish::Failed {
                code: "training_failed",
                message: "late".into()
            },
            60
        )
        .await
        .is_err());
}

async fn a_requeued_job_keeps_its_progress_and_is_claimed_again(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    s.claim("w1", 10, 1000).await.unwrap().unwrap();
    let progress = Progress {
        iteration: 40,
        checkpoint_iteration: Some(40),
        ..Progress::default()
    };
    s.heartbeat("job_a", "w1", &progress, 1000).await.unwrap();
    s.finish("job_a", "w1", &Finish::Requeue, 20).await.unwrap();
    let job = s.job("job_a").await.unwrap().unwrap();
    assert_eq!((job.state, job.finished_at), (JobState::Queued, None));
    let again = s.claim("w2", 30, 1000).await.unwrap().unwrap();
    assert_eq!(again.attempts, 2);
    assert_eq!(again.started_at, Some(10), "the first start is kept");
    assert_eq!(again.progress.checkpoint_iteration, Some(40));
}

async fn expired_leases_are_requeued_then_abandoned(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    s.claim("dead", 10, 100).await.unwrap().unwrap();
    assert!(
        s.requeue_expired(99, 3).await.unwrap().is_empty(),
        "lease still valid"
    );
    assert_eq!(s.requeue_expired(101, 3).await.unwrap(), ["job_a"]);
    assert_eq!(
        s.job("job_a").await.unwrap().unwrap().state,
        JobState::Queued
    );
    // The dead owner can no longer write.
    assert!(s
        .finish("job_a", "dead", &Finish::Succeeded, 5)
        .await
        .is_err());
    for attempt in 2..=3 {
        let job = s.claim("w", 200, 300).await.unwrap().unwrap();
        assert_eq!(job.attempts, attempt);
        s.requeue_expired(301, 3).await.unwrap();
    }
    let job = s.job("job_a").await.unwrap().unwrap();
    assert_eq!((job.state, job.finished_at), (JobState::Failed, Some(301)));
    assert_eq!(job.error_code.as_deref(), Some("abandoned"));
    assert!(job.error.unwrap().contains("abandoned"));
}

async fn a_process_that_dies_the_same_way_twice_fails_the_job(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    let died = |reason: &'static str| Finish::Died {
        reason,
        message: format!("the job's process died: {reason}"),
    };
    let mut deaths = Vec::new();
    for (attempt, reason) in [(1, "out_of_memory"), (2, "time_limit"), (3, "time_limit")] {
        let job = s.claim("w", 10 * attempt, 1000).await.unwrap().unwrap();
        assert_eq!(job.attempts, attempt as u32);
        s.finish("job_a", "w", &died(reason), 10 * attempt + 5)
            .await
            .unwrap();
        let job = s.job("job_a").await.unwrap().unwrap();
        deaths.push((job.state, job.last_death, job.error_code, job.finished_at));
    }
    let death = |reason: &str| Some(reason.to_owned());
    assert_eq!(
        deaths,
        [
            // A first death requeues, remembering how it died.
            (JobState::Queued, death("out_of_memory"), None, None),
            // Another way of dying is another first.
            (JobState::Queued, death("time_limit"), None, None),
            // The same way twice in a row fails the job with that reason.
            (
                JobState::Failed,
                death("time_limit"),
                death("time_limit"),
                Some(35)
            ),
        ]
    );
    let job = s.job("job_a").await.unwrap().unwrap();
    assert_eq!(
        job.error.as_deref(),
        Some("the job's process died: time_limit")
    );
    assert!(s.claim("w", 50, 1000).await.unwrap().is_none());
}

async fn an_expired_job_with_a_cancel_request_ends_cancelled(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    s.claim("dead", 10, 100).await.unwrap().unwrap();
    let running = s.request_cancel("job_a", 20).await.unwrap().unwrap();
    assert_eq!(running.state, JobState::Running);
    assert!(running.cancel_requested);
    assert!(s
        .heartbeat("job_a", "dead", &Progress::default(), 100)
        .await
        .unwrap());
    s.requeue_expired(500, 3).await.unwrap();
    let job = s.job("job_a").await.unwrap().unwrap();
    assert_eq!((job.state, job.error), (JobState::Cancelled, None));
}

async fn idempotency_key_returns_the_same_job_or_conflicts(s: &dyn Store) {
    let (a, new_a) = s
        .submit(&new_job("job_a", 1), Some(("k1", "h1")))
        .await
        .unwrap();
    let (b, new_b) = s
        .submit(&new_job("job_b", 2), Some(("k1", "h1")))
        .await
        .unwrap();
    assert!(new_a && !new_b);
    assert_eq!(a, b);
    assert!(matches!(
        s.submit(&new_job("job_c", 3), Some(("k1", "other"))).await,
        Err(StoreError::IdempotencyConflict(_))
    ));
    let (d, new_d) = s
        .submit(&new_job("job_d", 4), Some(("k2", "h1")))
        .await
        .unwrap();
    assert!(new_d);
    assert_eq!(d.id, "job_d");
    assert_eq!(s.list_jobs(10, None).await.unwrap().len(), 2);
}

async fn restarted_jobs_run_again_resuming_or_afresh(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    assert_eq!(
        s.restart("job_a", None, None).await.unwrap().unwrap().state,
        JobState::Queued,
        "a queued job stays as it is"
    );
    s.claim("w", 10, 100).await.unwrap().unwrap();
    let failed = Finish::Failed {
        code: "training_failed",
        message: "diverged".into(),
    };
    s.finish("job_a", "w", &failed, 20).await.unwrap();
    assert!(s.restart("job_none", None, None).await.unwrap().is_none());
    // As it was: resumes (its attempts carry on, so the next claim resumes).
    let again = s.restart("job_a", None, None).await.unwrap().unwrap();
    assert_eq!(
        (
            again.state,
            again.error,
            again.error_code,
            again.finished_at,
            again.attempts
        ),
        (JobState::Queued, None, None, None, 1)
    );
    assert_eq!(s.claim("w", 30, 100).await.unwrap().unwrap().attempts, 2);
    s.finish("job_a", "w", &Finish::Cancelled, 40)
        .await
        .unwrap();
    // Changed: starts over, with its new spec and progress.
    let spec = JobSpec::Train {
        config: TrainConfig {
            iterations: 77.into(),
            ..TrainConfig::default()
        },
    };
    let fresh = Progress {
        iterations: 77,
        ..Progress::default()
    };
    let over = s
        .restart("job_a", Some(&spec), Some(&fresh))
        .await
        .unwrap()
        .unwrap();
    assert_eq!((over.state, over.attempts), (JobState::Queued, 0));
    assert_eq!((over.spec, over.progress), (spec, fresh));
}

async fn webhooks_are_taken_once_retried_and_recorded(s: &dyn Store) {
    let hooked = NewJob {
        webhook_url: Some("http://127.0.0.1:9/hook".into()),
        ..new_job("job_a", 1)
    };
    s.submit(&hooked, None).await.unwrap();
    s.submit(&new_job("job_b", 2), None).await.unwrap();
    assert!(
        s.take_webhook(5, 100, &[]).await.unwrap().is_none(),
        "not ended yet"
    );
    while let Some(job) = s.claim("w", 10, 100).await.unwrap() {
        s.finish(&job.id, "w", &Finish::Succeeded, 20)
            .await
            .unwrap();
    }
    let taken = s.take_webhook(30, 60, &[]).await.unwrap().unwrap();
    assert_eq!((taken.job.id.as_str(), taken.attempts), ("job_a", 0));
    assert_eq!(taken.url, "http://127.0.0.1:9/hook");
    assert!(
        s.take_webhook(31, 60, &[]).await.unwrap().is_none(),
        "leased"
    );
    s.record_webhook("job_a", 1, "not delivered: cannot connect", Some(80))
        .await
        .unwrap();
    assert!(
        s.take_webhook(79, 200, &[]).await.unwrap().is_none(),
        "not due yet"
    );
    let retry = s.take_webhook(80, 200, &[]).await.unwrap().unwrap();
    assert_eq!(retry.attempts, 1);
    s.record_webhook("job_a", 2, "delivered: 200", None)
        .await
        .unwrap();
    assert!(
        s.take_webhook(10_000, 20_000, &[]).await.unwrap().is_none(),
        "delivered"
    );
    let webhook = s.job("job_a").await.unwrap().unwrap().webhook.unwrap();
    assert_eq!(
        (
            webhook.attempts,
            webhook.last_status.as_deref(),
            webhook.done
        ),
        (2, Some("delivered: 200"), true)
    );
    assert_eq!(s.job("job_b").await.unwrap().unwrap().webhook, None);
}

/// A sender passes over the accounts whose deliveries it already has in flight: their jobs stay
/// due for later, and another account's delivery is taken first.
async fn webhooks_of_busy_accounts_wait(s: &dyn Store) {
    let hooked = |id: &str, at: i64, account: Option<&str>| NewJob {
        webhook_url: Some("http://127.0.0.1:9/hook".into()),
        account: account.map(str::to_owned),
        ..new_job(id, at)
    };
    s.submit(&hooked("job_a", 1, Some("alice")), None)
        .await
        .unwrap();
    s.submit(&hooked("job_b", 2, None), None).await.unwrap();
    s.submit(&hooked("job_c", 3, Some("bob")), None)
        .await
        .unwrap();
    let mut finished_at = 10;
    while let Some(job) = s.claim("w", 10, 100).await.unwrap() {
        finished_at += 1;
        s.finish(&job.id, "w", &Finish::Succeeded, finished_at)
            .await
            .unwrap();
    }
    let busy = ["alice".to_owned(), String::new()];
    let taken = s.take_webhook(50, 60, &busy).await.unwrap().unwrap();
    assert_eq!(
        taken.job.id, "job_c",
        "alice's and the account-less job wait"
    );
    assert!(s.take_webhook(50, 60, &busy).await.unwrap().is_none());
    let next = s.take_webhook(50, 60, &[]).await.unwrap().unwrap();
    assert_eq!(next.job.id, "job_a", "the oldest once nobody is busy");
}

async fn progress_events_are_kept_in_order_and_go_with_their_job(s: &dyn Store) {
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    assert_eq!(s.next_event_seq("job_a").await.unwrap(), 0);
    let events: Vec<String> = (0..5).map(|i| format!("{{\"n\":{i}}}")).collect();
    s.append_events("job_a", 0, &events[..3]).await.unwrap();
    s.append_events("job_a", 3, &events[3..]).await.unwrap();
    assert_eq!(s.next_event_seq("job_a").await.unwrap(), 5);
    let page = s.events("job_a", 1, 2).await.unwrap();
    assert_eq!(page, [(1, events[1].clone()), (2, events[2].clone())]);
    assert_eq!(s.events("job_a", 5, 10).await.unwrap(), []);
    assert_eq!(s.events("job_b", 0, 10).await.unwrap(), []);
    s.request_cancel("job_a", 2).await.unwrap();
    assert_eq!(s.delete_job("job_a").await.unwrap(), DeleteOutcome::Deleted);
    assert_eq!(s.events("job_a", 0, 10).await.unwrap(), []);
}

async fn idempotency_keys_are_per_account(s: &dyn Store) {
    let of = |id: &str, account: Option<&str>| NewJob {
        account: account.map(str::to_owned),
        ..new_job(id, 1)
    };
    // The admin's key `bob/k7` and bob's `k7` are different keys (they once collided).
    let (admin, _) = s
        .submit(&of("job_admin", None), Some(("bob/k7", "h")))
        .await
        .unwrap();
    let (bob, new_bob) = s
        .submit(&of("job_bob", Some("bob")), Some(("k7", "h")))
        .await
        .unwrap();
    let (alice, new_alice) = s
        .submit(&of("job_alice", Some("alice")), Some(("k7", "h")))
        .await
        .unwrap();
    for (account, key, found) in [
        (Some("bob"), "k7", true),
        (None, "bob/k7", true),
        (None, "k7", false),
        (Some("carol"), "k7", false),
    ] {
        assert_eq!(
            s.has_request_key(account, key).await.unwrap(),
            found,
            "{account:?} {key}"
        );
    }
    assert!(new_bob && new_alice);
    assert_eq!(
        (admin.id.as_str(), bob.id.as_str(), alice.id.as_str()),
        ("job_admin", "job_bob", "job_alice")
    );
    let (again, new) = s
        .submit(&of("job_bob2", Some("bob")), Some(("k7", "h")))
        .await
        .unwrap();
    assert_eq!((again.id.as_str(), new), ("job_bob", false));
    match s
        .submit(&of("job_bob3", Some("bob")), Some(("k7", "other")))
        .await
    {
        Err(e @ StoreError::IdempotencyConflict(_)) => {
            assert_eq!(
                e.to_string(),
                "Idempotency-Key `k7` was already used for a different request"
            )
        }
        other => panic!("{other:?}"),
    }
}

async fn concurrent_submits_with_one_key_create_one_job(s: Arc<dyn Store>) {
    let submits = (0..8).map(|i| {
        let s = s.clone();
        tokio::spawn(async move {
            s.submit(&new_job(&format!("job_{i}"), i), Some(("key", "hash")))
                .await
                .unwrap()
        })
    });
    let mut created = 0;
    let mut ids = HashSet::new();
    for submit in submits {
        let (job, new) = submit.await.unwrap();
        created += usize::from(new);
        ids.insert(job.id);
    }
    assert_eq!((created, ids.len()), (1, 1));
}

async fn cancel_and_capture_deletion_respect_job_states(s: &dyn Store) {
    let capture = CaptureRecord {
        id: "cap_1".into(),
        views: 3,
        width: 1224,
        height: 1024,
        kinds: vec!["rgb".into(), "stokes".into()],
        warnings: vec!["a warning".into()],
        size_bytes: 10,
        created_at: 7,
        account: Some("studio".into()),
    };
    s.insert_capture(&capture).await.unwrap();
    assert!(s.insert_capture(&capture).await.is_err(), "ids are unique");
    assert_eq!(s.capture("cap_1").await.unwrap().unwrap(), capture);
    assert_eq!(s.capture_ids().await.unwrap(), ["cap_1"]);
    assert!(s.capture("cap_2").await.unwrap().is_none());
    s.submit(&new_job("job_a", 1), None).await.unwrap();
    assert_eq!(
        s.delete_capture("cap_1").await.unwrap(),
        DeleteOutcome::InUse
    );
    let cancelled = s.request_cancel("job_a", 5).await.unwrap().unwrap();
    assert_eq!(
        (cancelled.state, cancelled.finished_at),
        (JobState::Cancelled, Some(5))
    );
    // A finished job is left as it is.
    let again = s.request_cancel("job_a", 9).await.unwrap().unwrap();
    assert_eq!(again, cancelled);
    assert!(s.claim("w", 6, 100).await.unwrap().is_none());
    assert_eq!(
        s.delete_capture("cap_1").await.unwrap(),
        DeleteOutcome::Deleted
    );
    assert_eq!(
        s.delete_capture("cap_1").await.unwrap(),
        DeleteOutcome::NotFound
    );
    assert!(s.request_cancel("nope", 5).await.unwrap().is_none());
    assert!(s.job("nope").await.unwrap().is_none());
    s.ping().await.unwrap();
}

async fn accounts_see_their_jobs_and_deletion_and_retention_spare_what_is_in_use(s: &dyn Store) {
    let mine = |id: &str, at: i64| NewJob {
        account: Some("alice".into()),
        ..new_job(id, at)
    };
    s.submit(&mine("job_a", 1), None).await.unwrap();
    s.submit(&new_job("job_b", 2), None).await.unwrap();
    let alices: Vec<_> = s.list_jobs(10, Some("alice")).await.unwrap();
    assert_eq!(alices.len(), 1);
    assert_eq!(alices[0].account.as_deref(), Some("alice"));
    assert!(s.list_jobs(10, Some("bob")).await.unwrap().is_empty());
    assert_eq!(s.list_jobs(10, None).await.unwrap().len(), 2);
    let queued = |queued| QueueCounts { queued, running: 0 };
    assert_eq!(s.counts(Some("alice")).await.unwrap(), queued(1));
    assert_eq!(s.counts(Some("bob")).await.unwrap(), queued(0));
    assert_eq!(s.counts(None).await.unwrap(), queued(2));
    // Queued or running jobs are not deleted.
    assert_eq!(s.delete_job("job_a").await.unwrap(), DeleteOutcome::InUse);
    let running = s.claim("w", 3, 100).await.unwrap().unwrap();
    assert_eq!(running.id, "job_a");
    s.finish("job_a", "w", &Finish::Succeeded, 10)
        .await
        .unwrap();
    // A relight of job_a that is still queued keeps job_a.
    s.submit(&relight_of("job_r", "job_a", 11), None)
        .await
        .unwrap();
    assert_eq!(s.delete_job("job_a").await.unwrap(), DeleteOutcome::InUse);
    assert!(s.jobs_ended_before(100).await.unwrap().is_empty());
    s.request_cancel("job_r", 12).await.unwrap();
    s.request_cancel("job_b", 13).await.unwrap();
    assert_eq!(s.jobs_ended_before(12).await.unwrap(), ["job_a"]);
    assert_eq!(
        s.jobs_ended_before(100).await.unwrap(),
        ["job_a", "job_r", "job_b"],
        "oldest end first"
    );
    assert_eq!(s.delete_job("job_a").await.unwrap(), DeleteOutcome::Deleted);
    assert_eq!(
        s.delete_job("job_a").await.unwrap(),
        DeleteOutcome::NotFound
    );
    assert!(s.job("job_a").await.unwrap().is_none());
    // Captures: only old ones that no job uses.
    for (id, at) in [("cap_1", 5), ("cap_old", 5), ("cap_new", 50)] {
        let capture = CaptureRecord {
            id: id.into(),
            views: 1,
            width: 8,
            height: 8,
            kinds: vec![],
            warnings: vec![],
            size_bytes: 1,
            created_at: at,
            account: None,
        };
        s.insert_capture(&capture).await.unwrap();
    }
    assert_eq!(s.unused_captures_before(20).await.unwrap(), ["cap_old"]);
    for id in ["job_r", "job_b"] {
        assert_eq!(s.delete_job(id).await.unwrap(), DeleteOutcome::Deleted);
    }
    let mut unused = s.unused_captures_before(20).await.unwrap();
    unused.sort();
    assert_eq!(unused, ["cap_1", "cap_old"]);
}

/// Runs every check, each on a fresh store from `fresh`.
fn part(index: u32, sha: char) -> UploadPart {
    UploadPart {
        index,
        size: 100,
        sha256: sha.to_string().repeat(64),
        copy: Some(format!("copy_{index}{sha}")),
    }
}

async fn uploads_take_parts_until_one_commit_settles_them(s: &dyn Store) {
    let upload = UploadRecord {
        id: "upl_1".into(),
        account: Some("alice".into()),
        size: 250,
        part_size: 100,
        sha256: Some("f".repeat(64)),
        state: UploadState::Open,
        parts: Vec::new(),
        created_at: 10,
        updated_at: 10,
    };
    s.create_upload(&upload).await.unwrap();
    assert_eq!(s.upload("upl_1").await.unwrap().as_ref(), Some(&upload));
    assert_eq!(s.upload("upl_none").await.unwrap(), None);
    // Parts in any order; one sent again replaces the first, which is handed back.
    for (p, now) in [(part(2, 'a'), 11), (part(0, 'b'), 12), (part(0, 'c'), 13)] {
        let outcome = s.record_part("upl_1", &p, now).await.unwrap();
        let replaced = (p.sha256.starts_with('c')).then(|| part(0, 'b'));
        assert_eq!(outcome, PartOutcome::Recorded { replaced });
    }
    let stored = s.upload("upl_1").await.unwrap().unwrap();
    assert_eq!(stored.parts, [part(0, 'c'), part(2, 'a')]);
    assert_eq!(stored.updated_at, 13);
    assert_eq!(
        s.record_part("upl_none", &part(0, 'a'), 14).await.unwrap(),
        PartOutcome::NotFound
    );

    // One commit at a time; parts are refused meanwhile; a lease that ran out is taken over.
    let taken = s.begin_commit("upl_1", 20, 100).await.unwrap().unwrap();
    assert_eq!(taken.state, UploadState::Committing { until: 100 });
    assert_eq!(taken.parts.len(), 2);
    assert_eq!(s.begin_commit("upl_1", 50, 130).await.unwrap(), None);
    assert_eq!(
        s.record_part("upl_1", &part(1, 'd'), 51).await.unwrap(),
        PartOutcome::Closed
    );
    assert!(s.begin_commit("upl_1", 101, 200).await.unwrap().is_some());
    // A part that could not be read back is forgotten, the rest kept, the upload open again.
    let lost = UploadEnd::PartsLost { indexes: vec![2] };
    s.end_commit("upl_1", &lost, 102).await.unwrap();
    let reopened = s.upload("upl_1").await.unwrap().unwrap();
    assert_eq!(reopened.state, UploadState::Open);
    assert_eq!(reopened.parts, [part(0, 'c')]);
    assert!(matches!(
        s.record_part("upl_1", &part(2, 'a'), 102).await.unwrap(),
        PartOutcome::Recorded { replaced: None }
    ));
    s.begin_commit("upl_1", 102, 200).await.unwrap().unwrap();
    // Reopened by a failure of the service: parts again, then committed for good.
    s.end_commit("upl_1", &UploadEnd::Reopened, 102)
        .await
        .unwrap();
    assert!(matches!(
        s.record_part("upl_1", &part(1, 'd'), 103).await.unwrap(),
        PartOutcome::Recorded { replaced: None }
    ));
    s.begin_commit("upl_1", 104, 300).await.unwrap().unwrap();
    let end = UploadEnd::Committed {
        capture_id: "cap_9".into(),
    };
    s.end_commit("upl_1", &end, 105).await.unwrap();
    let committed = s.upload("upl_1").await.unwrap().unwrap();
    assert_eq!(
        committed.state,
        UploadState::Committed {
            capture_id: "cap_9".into()
        }
    );
    assert!(committed.parts.is_empty());
    assert_eq!(s.begin_commit("upl_1", 106, 400).await.unwrap(), None);

    // A refused one keeps its answer; idle ones are found by their last touch; deletion.
    s.create_upload(&UploadRecord {
        id: "upl_2".into(),
        created_at: 200,
        updated_at: 200,
        ..upload.clone()
    })
    .await
    .unwrap();
    s.begin_commit("upl_2", 201, 500).await.unwrap().unwrap();
    let refused = UploadEnd::Failed {
        code: "invalid_archive".into(),
        message: "corrupt".into(),
    };
    s.end_commit("upl_2", &refused, 202).await.unwrap();
    assert_eq!(
        s.upload("upl_2").await.unwrap().unwrap().state,
        UploadState::Failed {
            code: "invalid_archive".into(),
            message: "corrupt".into()
        }
    );
    assert_eq!(s.uploads_idle_before(150).await.unwrap(), ["upl_1"]);
    assert!(s.delete_upload("upl_1").await.unwrap());
    assert!(!s.delete_upload("upl_1").await.unwrap());
    assert_eq!(s.upload("upl_1").await.unwrap(), None);
    assert_eq!(s.uploads_idle_before(i64::MAX).await.unwrap(), ["upl_2"]);
}

/// Claims take the highest priority first, then the oldest; an account running its limit of
/// jobs waits while others' jobs are claimed. What an account holds is counted.
async fn claims_follow_priority_and_running_limits(s: &dyn Store) {
    let job = |id: &str, account: &str, priority: i32, at: i64| NewJob {
        account: Some(account.into()),
        priority,
        max_runtime_seconds: Some(60),
        ..new_job(id, at)
    };
    for new in [
        job("job_a1", "alice", 0, 1),
        job("job_a2", "alice", 5, 2),
        job("job_a3", "alice", 5, 3),
        job("job_b1", "bob", 0, 4),
        job("job_c1", "carol", -1, 0),
    ] {
        s.submit(&new, None).await.unwrap();
    }
    let stored = s.job("job_a2").await.unwrap().unwrap();
    assert_eq!((stored.priority, stored.max_runtime_seconds), (5, Some(60)));
    // alice may run one job at once, bob two, everyone else (carol) one.
    let limits = RunningLimits {
        default: Some(1),
        accounts: [("alice".to_owned(), 1), ("bob".to_owned(), 2)].into(),
    };
    let mut order = Vec::new();
    while let Some(job) = s.claim_within("w", 10, 1000, &limits).await.unwrap() {
        order.push(job.id);
    }
    // alice's priority-5 job first, then (alice at her limit) bob's, then carol's priority -1.
    assert_eq!(order, ["job_a2", "job_b1", "job_c1"]);
    let usage = s.account_usage("alice").await.unwrap();
    assert_eq!((usage.running, usage.queued, usage.stored_bytes), (1, 2, 0));
    // alice's job ends: her next is the older of the two left at priority 5.
    s.finish("job_a2", "w", &Finish::Succeeded, 20)
        .await
        .unwrap();
    let next = s
        .claim_within("w", 21, 1000, &limits)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(next.id, "job_a3");
    // Without limits the last one is claimed at once.
    assert_eq!(s.claim("w", 22, 1000).await.unwrap().unwrap().id, "job_a1");

    // Stored bytes: the account's captures and its open uploads (as declared).
    let capture = CaptureRecord {
        id: "cap_alice".into(),
        views: 1,
        width: 8,
        height: 8,
        kinds: vec![],
        warnings: vec![],
        size_bytes: 1000,
        created_at: 1,
        account: Some("alice".into()),
    };
    s.insert_capture(&capture).await.unwrap();
    let upload = UploadRecord {
        id: "upl_alice".into(),
        account: Some("alice".into()),
        size: 250,
        part_size: 100,
        sha256: None,
        state: UploadState::Open,
        parts: Vec::new(),
        created_at: 10,
        updated_at: 10,
    };
    s.create_upload(&upload).await.unwrap();
    assert_eq!(s.account_usage("alice").await.unwrap().stored_bytes, 1250);
    assert_eq!(s.account_usage("bob").await.unwrap().stored_bytes, 0);
}

/// Storage is reserved in the transaction that checks it: of concurrent reservations only what
/// fits is granted; a partial one takes what is left; a reservation stops counting once its
/// capture or upload is recorded, when released, and when its lease ends.
async fn storage_is_reserved_in_the_transaction_that_checks_it(s: Arc<dyn Store>) {
    let capture = CaptureRecord {
        id: "cap_held".into(),
        views: 1,
        width: 8,
        height: 8,
        kinds: vec![],
        warnings: vec![],
        size_bytes: 250,
        created_at: 1,
        account: Some("alice".into()),
    };
    s.insert_capture(&capture).await.unwrap();
    // Usage is read at the clock's time: reservations are made around it.
    let now = phygap_api::storage::store::now_ms();
    let until = now + 3_600_000;
    let tasks: Vec<_> = (0..20)
        .map(|i| {
            let s = s.clone();
            tokio::spawn(async move {
                s.reserve_bytes("alice", &format!("cap_{i}"), 100, false, 1000, now, until)
                    .await
                    .unwrap()
            })
        })
        .collect();
    let mut granted = Vec::new();
    for task in tasks {
        let reserved = task.await.unwrap();
        assert!(
            reserved.granted == 0 || reserved.granted == 100,
            "{reserved:?}"
        );
        if reserved.granted == 0 {
            assert!(reserved.stored_bytes > 900, "{reserved:?}");
        }
        granted.push(reserved.granted);
    }
    assert_eq!(granted.iter().filter(|&&g| g == 100).count(), 7);
    assert_eq!(s.account_usage("alice").await.unwrap().stored_bytes, 950);
    assert_eq!(s.account_usage("bob").await.unwrap().stored_bytes, 0);
    // What is left, partially; then nothing.
    let partial = s
        .reserve_bytes("alice", "cap_partial", 400, true, 1000, now, until)
        .await
        .unwrap();
    assert_eq!((partial.granted, partial.stored_bytes), (50, 950));
    let none = s
        .reserve_bytes("alice", "cap_none", 1, false, 1000, now, until)
        .await
        .unwrap();
    assert_eq!((none.granted, none.stored_bytes), (0, 1000));
    // A reservation grows under its id; releases free their bytes.
    s.release_reservation("cap_partial").await.unwrap();
    for _ in 0..2 {
        let grown = s
            .reserve_bytes("alice", "cap_grown", 20, true, 1000, now, until)
            .await
            .unwrap();
        assert_eq!(grown.granted, 20);
    }
    assert_eq!(s.account_usage("alice").await.unwrap().stored_bytes, 990);
    // Recorded, a capture counts in its reservation's place (not twice).
    let winner = (0..20)
        .map(|i| format!("cap_{i}"))
        .zip(&granted)
        .find(|(_, &g)| g == 100)
        .unwrap()
        .0;
    s.insert_capture(&CaptureRecord {
        id: winner.clone(),
        size_bytes: 90,
        ..capture.clone()
    })
    .await
    .unwrap();
    assert_eq!(s.account_usage("alice").await.unwrap().stored_bytes, 980);
    s.release_reservation(&winner).await.unwrap();
    assert_eq!(s.account_usage("alice").await.unwrap().stored_bytes, 980);
    // Past their lease, reservations count no more; the next check drops them.
    let later = s
        .reserve_bytes("alice", "cap_later", 600, false, 1000, until, until + 1)
        .await
        .unwrap();
    assert_eq!((later.granted, later.stored_bytes), (600, 340));
}

/// Places in an account's queue are reserved in the transaction that checks `max_queued`: of
/// concurrent reservations only what fits is granted; a place counts until its job is queued
/// (then the job counts), released, or past its lease.
async fn queue_places_are_reserved_in_the_transaction_that_checks_them(s: Arc<dyn Store>) {
    let queued = NewJob {
        account: Some("alice".into()),
        ..new_job("job_queued", 1)
    };
    s.submit(&queued, None).await.unwrap();
    let tasks: Vec<_> = (0..10)
        .map(|i| {
            let s = s.clone();
            tokio::spawn(async move {
                s.reserve_queue_place("alice", &format!("job_{i}"), 3, 10, 1000)
                    .await
                    .unwrap()
            })
        })
        .collect();
    let mut placed = Vec::new();
    for (i, task) in tasks.into_iter().enumerate() {
        match task.await.unwrap() {
            Ok(()) => placed.push(format!("job_{i}")),
            Err(held) => assert_eq!(held, 3),
        }
    }
    assert_eq!(placed.len(), 2, "{placed:?}");
    // Submitted, a job counts in its place's stead (not twice); bob's queue is his own.
    let submitted = NewJob {
        account: Some("alice".into()),
        ..new_job(&placed[0], 2)
    };
    s.submit(&submitted, None).await.unwrap();
    assert_eq!(
        s.reserve_queue_place("alice", "job_x", 3, 11, 1000)
            .await
            .unwrap(),
        Err(3)
    );
    assert_eq!(
        s.reserve_queue_place("bob", "job_b", 1, 11, 1000)
            .await
            .unwrap(),
        Ok(())
    );
    // Released, or past its lease, a place is free again.
    s.release_queue_place(&placed[1]).await.unwrap();
    assert_eq!(
        s.reserve_queue_place("alice", "job_y", 3, 12, 1000)
            .await
            .unwrap(),
        Ok(())
    );
    assert_eq!(
        s.reserve_queue_place("alice", "job_z", 4, 1000, 2000)
            .await
            .unwrap(),
        Ok(()),
        "job_y's place ended at 1000"
    );
}

async fn the_suite<F, Fut>(fresh: F)
where
    F: Fn() -> Fut,
    Fut: std::future::Future<Output = Arc<dyn Store>>,
{
    claim_is_exclusive_and_fifo(fresh().await.as_ref()).await;
    claims_follow_priority_and_running_limits(fresh().await.as_ref()).await;
    concurrent_claims_take_each_job_once(fresh().await).await;
    concurrent_claims_keep_accounts_within_their_running_limits(fresh().await).await;
    only_the_owner_can_heartbeat_and_finish(fresh().await.as_ref()).await;
    a_requeued_job_keeps_its_progress_and_is_claimed_again(fresh().await.as_ref()).await;
    expired_leases_are_requeued_then_abandoned(fresh().await.as_ref()).await;
    an_expired_job_with_a_cancel_request_ends_cancelled(fresh().await.as_ref()).await;
    a_process_that_dies_the_same_way_twice_fails_the_job(fresh().await.as_ref()).await;
    idempotency_key_returns_the_same_job_or_conflicts(fresh().await.as_ref()).await;
    idempotency_keys_are_per_account(fresh().await.as_ref()).await;
    restarted_jobs_run_again_resuming_or_afresh(fresh().await.as_ref()).await;
    webhooks_are_taken_once_retried_and_recorded(fresh().await.as_ref()).await;
    webhooks_of_busy_accounts_wait(fresh().await.as_ref()).await;
    progress_events_are_kept_in_order_and_go_with_their_job(fresh().await.as_ref()).await;
    concurrent_submits_with_one_key_create_one_job(fresh().await).await;
    cancel_and_capture_deletion_respect_job_states(fresh().await.as_ref()).await;
    uploads_take_parts_until_one_commit_settles_them(fresh().await.as_ref()).await;
    storage_is_reserved_in_the_transaction_that_checks_it(fresh().await).await;
    queue_places_are_reserved_in_the_transaction_that_checks_them(fresh().await).await;
    accounts_see_their_jobs_and_deletion_and_retention_spare_what_is_in_use(fresh().await.as_ref())
        .await;
}

/// A database file written by the first release (no accounts, failure codes or per-account
/// keys; keys prefixed with the account in `idempotency_key`) opens, keeps its rows, and gains
/// the columns; its keys move to their accounts.
#[tokio::test]
async fn an_older_sqlite_file_is_upgraded_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("old.sqlite3");
    {
        let conn = rusqlite::Connection::open(&path).unwrap();
        conn.execute_batch(
            "CREATE TABLE captures (id TEXT PRIMARY KEY, views INTEGER NOT NULL,
                kinds TEXT NOT NULL, warnings TEXT NOT NULL, size_bytes INTEGER NOT NULL,
                created_at INTEGER NOT NULL);
             INSERT INTO captures VALUES ('cap_old', 2, '[]', '[]', 5, 1);
             CREATE TABLE jobs (id TEXT PRIMARY KEY, capture_id TEXT NOT NULL,
                spec TEXT NOT NULL, state TEXT NOT NULL, progress TEXT NOT NULL, error TEXT,
                created_at INTEGER NOT NULL, started_at INTEGER, finished_at INTEGER,
                attempts INTEGER NOT NULL DEFAULT 0,
                cancel_requested INTEGER NOT NULL DEFAULT 0, owner TEXT, lease_until INTEGER,
                idempotency_key TEXT UNIQUE, request_hash TEXT, account TEXT);",
        )
        .unwrap();
        let spec = serde_json::to_string(&new_job("x", 0).spec).unwrap();
        let progress = serde_json::to_string(&Progress::default()).unwrap();
        for (id, key, account) in [
            ("job_old", "bob/k7", Some("bob")),
            ("job_admin", "k7", None),
        ] {
            conn.execute(
                "INSERT INTO jobs (id, capture_id, spec, state, progress, created_at,
                                   idempotency_key, request_hash, account)
                 VALUES (?1, 'cap_old', ?2, 'succeeded', ?3, 1, ?4, 'h', ?5)",
                rusqlite::params![id, spec, progress, key, account],
            )
            .unwrap();
        }
    }
    let store = SqliteStore::open(&path).unwrap();
    let old = store.capture("cap_old").await.unwrap().unwrap();
    assert_eq!(
        (old.views, old.account, old.width, old.height),
        (2, None, 0, 0)
    );
    let job = store.job("job_old").await.unwrap().unwrap();
    assert_eq!((job.error_code, job.last_death), (None, None));
    let retry = NewJob {
        account: Some("bob".into()),
        ..new_job("job_new", 2)
    };
    let (again, new) = store.submit(&retry, Some(("k7", "h"))).await.unwrap();
    assert_eq!((again.id.as_str(), new), ("job_old", false));
    let (admin, new) = store
        .submit(&new_job("job_new", 2), Some(("k7", "h")))
        .await
        .unwrap();
    assert_eq!((admin.id.as_str(), new), ("job_admin", false));
    drop(store);
    SqliteStore::open(&path).unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_sqlite_store_passes_the_suite() {
    let dir = tempfile::tempdir().unwrap();
    let counter = std::sync::atomic::AtomicUsize::new(0);
    the_suite(|| {
        let n = counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let path = dir.path().join(format!("db{n}.sqlite3"));
        async move { Arc::new(SqliteStore::open(&path).unwrap()) as Arc<dyn Store> }
    })
    .await;
}

/// Runs `sql` on the cluster's `postgres` database; returns the first column of its rows.
async fn admin_query(url: &str, sql: &str) -> Vec<i64> {
    let (client, connection) = tokio_postgres::connect(url, tokio_postgres::NoTls)
        .await
        .unwrap();
    tokio::spawn(connection);
    if sql.starts_with("SELECT") {
        let rows = client.query(sql, &[]).await.unwrap();
        rows.iter().map(|r| r.get::<_, i64>(0)).collect()
    } else {
        client.batch_execute(sql).await.unwrap();
        Vec::new()
    }
}

/// A new empty database on `cluster`; its URL.
async fn new_database(cluster: &TempPostgres, name: &str) -> String {
    admin_query(&cluster.url, &format!("CREATE DATABASE {name}")).await;
    cluster.url.replace("/postgres", &format!("/{name}"))
}

/// A fresh database on `cluster` for each check, migrated by the store.
async fn fresh_postgres(cluster: &TempPostgres, n: usize) -> Arc<dyn Store> {
    let url = new_database(cluster, &format!("suite_{n}")).await;
    Arc::new(PostgresStore::connect(&url).await.unwrap())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_postgres_store_passes_the_suite() {
    let Some(cluster) = TempPostgres::start() else {
        return;
    };
    let counter = std::sync::atomic::AtomicUsize::new(0);
    the_suite(|| {
        let n = counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        fresh_postgres(&cluster, n)
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn replicas_starting_together_migrate_the_schema_once() {
    let Some(cluster) = TempPostgres::start() else {
        return;
    };
    let url = new_database(&cluster, "racing").await;
    let starts = (0..6).map(|_| {
        let url = url.clone();
        tokio::spawn(async move { PostgresStore::connect(&url).await.map(|_| ()) })
    });
    for start in starts {
        start.await.unwrap().unwrap();
    }
    let versions = admin_query(&url, "SELECT count(*) FROM schema_migrations").await;
    assert_eq!(versions, [4]);
    // A database from a newer build is refused, not silently used.
    admin_query(
        &url,
        "INSERT INTO schema_migrations (version, applied_at) VALUES (999, 0)",
    )
    .await;
    let refused = PostgresStore::connect(&url).await.err().unwrap();
    assert!(matches!(refused, StoreError::Migration(_)), "{refused}");
    assert!(refused.to_string().contains("999"), "{refused}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn an_outage_is_unavailable_and_the_store_recovers_with_its_data() {
    let Some(cluster) = TempPostgres::start() else {
        return;
    };
    let store = PostgresStore::connect(&cluster.url).await.unwrap();
    store.submit(&new_job("job_a", 1), None).await.unwrap();
    cluster.stop_server();
    for _ in 0..2 {
        let error = store.job("job_a").await.err().unwrap();
        assert!(matches!(error, StoreError::Unavailable(_)), "{error:?}");
    }
    assert!(matches!(
        PostgresStore::connect(&cluster.url).await,
        Err(StoreError::Unavailable(_))
    ));
    cluster.start_server();
    let job = store.job("job_a").await.unwrap().unwrap();
    assert_eq!(job.state, JobState::Queued);
}
