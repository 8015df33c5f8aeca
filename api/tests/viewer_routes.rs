//! The routes the web page's viewer needs: the mesh with the learned materials, and the captured
//! test views beside which the page shows the renders.

mod common;

use common::*;
use reqwest::Method;

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn a_job_not_trained_has_nothing_to_view() {
    // No workers: the job stays queued.
    let (_dir, t) = TestServer::start_fresh_with(|c| c.workers = 0).await;
    let id = t.start_training(30, 10).await;
    for path in [
        format!("/v1/jobs/{id}/material-mesh"),
        format!("/v1/jobs/{id}/ground-truth/s0/000.png"),
    ] {
        let (status, body) = t.get_json(&path).await;
        assert_eq!(
            (status, error_code(&body).0),
            (409, "model_not_ready"),
            "{path}: {body}"
        );
    }
    t.server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn material_mesh_and_captured_views_of_a_trained_job() {
    let (_dir, t) = TestServer::start_fresh().await;
    let id = t.start_training(30, 10).await;
    t.wait_succeeded(&id).await;

    let bytes = |path: String| {
        let t = &t;
        async move {
            let response = t.send(Method::GET, &path).await;
            let status = response.status().as_u16();
            let content_type = response
                .headers()
                .get("content-type")
                .map(|v| v.to_str().unwrap().to_string());
            (
                status,
                content_type,
                response.bytes().await.unwrap().to_vec(),
            )
        }
    };
    let (status, content_type, ply) = bytes(format!("/v1/jobs/{id}/material-mesh")).await;
    assert_eq!(
        (status, content_type.as_deref()),
        (200, Some("application/x-ply"))
    );
    let ply = phygap::formats::ply::parse_ply(&ply).unwrap();
    let (_, _, mesh) = bytes(format!("/v1/jobs/{id}/artifacts/mesh.ply")).await;
    let mesh = phygap::formats::ply::parse_ply(&mesh).unwrap();
    let vertex = ply.element("vertex").unwrap();
    assert_eq!(vertex.count, mesh.element("vertex").unwrap().count);
    assert_eq!(
        vertex.scalar("x"),
        mesh.element("vertex").unwrap().scalar("x")
    );
    assert_eq!(
        ply.element("face").unwrap().count,
        mesh.element("face").unwrap().count
    );
    for name in ["red", "green", "blue"] {
        let levels = vertex.scalar(name).unwrap();
        assert!(levels.iter().all(|&v| (0.0..=255.0).contains(&v)), "{name}");
    }
    // Roughness in (0, 1) and IoR in (1.3, 2.3): the surfels' activation ranges.
    assert!(vertex
        .scalar("roughness")
        .unwrap()
        .iter()
        .all(|&r| r > 0.0 && r < 1.0));
    assert!(vertex
        .scalar("ior")
        .unwrap()
        .iter()
        .all(|&r| r > 1.3 && r < 2.3));

    for kind in ["s0", "dolp", "aolp"] {
        let (status, content_type, png) =
            bytes(format!("/v1/jobs/{id}/ground-truth/{kind}/000.png")).await;
        assert_eq!(
            (status, content_type.as_deref()),
            (200, Some("image/png")),
            "{kind}"
        );
        let (_, _, render) = bytes(format!("/v1/jobs/{id}/artifacts/renders/{kind}/000.png")).await;
        // PNG width and height (IHDR) match the render's: the same view, side by side.
        assert_eq!(&png[..4], b"\x89PNG");
        assert_eq!(png[16..24], render[16..24], "{kind}");
    }
    for (path, status, code) in [
        (
            format!("/v1/jobs/{id}/ground-truth/normal/000.png"),
            404,
            "not_found",
        ),
        (
            format!("/v1/jobs/{id}/ground-truth/s0/099.png"),
            404,
            "not_found",
        ),
        (
            format!("/v1/jobs/{id}/ground-truth/s0/zero.png"),
            404,
            "not_found",
        ),
        (
            "/v1/jobs/job_none/material-mesh".to_string(),
            404,
            "not_found",
        ),
    ] {
        let (got, body) = t.get_json(&path).await;
        assert_eq!((got, error_code(&body).0), (status, code), "{path}: {body}");
    }
    t.server.shutdown().await;
}
