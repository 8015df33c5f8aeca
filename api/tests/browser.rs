//! The web page in a real browser: headless Chromium driven through chromedriver against a real
//! server on loopback (with a token). It answers the token prompt, uploads a broken capture (the
//! validation report names its problems) and the synthetic one, starts a small job from the form,
//! waits for the live job list to say `succeeded`, opens the result viewer (the WebGL canvas
//! really draws: its pixels are sampled, for the material mesh and for the exported `model.glb`;
//! captured views and renders are shown), relights the model from the page, checks a phone-width
//! layout, and that the console logged no error.
//!
//! Skips with a notice when Chromium or chromedriver is missing (`apt-get install chromium
//! chromium-driver`), except under `CI=true`, where that fails. With `PHYGAP_WEB_SCREENSHOTS=DIR`
//! the pages' screenshots are written there; with `PHYGAP_WEB_ITERATIONS=N` the page is given a
//! larger capture to train with the default settings for N steps: the capture folder
//! `PHYGAP_WEB_CAPTURE` names, else the checkered creature (24 views of 96 px). The docs'
//! screenshots are made so.

mod common;
mod webdriver;

use std::path::PathBuf;
use std::time::Duration;

use common::*;
use serde_json::{json, Value};
use webdriver::{Browser, Session};

const TOKEN: &str = "page-test-token";

/// What the page is given to reconstruct.
struct Scenario {
    archive: Vec<u8>,
    /// The archive's file name (its extension says zip or tar).
    file_name: &'static str,
    views: usize,
    test_views: usize,
    iterations: u32,
    /// The job form's extra settings (JSON), and whether GridMap stays on.
    extra: &'static str,
    gridmap: bool,
    /// How long training may take.
    training: Duration,
}

impl Scenario {
    /// The test capture, trained for seconds.
    fn small() -> Scenario {
        Scenario {
            // Over 300 kB: more than one part once the page's part size is lowered to 64 KiB.
            archive: padded_capture_tar(),
            file_name: "capture.tar",
            views: 10,
            test_views: 2,
            iterations: 40,
            extra: r#"{"checkpoint_interval": 10, "eval_interval": 10, "initial_surfels": 100, "max_surfels": 1000}"#,
            gridmap: false,
            training: WAIT,
        }
    }

    /// A capture worth a screenshot, trained with the default settings: the folder
    /// `PHYGAP_WEB_CAPTURE` names, else the checkered creature.
    fn showcase() -> Scenario {
        let iterations = std::env::var("PHYGAP_WEB_ITERATIONS")
            .ok()
            .and_then(|v| v.parse().ok())
            .expect("PHYGAP_WEB_ITERATIONS is a number of steps");
        let synthesized = tempfile::tempdir().unwrap();
        let dir = match std::env::var_os("PHYGAP_WEB_CAPTURE") {
            Some(dir) => PathBuf::from(dir),
            None => {
                let options = phygap::pipeline::synth::SynthOptions {
                    shape: phygap::pipeline::synth::Shape::Creature,
                    texture: phygap::pipeline::synth::Texture::Checker,
                    ..Default::default()
                };
                phygap::pipeline::synth::synth(synthesized.path(), &options).unwrap();
                synthesized.path().to_owned()
            }
        };
        let capture = phygap::io::capture::load(&dir).unwrap();
        Scenario {
            archive: zip_of(&files_of(&dir)),
            file_name: "capture.zip",
            views: capture.views.len(),
            test_views: capture.test_views().count(),
            iterations,
            extra: "",
            gridmap: true,
            training: Duration::from_secs(3600),
        }
    }
}
const WAIT: Duration = Duration::from_secs(240);

/// The page's state of the job card of `id`, as shown.
fn card_state_script(id: &str) -> String {
    format!(
        "const s = document.querySelector('article.job[data-job-id=\"{id}\"] .job-state');\
         return s && ['succeeded', 'failed', 'cancelled'].includes(s.textContent) ? s.textContent : null;"
    )
}

/// Statistics of the WebGL canvas `css`'s pixels: size, distinct colours (on a sparse grid) and
/// the mean brightness of its central tenth.
const CANVAS_PIXELS: &str = "
  const c = document.querySelector(arguments[0]);
  const copy = document.createElement('canvas');
  copy.width = c.width; copy.height = c.height;
  const g = copy.getContext('2d');
  g.drawImage(c, 0, 0);
  const d = g.getImageData(0, 0, c.width, c.height).data;
  const colours = new Set();
  for (let i = 0; i < d.length; i += 4 * 5) colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
  let centre = 0, n = 0;
  for (let y = Math.floor(c.height * 0.45); y < c.height * 0.55; y++)
    for (let x = Math.floor(c.width * 0.45); x < c.width * 0.55; x++) {
      const i = 4 * (y * c.width + x); centre += d[i] + d[i + 1] + d[i + 2]; n++; }
  return { width: c.width, height: c.height, distinct: colours.size, centre: centre / (3 * n) };";

