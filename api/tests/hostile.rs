//! Hostile inputs, each one a finding of the attack on the service (issue 27), reproduced
//! against the real `phygap-api serve` process, which must answer with a named error (or fail
//! only the job, with a named reason) and stay up: a few-byte image declaring 10¹⁰ pixels, as a
//! capture image and as a relight map; a job config asking for 4·10⁹ surfels; relight cameras of
//! 10¹⁰ pixels; a capture of 8,000 frames; a job over its memory limit beside a job that
//! succeeds; connections that trickle, idle or crowd; and every error in the one JSON shape.

mod common;

use std::time::{Duration, Instant};

use common::process::ServerProcess;
use common::*;
use phygap::testing::hostile::exr_declaring;
use serde_json::{json, Value};
use tokio::io::{AsyncReadExt, AsyncWriteExt};

/// The test capture's files, at the archive's top level.
fn capture_files() -> Vec<(String, Vec<u8>)> {
    let dir = tempfile::tempdir().unwrap();
    write_capture(dir.path());
    files_of(dir.path())
}

/// The test capture with one file replaced.
fn capture_with(name: &str, bytes: Vec<u8>) -> Vec<u8> {
    let mut files = capture_files();
    let file = files.iter_mut().find(|(n, _)| n == name).unwrap();
    file.1 = bytes;
    tar_of(&files)
}

/// The test capture with its transforms.json changed by `edit`.
fn capture_with_transforms(edit: impl FnOnce(&mut Value)) -> Vec<u8> {
    let mut files = capture_files();
    let file = files
        .iter_mut()
        .find(|(n, _)| n == "transforms.json")
        .unwrap();
    let mut doc: Value = serde_json::from_slice(&file.1).unwrap();
    edit(&mut doc);
    file.1 = serde_json::to_vec(&doc).unwrap();
    tar_of(&files)
}

async fn relight_form(
    api: &ApiClient,
    job: &str,
    envmap: Vec<u8>,
    cameras: Option<Value>,
) -> reqwest::Response {
    let mut form = reqwest::multipart::Form::new().part(
        "envmap",
        reqwest::multipart::Part::bytes(envmap).file_name("map.exr"),
    );
    if let Some(cameras) = cameras {
        form = form.part(
            "cameras",
            reqwest::multipart::Part::bytes(serde_json::to_vec(&cameras).unwrap())
                .file_name("cameras.json"),
        );
    }
    api.client
        .post(api.url(&format!("/v1/jobs/{job}/relight")))
        .multipart(form)
        .send()
        .await
        .unwrap()
}

