//! End-to-end tests of the service over loopback HTTP: upload → job → progress → artifacts,
//! idempotent submits, cancel, auth, bad uploads, event streams, relighting, concurrent pollers,
//! and the OpenAPI document against the router.

mod common;

use std::time::{Duration, Instant};

use common::*;
use reqwest::Method;
use serde_json::{json, Value};

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn upload_train_and_download_every_artifact() {
    let (dir, t) = TestServer::start_fresh().await;
    let (status, capture) = t.upload(capture_zip()).await;
    assert_eq!(status, 201, "{capture}");
    assert_eq!(capture["views"], 10);
    assert_eq!(capture["kinds"], json!(["stokes"]));
    assert_eq!(
        capture["warnings"],
        json!([]),
        "synthetic captures have masks"
    );
    let capture_id = capture["id"].as_str().unwrap();
    let (status, shown) = t.get_json(&format!("/v1/captures/{capture_id}")).await;
    assert_eq!((status, &shown["views"]), (200, &json!(10)));

    let (status, job) = t.submit(capture_id, train_config(40, 10)).await;
    assert_eq!(status, 201, "{job}");
    assert_eq!(job["state"], "queued");
    assert_eq!(job["iterations"], 40);
    assert!(
        job["backend"].is_null(),
        "no backend before training: {job}"
    );
    assert!(
        job["peak_rss_bytes"].is_null(),
        "no memory before training: {job}"
    );
    let id = job["id"].as_str().unwrap().to_string();
    let done = t.wait_succeeded(&id).await;
    assert_eq!(done["iteration"], 40);
    assert_eq!(done["stage"], "done");
    // The backend it trained on, as `--backend auto` resolved it on this machine.
    let backend = done["backend"].as_str().unwrap_or_default();
    assert!(
        backend.starts_with("fast (") || backend.starts_with("gpu on "),
        "{done}"
    );
    // The training process's peak resident memory (Linux reports it): more than the
    // 10-view capture's decoded samples alone, less than this machine could hold.
    if cfg!(target_os = "linux") {
        let peak = done["peak_rss_bytes"].as_u64().unwrap_or_default();
        assert!(peak > 8 << 20 && peak < 1 << 40, "{done}");
    }
    let psnr = done["test_psnr"].as_f64().unwrap();
    // (8 dB: a 10-step job on the same capture scores 9.99 dB since exposure normalization.)
    assert!(psnr > 8.0 && psnr < 100.0, "a real test PSNR: {done}");
    let loss = done["losses"]["total"].as_f64().unwrap();
    assert!(loss.is_finite() && loss > 0.0, "{done}");
    for key in ["created_at", "started_at", "finished_at"] {
        assert!(done[key].as_str().unwrap().ends_with('Z'), "{key}: {done}");
    }

    let artifacts = t.artifacts(&id).await;
    let names: Vec<&str> = artifacts
        .iter()
        .map(|a| a["name"].as_str().unwrap())
        .collect();
    for expected in [
        "config.json",
        "envmap.exr",
        "envmap.hdr",
        "envmap.png",
        "mesh.ply",
        "metrics.json",
        "model.glb",
        "model.json",
        "renders/s0/000.exr",
        "renders/s0/000.png",
        "renders/normal/001.png",
        "surfels.ply",
    ] {
        assert!(names.contains(&expected), "{expected} in {names:?}");
    }
    for artifact in &artifacts {
        let name = artifact["name"].as_str().unwrap();
        let path = format!("/v1/jobs/{id}/artifacts/{name}");
        let response = t.send(Method::GET, &path).await;
        assert_eq!(response.status(), 200, "{name}");
        let content_type = response.headers()["content-type"]
            .to_str()
            .unwrap()
            .to_string();
        assert_eq!(content_type, artifact["content_type"].as_str().unwrap());
        let bytes = response.bytes().await.unwrap();
        assert_eq!(
            bytes.len() as u64,
            artifact["size"].as_u64().unwrap(),
            "{name}"
        );
        match name {
            "envmap.exr" => {
                assert_eq!(content_type, "image/x-exr");
                assert_eq!(&bytes[..4], &[0x76, 0x2f, 0x31, 0x01]);
            }
            "metrics.json" => {
                let metrics: Value = serde_json::from_slice(&bytes).unwrap();
                assert_eq!(metrics["test_views"], 2);
                assert!(metrics["psnr"].as_f64().unwrap() > 8.0, "{metrics}");
            }
            "model.json" | "config.json" => {
                assert_eq!(content_type, "application/json");
            }
            "surfels.ply" | "mesh.ply" => assert!(bytes.starts_with(b"ply\n")),
            "model.glb" => {
                assert_eq!(content_type, "model/gltf-binary");
                assert_eq!(&bytes[..4], b"glTF");
            }
            "envmap.hdr" => {
                assert_eq!(content_type, "image/vnd.radiance");
                assert!(bytes.starts_with(b"#?RADIANCE"));
            }
            other if other.ends_with(".png") => assert_eq!(&bytes[1..4], b"PNG"),
            other if other.ends_with(".exr") => assert_eq!(&bytes[..4], &[0x76, 0x2f, 0x31, 0x01]),
            other => panic!("unexpected artifact {other}"),
        }
        // The same file by ranges: a middle slice, a suffix and an unsatisfiable one.
        let len = bytes.len();
        let part = t.get_range(&path, "bytes=2-5").await;
        assert_eq!(part.status(), 206);
        assert_eq!(
            part.headers()["content-range"],
            format!("bytes 2-5/{len}").as_str()
        );
        assert_eq!(part.bytes().await.unwrap(), bytes.slice(2..6));
        let suffix = t.get_range(&path, "bytes=-3").await;
        assert_eq!(suffix.bytes().await.unwrap(), bytes.slice(len - 3..));
        let beyond = t.get_range(&path, &format!("bytes={len}-")).await;
        assert_eq!(beyond.status(), 416);
    }
    let (status, body) = t
        .get_json(&format!("/v1/jobs/{id}/artifacts/../../phygap.sqlite3"))
        .await;
    assert_eq!(status, 404, "{body}");
    let (status, body) = t
        .get_json(&format!("/v1/jobs/{id}/artifacts/no-such-file.ply"))
        .await;
    assert_eq!((status, error_code(&body).0), (404, "not_found"));

    // A capture still used by no live job can be deleted; its files go too.
    let response = t.delete_capture(capture_id).await;
    assert_eq!(response.status(), 204);
    assert!(!dir.path().join("captures").join(capture_id).exists());
    let (status, _) = t.get_json(&format!("/v1/captures/{capture_id}")).await;
    assert_eq!(status, 404);

    // Metrics saw the job and the requests.
    let text = t.send(Method::GET, "/metrics").await.text().await.unwrap();
    assert!(text.contains("phygap_queue_depth 0\n"), "{text}");
    assert!(
        text.contains("phygap_job_duration_seconds_count{kind=\"train\",outcome=\"succeeded\"} 1"),
        "{text}"
    );
    assert!(
        text.contains("route=\"/v1/jobs/{id}\",status=\"200\""),
        "{text}"
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn tar_uploads_and_event_stream_follow_a_job_to_its_end() {
    let (_dir, t) = TestServer::start_fresh().await;
    let (status, capture) = t.upload(capture_tar()).await;
    assert_eq!(status, 201, "{capture}");
    let id = t
        .submit_job(capture["id"].as_str().unwrap(), train_config(60, 20))
        .await;
    let mut response = t.send(Method::GET, &format!("/v1/jobs/{id}/events")).await;
    assert_eq!(response.status(), 200);
    assert!(response.headers()["content-type"]
        .to_str()
        .unwrap()
        .starts_with("text/event-stream"));
    let deadline = Instant::now() + LONG;
    let mut text = String::new();
    while let Some(chunk) = tokio::time::timeout_at(deadline.into(), response.chunk())
        .await
        .expect("stream ends in time")
        .unwrap()
    {
        text.push_str(std::str::from_utf8(&chunk).unwrap());
    }
    let events: Vec<(String, Value)> = text
        .split("\n\n")
        .filter_map(|block| {
            let name = block.lines().find_map(|l| l.strip_prefix("event: "))?;
            let data = block.lines().find_map(|l| l.strip_prefix("data: "))?;
            Some((name.to_string(), serde_json::from_str(data).unwrap()))
        })
        .collect();
    assert!(events.len() >= 3, "{text}");
    let (last_name, last) = events.last().unwrap();
    assert_eq!(
        (last_name.as_str(), last["state"].as_str()),
        ("end", Some("succeeded"))
    );
    assert!(events[..events.len() - 1]
        .iter()
        .all(|(n, _)| n == "progress"));
    let iterations: Vec<u64> = events
        .iter()
        .map(|(_, j)| j["iteration"].as_u64().unwrap())
        .collect();
    assert!(
        iterations.windows(2).all(|w| w[0] <= w[1]),
        "{iterations:?}"
    );
    assert!(
        iterations.iter().any(|&i| i > 0 && i < 60),
        "saw intermediate progress: {iterations:?}"
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn idempotent_submit_returns_the_same_job() {
    let (_dir, t) = TestServer::start_fresh_with(|config| config.workers = 0).await;
    let capture_id = t.upload_capture().await;
    let body = json!({ "capture_id": capture_id, "config": train_config(10, 5) });
    let mut ids = Vec::new();
    for expected in [201, 200, 200] {
        let response = t.post_job(&body, Some("retry-1")).await;
        assert_eq!(response.status(), expected);
        ids.push(
            response.json::<Value>().await.unwrap()["id"]
                .as_str()
                .unwrap()
                .to_string(),
        );
    }
    assert!(ids.iter().all(|id| id == &ids[0]), "{ids:?}");
    let other = json!({ "capture_id": capture_id, "config": train_config(11, 5) });
    let response = t.post_job(&other, Some("retry-1")).await;
    expect_error(response, 422, "idempotency_key_reused").await;
    let (_, list) = t.get_json("/v1/jobs").await;
    assert_eq!(list["jobs"].as_array().unwrap().len(), 1);
    // Without a key, each submit is a new job.
    t.submit(&capture_id, train_config(10, 5)).await;
    let (_, list) = t.get_json("/v1/jobs").await;
    assert_eq!(list["jobs"].as_array().unwrap().len(), 2);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn invalid_job_requests_are_rejected_with_reasons() {
    let (_dir, t) = TestServer::start_fresh().await;
    let capture_id = t.upload_capture().await;
    let cases = [
        (
            json!({ "capture_id": capture_id, "config": { "iterations": 0 } }),
            422,
            "invalid_config",
            "iterations",
        ),
        (
            json!({ "capture_id": capture_id, "config": { "iteratons": 5 } }),
            422,
            "invalid_request",
            "iteratons",
        ),
        (
            json!({ "capture_id": "cap_missing" }),
            422,
            "unknown_capture",
            "cap_missing",
        ),
        (
            json!({ "config": {} }),
            422,
            "invalid_request",
            "capture_id",
        ),
    ];
    for (body, status, code, needle) in cases {
        let response = t.post_job(&body, None).await;
        let message = expect_error(response, status, code).await;
        assert!(message.contains(needle), "{body}: {message}");
    }
    let response = t.post_body("/v1/jobs", "{not json").await;
    expect_error(response, 400, "invalid_json").await;
    // Garbage to every POST route and unknown routes/methods: JSON errors, never a crash.
    for path in [
        "/v1/captures",
        "/v1/jobs",
        "/v1/jobs/job_x/cancel",
        "/v1/jobs/job_x/relight",
    ] {
        let response = t.post_body(path, vec![0xffu8; 1000]).await;
        assert!(
            response.status().is_client_error(),
            "{path}: {}",
            response.status()
        );
        let body: Value = response.json().await.unwrap();
        assert_ne!(error_code(&body).0, "<no code>", "{path}");
    }
    let (status, body) = t.get_json("/v1/nope").await;
    assert_eq!((status, error_code(&body).0), (404, "not_found"));
    let response = t.send(Method::PUT, "/v1/jobs").await;
    expect_error(response, 405, "method_not_allowed").await;
    let (status, _) = t.get_json("/healthz").await;
    assert_eq!(status, 200);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn cancel_stops_running_and_queued_jobs() {
    let (_dir, t) = TestServer::start_fresh().await;
    let capture_id = t.upload_capture().await;
    let running_id = t.submit_job(&capture_id, train_config(100_000, 1000)).await;
    let queued_id = t.submit_job(&capture_id, train_config(10, 5)).await;
    t.wait_iteration(&running_id, 5).await;
    // The capture is in use meanwhile.
    let response = t.delete_capture(&capture_id).await;
    assert_eq!(response.status(), 409);

    let response = t.cancel(&queued_id).await;
    assert_eq!(response.status(), 200);
    assert_eq!(
        response.json::<Value>().await.unwrap()["state"],
        "cancelled"
    );
    let response = t.cancel(&running_id).await;
    assert_eq!(response.status(), 200);
    assert_eq!(
        response.json::<Value>().await.unwrap()["cancel_requested"],
        true
    );
    let cancelled = t.wait_state(&running_id, "cancelled", LONG).await;
    assert_eq!(cancelled["state"], "cancelled", "{cancelled}");
    assert!(cancelled["iteration"].as_u64().unwrap() < 100_000);
    assert!(cancelled["finished_at"].is_string());
    let response = t.cancel(&running_id).await;
    assert_eq!(response.status(), 409);
    let (status, _) = t.get_json(&format!("/v1/jobs/{queued_id}")).await;
    assert_eq!(status, 200);
    assert!(t.artifacts(&queued_id).await.is_empty());
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn bearer_token_guards_v1_but_not_healthz() {
    let (dir, t) =
        TestServer::start_fresh_with(|config| config.token = Some("s3cret".into())).await;
    let (status, _) = t.get_json("/healthz").await;
    assert_eq!(status, 200);
    let (status, body) = t.get_json("/v1/jobs").await;
    assert_eq!((status, error_code(&body).0), (401, "unauthorized"));
    let wrong = t.get_with_token("/v1/jobs", "s3creT").await;
    assert_eq!(wrong.status(), 401);
    assert_eq!(wrong.headers()["www-authenticate"], "Bearer");
    let upload = t
        .post_body(
            "/v1/captures",
            b"an archive is never read before the token is checked".to_vec(),
        )
        .await;
    assert_eq!(upload.status(), 401);
    assert_eq!(count_files(&dir.path().join("captures")), 0);
    let right = t.get_with_token("/v1/jobs", "s3cret").await;
    assert_eq!(right.status(), 200);
    t.server.shutdown().await;

    let (_open_dir, t) = TestServer::start_fresh().await;
    let (status, _) = t.get_json("/v1/jobs").await;
    assert_eq!(status, 200);
    t.server.shutdown().await;
}

/// Each bad upload: its status, its error code, a word of its message; and nothing left behind.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn bad_uploads_are_rejected_and_leave_no_state() {
    let (dir, t) = TestServer::start_fresh_with(|config| config.max_upload_bytes = 256 << 10).await;
    let file = |name: &str, data: &[u8]| (name.to_string(), data.to_vec());
    let mut corrupt = capture_zip();
    corrupt.truncate(corrupt.len() / 2);
    let valid_transforms = capture_transforms();
    let cases: Vec<(&str, Vec<u8>, u16, &str, &str)> = vec![
        ("corrupt zip", corrupt, 400, "invalid_archive", "corrupt"),
        (
            "garbage",
            b"hello, this is not an archive".to_vec(),
            415,
            "unsupported_archive",
            ".zip",
        ),
        ("empty", Vec::new(), 400, "empty_upload", "empty"),
        (
            "traversal zip",
            zip_of(&[
                file("transforms.json", b"{}"),
                file("../../escape.txt", b"x"),
            ]),
            400,
            "unsafe_archive",
            "traversal",
        ),
        (
            "absolute tar",
            tar_with_raw_name("/tmp/phygap-evil.txt"),
            400,
            "unsafe_archive",
            "absolute",
        ),
        (
            "symlink tar",
            tar_with_symlink(),
            400,
            "unsafe_archive",
            "links",
        ),
        (
            "too large",
            vec![7u8; 300 << 10],
            413,
            "payload_too_large",
            "MiB",
        ),
        (
            "bomb",
            zip_of(&[
                file("transforms.json", &valid_transforms),
                file("zeros.bin", &vec![0u8; 64 << 20]),
            ]),
            413,
            "payload_too_large",
            "bomb",
        ),
        (
            "no transforms.json",
            zip_of(&[file("images/a.png", b"x")]),
            422,
            "invalid_capture",
            "transforms.json",
        ),
        (
            "missing image",
            zip_of(&[file("transforms.json", &valid_transforms)]),
            422,
            "invalid_capture",
            "missing file",
        ),
    ];
    for (label, body, status, code, needle) in cases {
        let (got, response) = t.upload(body).await;
        assert_eq!(got, status, "{label}: {response}");
        let (got_code, message) = error_code(&response);
        assert_eq!(got_code, code, "{label}: {message}");
        assert!(message.contains(needle), "{label}: {message}");
        assert!(
            !response
                .to_string()
                .contains(&*dir.path().to_string_lossy()),
            "{label}: the answer shows a server path: {response}"
        );
        if label == "missing image" {
            // Each problem is listed with its frame and key, as `phygap inspect` names it.
            let problems = response["error"]["problems"].as_array().unwrap();
            assert!(!problems.is_empty(), "{response}");
            assert!(problems
                .iter()
                .all(|p| p["frame"].as_str().unwrap().starts_with("frame ")));
            assert!(problems
                .iter()
                .any(|p| p["message"].as_str().unwrap().contains("missing file")));
        } else {
            assert!(
                response["error"].get("problems").is_none(),
                "{label}: {response}"
            );
        }
        assert_eq!(
            count_files(&dir.path().join("tmp")),
            0,
            "{label}: temp files left"
        );
        assert_eq!(
            count_files(&dir.path().join("captures")),
            0,
            "{label}: capture files left"
        );
        assert!(
            t.server
                .state()
                .store
                .capture_ids()
                .await
                .unwrap()
                .is_empty(),
            "{label}: record left"
        );
    }
    assert!(!std::path::Path::new("/tmp/phygap-evil.txt").exists());
    // Too large without a Content-Length (chunked): stopped while streaming.
    let chunks: Vec<Result<Vec<u8>, std::io::Error>> =
        (0..40).map(|_| Ok(vec![1u8; 16 << 10])).collect();
    let stream = reqwest::Body::wrap_stream(futures_util::stream::iter(chunks));
    let response = t.post_body("/v1/captures", stream).await;
    assert_eq!(response.status(), 413);
    assert_eq!(count_files(&dir.path().join("tmp")), 0);
    // And a good upload still works afterwards.
    t.upload_capture().await;
    assert_eq!(t.server.state().store.capture_ids().await.unwrap().len(), 1);
    t.server.shutdown().await;
}

/// The bytes of the test capture's transforms.json (which names images).
fn capture_transforms() -> Vec<u8> {
    let dir = tempfile::tempdir().unwrap();
    write_capture(dir.path());
    std::fs::read(dir.path().join("transforms.json")).unwrap()
}

/// A tar whose one entry has `name` written raw into the header (builders refuse such names).
fn tar_with_raw_name(name: &str) -> Vec<u8> {
    let mut header = tar::Header::new_ustar();
    header.as_old_mut().name[..name.len()].copy_from_slice(name.as_bytes());
    header.set_size(1);
    header.set_mode(0o644);
    header.set_cksum();
    let mut bytes = header.as_bytes().to_vec();
    bytes.extend_from_slice(b"x");
    bytes.resize(1024, 0);
    bytes.extend_from_slice(&[0u8; 1024]);
    bytes
}

fn tar_with_symlink() -> Vec<u8> {
    let mut builder = tar::Builder::new(Vec::new());
    let mut header = tar::Header::new_ustar();
    header.set_entry_type(tar::EntryType::Symlink);
    header.set_size(0);
    builder
        .append_link(&mut header, "transforms.json", "/etc/passwd")
        .unwrap();
    builder.into_inner().unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn relight_runs_as_its_own_job() {
    let (dir, t) = TestServer::start_fresh().await;
    let train_id = t.start_training(10, 5).await;
    // Not trained yet (or still running): refused.
    let envmap_path = dir.path().join("sky.exr");
    phygap::formats::image_io::write_exr(
        &envmap_path,
        &phygap::formats::image_io::Image::filled(8, 4, 3, 2.0),
    )
    .unwrap();
    let envmap = std::fs::read(&envmap_path).unwrap();
    t.wait_state(&train_id, "succeeded", LONG).await;
    let response = t.relight(&train_id, b"not an image".to_vec(), "90").await;
    assert_eq!(response.status(), 415);
    let response = t.relight(&train_id, envmap.clone(), "90").await;
    assert_eq!(response.status(), 201);
    let relight: Value = response.json().await.unwrap();
    assert_eq!(
        (relight["kind"].as_str(), relight["parent_job_id"].as_str()),
        (Some("relight"), Some(train_id.as_str()))
    );
    let relight_id = relight["id"].as_str().unwrap();
    t.wait_succeeded(relight_id).await;
    let names = t.artifact_names(relight_id).await;
    let expected: Vec<String> = ["s0", "s1", "s2"]
        .iter()
        .flat_map(|k| ["000.exr", "000.png", "001.exr", "001.png"].map(|f| format!("{k}/{f}")))
        .collect();
    assert_eq!(names, expected, "the model's two test cameras, relit");
    let relit = t
        .send(
            Method::GET,
            &format!("/v1/jobs/{relight_id}/artifacts/s0/000.exr"),
        )
        .await
        .bytes()
        .await
        .unwrap();
    let relit_path = dir.path().join("relit.exr");
    std::fs::write(&relit_path, &relit).unwrap();
    let (image, _) = phygap::formats::image_io::read_image(&relit_path).unwrap();
    let mean = image.data.iter().map(|&v| f64::from(v)).sum::<f64>() / image.data.len() as f64;
    assert!(
        mean > 0.0 && image.first_non_finite().is_none(),
        "the object is lit by the uniform map: mean {mean}"
    );
    // Relighting a relight job is refused.
    let response = t.relight(relight_id, envmap, "90").await;
    assert_eq!(response.status(), 409);
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn fifty_concurrent_pollers_are_all_answered() {
    let (_dir, t) = TestServer::start_fresh().await;
    let id = t.start_training(200, 50).await;
    let url = t.url(&format!("/v1/jobs/{id}"));
    let mut tasks = Vec::new();
    for _ in 0..50 {
        let client = t.client.clone();
        let url = url.clone();
        tasks.push(tokio::spawn(async move {
            let mut latencies = Vec::new();
            let mut saw_running = false;
            let deadline = Instant::now() + LONG;
            for _ in 0..400 {
                let start = Instant::now();
                let response = client.get(&url).send().await.expect("answered");
                assert_eq!(response.status(), 200);
                let job: Value = response.json().await.unwrap();
                latencies.push(start.elapsed());
                saw_running |= job["state"] == "running";
                if job["state"] == "succeeded" || Instant::now() > deadline {
                    break;
                }
                tokio::time::sleep(Duration::from_millis(20)).await;
            }
            (latencies, saw_running)
        }));
    }
    let mut all = Vec::new();
    let mut running_seen = 0;
    for task in tasks {
        let (latencies, saw_running) = task.await.unwrap();
        all.extend(latencies);
        running_seen += saw_running as usize;
    }
    t.wait_succeeded(&id).await;
    assert!(running_seen > 0, "pollers overlapped the running job");
    all.sort();
    let pct = |p: f64| all[((all.len() - 1) as f64 * p).round() as usize];
    println!(
        "GET /v1/jobs/{{id}} under 50 concurrent pollers while a job runs: {} requests, p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms",
        all.len(),
        pct(0.5).as_secs_f64() * 1e3,
        pct(0.99).as_secs_f64() * 1e3,
        all.last().unwrap().as_secs_f64() * 1e3
    );
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn openapi_document_and_router_list_the_same_routes() {
    let (_dir, t) = TestServer::start_fresh().await;
    let (status, served) = t.get_json("/v1/openapi.json").await;
    assert_eq!(status, 200);
    let spec = phygap_api::http::openapi::spec_json().unwrap();
    assert_eq!(served, spec);
    assert_eq!(spec["openapi"], "3.1.0");
    let mut routes: Vec<(String, String)> = phygap_api::http::route_table(1)
        .iter()
        .map(|r| {
            (
                r.method.to_string(),
                phygap_api::http::openapi::openapi_path(r.path),
            )
        })
        .collect();
    routes.sort();
    assert_eq!(routes, phygap_api::http::openapi::spec_operations(&spec));
    // Every route answers (no 404 from the router for any documented path).
    for (method, path) in &routes {
        let concrete = path.replace("{id}", "job_none").replace("{name}", "x.json");
        let (status, body) =
            status_and_json(t.send(method.parse().unwrap(), &concrete).await).await;
        assert!(
            !(status == 404 && error_code(&body).1.starts_with("no route")),
            "{method} {path}"
        );
        assert_ne!(status, 405, "{method} {path}");
    }
    t.server.shutdown().await;
}
