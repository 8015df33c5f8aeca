//! The web page is served by the service itself, from files embedded in the binary.

mod common;

use common::*;
use reqwest::Method;

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_page_is_served_from_the_binary() {
    let (_dir, t) = TestServer::start_fresh_with(|c| c.token = Some("secret".into())).await;
    // The page is open (it holds no data); the API behind it is not.
    let page = t.send(Method::GET, "/").await;
    assert_eq!(page.status(), 200);
    assert_eq!(page.headers()["content-type"], "text/html; charset=utf-8");
    let html = page.text().await.unwrap();
    assert!(
        html.contains("/assets/app.js") && html.contains("/assets/app.css"),
        "{html}"
    );
    for (path, content_type, min_size) in [
        ("/assets/app.js", "text/javascript; charset=utf-8", 100_000),
        ("/assets/app.css", "text/css; charset=utf-8", 1_000),
        ("/assets/envmaps/studio.hdr", "image/vnd.radiance", 10_000),
    ] {
        let response = t.send(Method::GET, path).await;
        assert_eq!(response.status(), 200, "{path}");
        assert_eq!(response.headers()["content-type"], content_type, "{path}");
        assert!(response.bytes().await.unwrap().len() >= min_size, "{path}");
    }
    let (status, body) = t.get_json("/assets/../Cargo.toml").await;
    assert_eq!((status, error_code(&body).0), (404, "not_found"), "{body}");
    let (status, body) = t.get_json("/assets/no-such.js").await;
    assert_eq!((status, error_code(&body).0), (404, "not_found"), "{body}");
    let (status, _) = t.get_json("/v1/jobs").await;
    assert_eq!(status, 401);
    // Every embedded file is one build.sh makes.
    let files = phygap_api::http::web_page::files();
    for expected in [
        "index.html",
        "assets/app.js",
        "assets/app.css",
        "assets/envmaps/sky.hdr",
    ] {
        assert!(files.contains(&expected), "{expected} in {files:?}");
    }
    t.server.shutdown().await;
}