/// Cameras of one `side × side` frame.
fn one_camera(side: u32) -> Value {
    json!({"camera_convention": "OpenGL", "frames": [{
        "w": side, "h": side, "fl_x": side, "fl_y": side,
        "transform_matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 3], [0, 0, 0, 1]]}]})
}

/// Findings 1–5, 8, 9 and 12 against one server process, which answers `/healthz` after each.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn inputs_that_once_aborted_the_server_are_answered_and_it_stays_up() {
    let dir = tempfile::tempdir().unwrap();
    let server = ServerProcess::start(dir.path(), &["--job-memory-mb", "1024"]).await;
    let api = &server.api;
    let huge_exr = exr_declaring(100_000, 100_000);

    // 1. A capture image declaring 100000 × 100000 pixels: refused from its header.
    let (status, body) = api
        .upload(capture_with("s0/000.exr", huge_exr.clone()))
        .await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "invalid_capture"),
        "{body}"
    );
    let problem = &body["error"]["problems"][0];
    assert!(
        problem["message"]
            .as_str()
            .unwrap()
            .contains("100000×100000 pixels but w×h is 24×24"),
        "{body}"
    );
    server
        .assert_up("a capture image declaring 10¹⁰ pixels")
        .await;

    // 3. A config asking for 4·10⁹ surfels: refused before anything is queued.
    let capture = api.upload_capture().await;
    let config = json!({"iterations": 40, "max_surfels": 4294967295u64,
                        "initial_surfels": 4000000000u64});
    let (status, body) = api.submit(&capture, config).await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "invalid_config"),
        "{body}"
    );
    assert!(error_code(&body).1.contains("max_surfels"), "{body}");
    server.assert_up("a config of 4·10⁹ surfels").await;

    // A trained model to relight.
    let trained = api.submit_job(&capture, train_config(20, 10)).await;
    api.wait_succeeded(&trained).await;
    let jobs_before = api.get_json("/v1/jobs").await.1["jobs"]
        .as_array()
        .unwrap()
        .len();

    // 2. The same image as a relight map: refused at submit, so no job can abort a worker.
    let response = relight_form(api, &trained, huge_exr, None).await;
    let message = expect_error(response, 422, "envmap_too_large").await;
    assert!(message.contains("100000×100000"), "{message}");
    server
        .assert_up("a relight map declaring 10¹⁰ pixels")
        .await;

    // 4. Relight cameras of one 100000 × 100000 frame, and of one 60000 × 60000 frame.
    let map_path = dir.path().join("map.exr");
    let sky = phygap::formats::image_io::Image::filled(16, 8, 3, 0.5);
    phygap::formats::image_io::write_exr(&map_path, &sky).unwrap();
    let map = std::fs::read(&map_path).unwrap();
    let response = relight_form(api, &trained, map.clone(), Some(one_camera(100_000))).await;
    let message = expect_error(response, 422, "invalid_cameras").await;
    assert!(message.contains("at most 65536 pixels"), "{message}");
    let response = relight_form(api, &trained, map.clone(), Some(one_camera(60_000))).await;
    let message = expect_error(response, 422, "cameras_too_large").await;
    assert!(message.contains("max_pixels_per_view"), "{message}");
    let jobs_after = api.get_json("/v1/jobs").await.1["jobs"]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(jobs_after, jobs_before, "refused relights queue no job");
    server.assert_up("relight cameras of 10¹⁰ pixels").await;

    // 5. 8,000 frames naming the capture's ten: refused before a pixel is decoded, in a child
    // process; the service's own memory does not grow.
    let resident = server.resident_bytes();
    let many = capture_with_transforms(|doc| {
        let frames = doc["frames"].as_array().unwrap().clone();
        doc["frames"] = json!((0..8000)
            .map(|i| frames[i % frames.len()].clone())
            .collect::<Vec<_>>());
    });
    let (status, body) = api.upload(many).await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "capture_too_large"),
        "{body}"
    );
    assert!(error_code(&body).1.contains("max_views"), "{body}");
    let grown = server.resident_bytes().saturating_sub(resident);
    assert!(grown < 64 << 20, "the service grew by {} MiB", grown >> 20);
    server.assert_up("a capture of 8,000 frames").await;

    // 12. A capture without test views, and a focal length of 1e308: refused at upload.
    let no_test = capture_with_transforms(|doc| {
        for frame in doc["frames"].as_array_mut().unwrap() {
            frame["split"] = json!("train");
        }
    });
    let (status, body) = api.upload(no_test).await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "invalid_capture"),
        "{body}"
    );
    assert!(error_code(&body).1.contains("test view"), "{body}");
    let far_focal = capture_with_transforms(|doc| doc["fl_x"] = json!(1e308));
    let (status, body) = api.upload(far_focal).await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "invalid_capture"),
        "{body}"
    );
    assert_eq!(body["error"]["problems"][0]["key"], "fl_x", "{body}");

    // 9. A map whose header passes but whose pixels are missing fails its job, which names the
    // file as uploaded, not the service's folders.
    let response = relight_form(api, &trained, exr_declaring(64, 32), None).await;
    let (status, job) = status_and_json(response).await;
    assert_eq!(status, 201, "{job}");
    let failed = api
        .wait_state(job["id"].as_str().unwrap(), "failed", LONG)
        .await;
    let error = failed["error"].as_str().unwrap();
    assert_eq!(failed["error_code"], "relighting_failed", "{failed}");
    assert!(error.contains("envmap.exr"), "{error}");
    let data_dir = dir.path().canonicalize().unwrap();
    assert!(
        !error.contains(&*dir.path().to_string_lossy())
            && !error.contains(&*data_dir.to_string_lossy()),
        "{error}"
    );

    // 8. Artifacts have validators, and conditional requests use them.
    let path = format!("/v1/jobs/{trained}/artifacts/metrics.json");
    let whole = api.send(reqwest::Method::GET, &path).await;
    assert_eq!(whole.status(), 200);
    let header = |r: &reqwest::Response, name: &str| {
        r.headers()
            .get(name)
            .map(|v| v.to_str().unwrap().to_owned())
    };
    let etag = header(&whole, "etag").expect("an ETag");
    assert!(etag.starts_with('"') && !etag.starts_with("W/"), "{etag}");
    assert!(header(&whole, "last-modified").is_some());
    assert_eq!(
        header(&whole, "cache-control").as_deref(),
        Some("private, no-cache")
    );
    let size = whole.bytes().await.unwrap().len();
    let get = |headers: &[(&str, &str)]| {
        let mut request = api.client.get(api.url(&path));
        for (name, value) in headers {
            request = request.header(*name, *value);
        }
        request.send()
    };
    assert_eq!(
        get(&[("if-none-match", &etag)]).await.unwrap().status(),
        304
    );
    assert_eq!(get(&[("if-none-match", "*")]).await.unwrap().status(), 304);
    assert_eq!(
        get(&[("if-none-match", "\"stale\"")])
            .await
            .unwrap()
            .status(),
        200
    );
    let partial = get(&[("range", "bytes=0-3"), ("if-range", &etag)])
        .await
        .unwrap();
    assert_eq!(partial.status(), 206);
    let stale = get(&[("range", "bytes=0-3"), ("if-range", "\"stale\"")])
        .await
        .unwrap();
    assert_eq!(stale.status(), 200, "a range of another file is not sent");
    assert_eq!(stale.bytes().await.unwrap().len(), size);
    server.assert_up("the whole session").await;
}

