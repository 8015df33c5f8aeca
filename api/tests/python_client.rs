//! The Python client (`clients/python`) against a real service: `clients/python/tests/
//! test_client.py` uploads (in resumable parts, interrupted and resumed), trains, follows the progress, downloads (and resumes a download),
//! relights and meets the service's errors. Needs `python3` with `httpx` (`.ci/run` installs
//! it); skips with a notice without them, except under `CI=true`.

mod common;

use std::path::Path;

use common::*;

fn python_with_httpx() -> bool {
    std::process::Command::new("python3")
        .args(["-c", "import httpx"])
        .output()
        .is_ok_and(|o| o.status.success())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_python_client_drives_a_whole_session() {
    if !python_with_httpx() {
        assert!(
            !phygap::testing::running_in_ci(),
            "CI=true but python3 with httpx is missing"
        );
        println!("skipping: python3 with httpx not found (pip install httpx)");
        return;
    }
    let (_dir, t) = TestServer::start_fresh().await;
    let scratch = tempfile::tempdir().unwrap();
    let capture = scratch.path().join("capture.tar");
    std::fs::write(&capture, padded_capture_tar()).unwrap();
    let envmap = scratch.path().join("studio.exr");
    let sky = phygap::formats::image_io::Image::filled(32, 16, 3, 0.8);
    phygap::formats::image_io::write_exr(&envmap, &sky).unwrap();
    let script =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../clients/python/tests/test_client.py");
    let base = t.base.clone();
    let output = tokio::task::spawn_blocking(move || {
        std::process::Command::new("python3")
            .arg(script)
            .arg(&base)
            .arg(&capture)
            .arg(&envmap)
            .output()
            .unwrap()
    })
    .await
    .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr),
    );
    assert!(output.status.success(), "{stdout}\n{stderr}");
    assert!(stdout.contains("every check passed"), "{stdout}");
    t.server.shutdown().await;
}