async fn assert_canvas_draws(session: &Session, css: &str) {
    // Let a few frames render.
    tokio::time::sleep(Duration::from_millis(500)).await;
    let stats = session.script(CANVAS_PIXELS, json!([css])).await;
    println!("{css}: {stats}");
    assert!(stats["width"].as_u64().unwrap() > 100, "{stats}");
    assert!(
        stats["distinct"].as_u64().unwrap() > 200,
        "the canvas shows a shaded object over an environment, not a flat fill: {stats}"
    );
    assert!(
        stats["centre"].as_f64().unwrap() > 5.0,
        "the centre is lit: {stats}"
    );
}

async fn screenshot(session: &Session, dir: &Option<PathBuf>, name: &str) {
    if let Some(dir) = dir {
        std::fs::create_dir_all(dir).unwrap();
        session.screenshot(&dir.join(name)).await;
    }
}

/// Console entries of level SEVERE (errors, uncaught exceptions, failed loads), except the two
/// answers this test provokes on purpose, which Chromium logs as failed loads: the 401 that makes
/// the page ask for the token, and the 422 of the broken capture.
async fn console_errors(session: &Session) -> Vec<String> {
    let provoked = |message: &str| {
        (message.contains("/v1/jobs?limit=50 ") && message.contains("status of 401"))
            || (message.contains("/v1/captures ") && message.contains("status of 422"))
    };
    session
        .console()
        .await
        .into_iter()
        .filter(|(level, message)| level == "SEVERE" && !provoked(message))
        .map(|(_, message)| message)
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_page_uploads_trains_views_and_relights_in_a_browser() {
    let Some(browser) = Browser::find() else {
        let message = "no chromium/chromedriver (apt-get install chromium chromium-driver)";
        assert_ne!(std::env::var("CI").as_deref(), Ok("true"), "{message}");
        println!("skipping the browser test: {message}");
        return;
    };
    let screenshots = std::env::var_os("PHYGAP_WEB_SCREENSHOTS").map(PathBuf::from);
    let (dir, t) = TestServer::start_fresh_with(|c| c.token = Some(TOKEN.into())).await;
    let base = t.base.clone();
    let scenario = if std::env::var_os("PHYGAP_WEB_ITERATIONS").is_some() {
        Scenario::showcase()
    } else {
        Scenario::small()
    };
    let good = dir.path().join(scenario.file_name);
    std::fs::write(&good, &scenario.archive).unwrap();
    // transforms.json without its images: rejected with each missing file named.
    let broken = dir.path().join("broken.zip");
    let transforms = {
        let capture = tempfile::tempdir().unwrap();
        write_capture(capture.path());
        std::fs::read(capture.path().join("transforms.json")).unwrap()
    };
    std::fs::write(&broken, zip_of(&[("transforms.json".into(), transforms)])).unwrap();

    let session = Session::start(&browser, 1280, 900).await;
    session.goto(&format!("{base}/")).await;
    // The first API call is refused (401): the page asks for the token once.
    session
        .wait_for(
            "the token dialog",
            "return document.querySelector('#token-dialog').open",
            WAIT,
        )
        .await;
    session.type_into("#token-dialog input", TOKEN).await;
    session.click("#token-dialog button").await;
    session
        .wait_for(
            "the job list",
            "return document.querySelector('#job-list p')?.textContent",
            WAIT,
        )
        .await;

    session
        .type_into("#capture-file", broken.to_str().unwrap())
        .await;
    let problems = session
        .wait_for(
            "the validation report",
            "const p = [...document.querySelectorAll('#upload-report .problems li')]; return p.length ? p.map(li => li.textContent) : null",
            WAIT,
        )
        .await;
    let problems: Vec<&str> = problems
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap())
        .collect();
    assert!(
        problems.len() > 1,
        "every problem on its own line: {problems:?}"
    );
    assert!(
        problems[0].starts_with("frame 0") && problems[0].contains("missing file"),
        "{problems:?}"
    );

    // The good capture goes up in parts (resumable; the page's part size lowered to the
    // service's 64 KiB minimum).
    session
        .script(
            "localStorage.setItem('phygap.partBytes', String(64 * 1024))",
            json!([]),
        )
        .await;
    session
        .type_into("#capture-file", good.to_str().unwrap())
        .await;
    let accepted = session
        .wait_for(
            "the accepted capture",
            "return document.querySelector('#upload-report .accepted')?.textContent",
            WAIT,
        )
        .await;
    let views = format!("{} views", scenario.views);
    assert!(accepted.as_str().unwrap().contains(&views), "{accepted}");
    let progress = session
        .script(
            "return document.querySelector('#upload-progress').value",
            json!([]),
        )
        .await;
    assert_eq!(progress, json!(1), "the upload bar ends full");
    let upload_id = session
        .script(
            "return document.querySelector('#upload-report').dataset.uploadId || null",
            json!([]),
        )
        .await;
    let upload_id = upload_id.as_str().expect("the capture went up in parts");
    let (status, upload) = status_and_json(
        t.get_with_token(&format!("/v1/uploads/{upload_id}"), TOKEN)
            .await,
    )
    .await;
    assert_eq!(status, 200, "{upload}");
    assert_eq!(upload["state"], "committed", "{upload}");
    assert!(upload["parts"].as_u64().unwrap() > 1, "{upload}");
    let capture_id = upload["capture_id"].as_str().unwrap();
    assert!(
        accepted.as_str().unwrap().contains(capture_id),
        "{accepted}"
    );

    let iterations = scenario.iterations.to_string();
    session
        .type_into("#job-form input[name=iterations]", &iterations)
        .await;
    if !scenario.extra.is_empty() {
        session
            .type_into("#job-form textarea[name=extra]", scenario.extra)
            .await;
    }
    if !scenario.gridmap {
        session.click("#job-form input[name=gridmap]").await;
    }
    session.click("#job-form button[type=submit]").await;
    let message = session
        .wait_for("the queued job", "const m = document.querySelector('#job-message').textContent; return m.startsWith('Job ') ? m : null", WAIT)
        .await;
    let job_id = message
        .as_str()
        .unwrap()
        .split(' ')
        .nth(1)
        .unwrap()
        .to_string();
    let state = session
        .wait_for(
            "the job's end",
            &card_state_script(&job_id),
            scenario.training,
        )
        .await;
    assert_eq!(state, "succeeded");
    let stats = session
        .text(&format!("article.job[data-job-id=\"{job_id}\"] .job-stats"))
        .await;
    let done = format!("iteration {iterations} / {iterations}");
    assert!(
        stats.contains(&done) && stats.contains("test PSNR"),
        "{stats}"
    );
    // The training process's peak memory (Linux reports it), as the job shows it.
    assert!(
        !cfg!(target_os = "linux") || stats.contains(" peak memory"),
        "{stats}"
    );
    let (_, job) = {
        let response = t.get_with_token(&format!("/v1/jobs/{job_id}"), TOKEN).await;
        status_and_json(response).await
    };
    assert_eq!(
        job["config"]["gridmap"], scenario.gridmap,
        "the form's settings reached the job: {job}"
    );
    screenshot(&session, &screenshots, "web-jobs.png").await;

    // A long job, cancelled from its card while it runs.
    session
        .script(
            "document.querySelector('#job-form input[name=iterations]').value = '100000'",
            json!([]),
        )
        .await;
    session.click("#job-form button[type=submit]").await;
    let long_id = session
        .wait_for(
            "the long job",
            &format!(
                "const m = document.querySelector('#job-message').textContent;\
                 return m.startsWith('Job ') && !m.includes('{job_id}') ? m.split(' ')[1] : null"
            ),
            WAIT,
        )
        .await;
    let long_id = long_id.as_str().unwrap();
    let card = format!("article.job[data-job-id=\"{long_id}\"]");
    session
        .wait_for(
            "the long job running",
            &format!(
                "return document.querySelector('{card} .job-state')?.textContent === 'running'"
            ),
            WAIT,
        )
        .await;
    session.click(&format!("{card} .cancel")).await;
    let state = session
        .wait_for("the cancel", &card_state_script(long_id), WAIT)
        .await;
    assert_eq!(state, "cancelled");

    // The result viewer.
    session.goto(&format!("{base}/#/jobs/{job_id}")).await;
    session
        .wait_for(
            "the viewer",
            "return document.querySelector('#viewer-canvas')?.dataset.ready",
            WAIT,
        )
        .await;
    assert_canvas_draws(&session, "#viewer-canvas").await;
    // Per test view: (S0, DoLP, AoLP) × (captured, rendered), every one decoded.
    let expected = 6 * scenario.test_views;
    session
        .wait_for(
            "the captured views and renders",
            &format!(
                "const imgs = [...document.querySelectorAll('#comparisons img')];\
                 return imgs.length === {expected} && imgs.every(i => i.complete && i.naturalWidth > 0)"
            ),
            WAIT,
        )
        .await;
    let facts = session.text(".facts").await;
    assert!(
        facts.contains("roughness") && facts.contains("IoR") && facts.contains("Polarizer angles"),
        "{facts}"
    );
    screenshot(&session, &screenshots, "web-viewer.png").await;
    // The exported glTF (model.glb) in the same view, loaded by three.js's GLTFLoader.
    session.click("#view-toggle button[data-view=gltf]").await;
    session
        .wait_for(
            "the glTF view",
            "return document.querySelector('#viewer-canvas').dataset.shown === 'gltf'",
            WAIT,
        )
        .await;
    assert_canvas_draws(&session, "#viewer-canvas").await;
    let pressed = session
        .script(
            "return document.querySelector('#view-toggle button[data-view=gltf]').getAttribute('aria-pressed')",
            json!([]),
        )
        .await;
    assert_eq!(pressed, "true");
    // GLTFLoader read the export's mesh (as many vertices as model.glb's positions: the mesh
    // simplified from the material mesh, so no more vertices than it has) and its one IoR
    // (KHR_materials_ior), which the facts now show.
    let shown = session
        .script(
            "return { vertices: document.querySelector('#viewer-canvas').dataset.gltfVertices,\
                      mesh: document.querySelector('#material-facts dd').textContent,\
                      ior: document.querySelector('#material-facts .gltf-ior').textContent }",
            json!([]),
        )
        .await;
    let glb = t
        .get_with_token(&format!("/v1/jobs/{job_id}/artifacts/model.glb"), TOKEN)
        .await
        .bytes()
        .await
        .unwrap();
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let document: Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let position = &document["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
    let glb_vertices = document["accessors"][position.as_u64().unwrap() as usize]["count"]
        .as_u64()
        .unwrap();
    assert_eq!(shown["vertices"], glb_vertices.to_string(), "{shown}");
    let mesh_vertices: u64 = shown["mesh"].as_str().unwrap().parse().unwrap();
    assert!(
        (1..=mesh_vertices).contains(&glb_vertices),
        "model.glb has {glb_vertices} vertices, the material mesh {mesh_vertices}"
    );
    let ior = document["materials"][0]["extensions"]["KHR_materials_ior"]["ior"]
        .as_f64()
        .unwrap();
    assert_eq!(shown["ior"], format!("{ior:.3}"), "{shown}");
    screenshot(&session, &screenshots, "web-gltf.png").await;

    // Relighting from the page.
    session
        .goto(&format!("{base}/#/jobs/{job_id}/relight"))
        .await;
    session
        .wait_for(
            "the relight preview",
            "return document.querySelector('#relight-canvas')?.dataset.ready",
            WAIT,
        )
        .await;
    session.click("#relight-form button[type=submit]").await;
    session
        .wait_for(
            "the relit renders",
            "const imgs = [...document.querySelectorAll('#relit-renders img')];\
             return imgs.length > 0 && imgs.every(i => i.complete && i.naturalWidth > 0)",
            WAIT,
        )
        .await;
    assert_canvas_draws(&session, "#relight-canvas").await;
    screenshot(&session, &screenshots, "web-relight.png").await;

    // A phone's width: one column, nothing wider than the screen.
    session.set_window_size(390, 844).await;
    session.goto(&format!("{base}/#/jobs/{job_id}")).await;
    session
        .wait_for(
            "the viewer on a phone",
            "return document.querySelector('#viewer-canvas')?.dataset.ready",
            WAIT,
        )
        .await;
    let widths: Value = session
        .script(
            "return [document.documentElement.scrollWidth, window.innerWidth]",
            json!([]),
        )
        .await;
    assert!(
        widths[0].as_u64() <= widths[1].as_u64(),
        "no horizontal scrolling: {widths}"
    );
    assert_canvas_draws(&session, "#viewer-canvas").await;
    screenshot(&session, &screenshots, "web-phone.png").await;

    let errors = console_errors(&session).await;
    assert!(errors.is_empty(), "console errors: {errors:#?}");
    drop(session);
    t.server.shutdown().await;
}