/// A job over its memory limit fails `out_of_memory` (twice, then for good) within seconds,
/// while another job on the same service succeeds and the API answers throughout.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_job_over_its_memory_limit_fails_while_others_run() {
    let dir = tempfile::tempdir().unwrap();
    let flags = [
        "--workers",
        "2",
        "--job-memory-mb",
        "400",
        "--lease-seconds",
        "2",
    ];
    let server = ServerProcess::start(dir.path(), &flags).await;
    let api = &server.api;
    let capture = api.upload_capture().await;
    let greedy = json!({"iterations": 100, "initial_surfels": 10_000_000,
                        "max_surfels": 10_000_000, "backend": "fast", "gridmap": false});
    let greedy = api.submit_job(&capture, greedy).await;
    let modest = api.submit_job(&capture, train_config(30, 10)).await;
    let started = Instant::now();
    let failed = api.wait_state(&greedy, "failed", LONG).await;
    assert_eq!(failed["state"], "failed", "{failed}");
    assert_eq!(failed["error_code"], "out_of_memory", "{failed}");
    assert_eq!(failed["attempts"], 2, "one retry, then failed: {failed}");
    let error = failed["error"].as_str().unwrap();
    assert!(
        error.contains("memory allocation of") && error.contains("400 MiB"),
        "{error}"
    );
    server.assert_up("a job over its memory limit").await;
    api.wait_succeeded(&modest).await;
    println!(
        "the greedy job failed out_of_memory after {:.1} s",
        started.elapsed().as_secs_f64()
    );
    server.assert_up("both jobs").await;
}

/// Reads until the peer closes (`true`) or `limit` passes (`false`).
async fn closed_within(stream: &mut tokio::net::TcpStream, limit: Duration) -> bool {
    let mut buffer = [0u8; 4096];
    let deadline = tokio::time::Instant::now() + limit;
    loop {
        match tokio::time::timeout_at(deadline, stream.read(&mut buffer)).await {
            Ok(Ok(0)) | Ok(Err(_)) => return true,
            Ok(Ok(_)) => continue,
            Err(_) => return false,
        }
    }
}

/// Finding 6: a head trickled a byte at a time, an idle connection and a body at 20 bytes a
/// second are cut off; a crowd of idle connections holds no more than the connection limit.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn slow_idle_and_crowding_connections_are_cut_off() {
    let dir = tempfile::tempdir().unwrap();
    let flags = [
        "--header-timeout-seconds",
        "2",
        "--upload-window-seconds",
        "2",
        "--max-connections",
        "8",
    ];
    let server = ServerProcess::start(dir.path(), &flags).await;
    // The listener and the runtime's own sockets (signal handling), before any connection.
    let baseline = server.open_sockets();
    let address = format!("127.0.0.1:{}", server.port);
    let connect = || tokio::net::TcpStream::connect(address.clone());

    let mut idle = connect().await.unwrap();
    assert!(
        closed_within(&mut idle, Duration::from_secs(20)).await,
        "an idle connection stays open"
    );

    let mut trickle = connect().await.unwrap();
    let head = b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Slow: 1234567890\r\n\r\n";
    let mut cut_off = false;
    for byte in head {
        if trickle.write_all(&[*byte]).await.is_err() {
            cut_off = true;
            break;
        }
        tokio::time::sleep(Duration::from_millis(400)).await;
        let mut probe = [0u8; 1];
        if let Ok(Ok(0)) =
            tokio::time::timeout(Duration::from_millis(1), trickle.read(&mut probe)).await
        {
            cut_off = true;
            break;
        }
    }
    assert!(cut_off, "a head trickled over 20 s was served");

    let mut slow = connect().await.unwrap();
    slow.write_all(
        b"POST /v1/captures HTTP/1.1\r\nHost: x\r\nContent-Type: application/x-tar\r\n\
          Content-Length: 100000\r\n\r\n",
    )
    .await
    .unwrap();
    // Ten bytes every half second until the server answers; then read the answer to its end.
    let mut answer = Vec::new();
    let mut chunk = [0u8; 4096];
    for _ in 0..100 {
        if answer.is_empty() && slow.write_all(&[b'x'; 10]).await.is_err() {
            break;
        }
        match tokio::time::timeout(Duration::from_millis(500), slow.read(&mut chunk)).await {
            Ok(Ok(0)) | Ok(Err(_)) => break,
            Ok(Ok(n)) => answer.extend_from_slice(&chunk[..n]),
            Err(_) => {}
        }
    }
    let answer = String::from_utf8_lossy(&answer);
    assert!(
        answer.starts_with("HTTP/1.1 408") && answer.contains("\"request_timeout\""),
        "{answer}"
    );

    let mut crowd = Vec::new();
    for _ in 0..30 {
        crowd.push(connect().await.unwrap());
    }
    tokio::time::sleep(Duration::from_millis(500)).await;
    let held = server.open_sockets() - baseline;
    assert!(
        held <= 8,
        "{held} connections held with a limit of 8 ({} sockets before)",
        baseline
    );
    // Once the idle crowd times out, requests are served again.
    drop(crowd);
    server.assert_up("a crowd of idle connections").await;
}

/// Findings 7, 10, 11 and 13: security headers everywhere, every error in the JSON shape,
/// per-account idempotency keys, and the Bearer scheme in any case.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn every_error_is_json_and_every_answer_carries_security_headers() {
    let token = "a-token-of-sixteen+";
    let (_dir, t) = TestServer::start_fresh_with(|c| c.token = Some(token.into())).await;
    let api = ApiClient::with_token(t.base.clone(), token);
    for path in ["/", "/v1/jobs", "/nowhere"] {
        let response = api.send(reqwest::Method::GET, path).await;
        let headers = response.headers();
        for (name, value) in phygap_api::http::security_headers::HEADERS {
            if name == "cache-control" && path == "/" {
                continue; // The page revalidates (no-cache) instead.
            }
            assert_eq!(
                headers.get(&name).map(|v| v.to_str().unwrap()),
                Some(value),
                "{name} on {path}"
            );
        }
    }
    let json_error = |response: reqwest::Response, status: u16, code: &'static str| async move {
        let content_type = response.headers()["content-type"]
            .to_str()
            .unwrap()
            .to_owned();
        assert_eq!(content_type, "application/json");
        expect_error(response, status, code).await
    };
    json_error(
        api.send(reqwest::Method::GET, "/v1/jobs/%FF").await,
        400,
        "bad_request",
    )
    .await;
    let long_path = format!("/v1/jobs/{}", "x".repeat(10_000));
    json_error(
        api.send(reqwest::Method::GET, &long_path).await,
        414,
        "uri_too_long",
    )
    .await;
    let big_header = api
        .client
        .get(api.url("/v1/jobs"))
        .header("x-padding", "y".repeat(40_000))
        .send()
        .await
        .unwrap();
    json_error(big_header, 431, "headers_too_large").await;
    let mut many = api.client.get(api.url("/v1/jobs"));
    for i in 0..150 {
        many = many.header(format!("x-h{i}"), "1");
    }
    json_error(many.send().await.unwrap(), 431, "headers_too_large").await;
    let huge_job = api
        .client
        .post(api.url("/v1/jobs"))
        .header("content-type", "application/json")
        .body(vec![b' '; 3 << 20])
        .send()
        .await
        .unwrap();
    // The unread rest of the body ends the connection; the client must not reuse it.
    assert_eq!(huge_job.headers()["connection"], "close");
    json_error(huge_job, 413, "payload_too_large").await;
    let long_entry = tar_of(&[(format!("{}.exr", "n".repeat(300)), vec![1, 2, 3])]);
    let (status, body) = api.upload(long_entry).await;
    assert_eq!(
        (status, error_code(&body).0),
        (400, "unsafe_archive"),
        "{body}"
    );

    // 13. The scheme's name in any case.
    let lower = t
        .client
        .get(t.url("/v1/jobs"))
        .header("authorization", format!("bearer {token}"))
        .send()
        .await
        .unwrap();
    assert_eq!(lower.status(), 200);
    t.server.shutdown().await;
}

/// Finding 13: an admin token shorter than 16 characters does not start a service.
#[test]
fn a_short_admin_token_is_refused_at_start() {
    let dir = tempfile::tempdir().unwrap();
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_phygap-api"))
        .args([
            "serve",
            "--bind",
            "127.0.0.1:0",
            "--token",
            "x",
            "--data-dir",
        ])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("at least 16"), "{stderr}");
}

/// Issue 29's admission: a training job whose capture cannot fit the job memory limit at the
/// working resolution it asks for is refused when submitted, naming what would fit.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_job_whose_capture_cannot_fit_is_refused_at_submit() {
    let (_dir, t) = TestServer::start_fresh_with(|c| {
        c.limits.job.memory_bytes = Some(200 << 20);
    })
    .await;
    let capture = t.upload_capture().await;
    let (_, record) = t.get_json(&format!("/v1/captures/{capture}")).await;
    assert_eq!(
        (record["width"].as_u64(), record["height"].as_u64()),
        (Some(24), Some(24))
    );
    let (status, body) = t.submit(&capture, train_config(20, 10)).await;
    assert_eq!(
        (status, error_code(&body).0),
        (422, "capture_too_large"),
        "{body}"
    );
    assert!(error_code(&body).1.contains("job memory limit"), "{body}");
    assert_eq!(t.get_json("/v1/jobs").await.1["jobs"], json!([]));
    t.server.shutdown().await;
}
