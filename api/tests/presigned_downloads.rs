//! Presigned downloads (issue 30): with `--presigned-downloads-seconds` and an S3 bucket, an
//! artifact's GET answers 307 to the object's presigned URL, which the bucket serves (whole or a
//! range) with the artifact's content type (stored with the object) and file name; a client that follows redirects gets the
//! bytes in one call. Runs on moto's S3 server on loopback (skipped with a notice without it,
//! a failure under `CI=true`).

mod common;

use std::time::Duration;

use common::s3::TempS3;
use common::*;
use reqwest::header;

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn artifact_downloads_redirect_to_presigned_bucket_urls() {
    let Some(bucket) = TempS3::start() else {
        return;
    };
    let (_dir, t) = TestServer::start_fresh_with(|c| {
        c.artifact_url = Some(bucket.url.clone());
        c.artifact_options = bucket.options();
        c.presigned_downloads = Some(Duration::from_secs(90));
    })
    .await;
    let job = t.start_training(6, 0).await;
    t.wait_succeeded(&job).await;
    let listed = t.artifacts(&job).await;
    let metrics = listed
        .iter()
        .find(|a| a["name"] == "metrics.json")
        .expect("metrics.json listed");
    let size = metrics["size"].as_u64().unwrap() as usize;

    let path = format!("/v1/jobs/{job}/artifacts/metrics.json");
    let plain = reqwest::Client::builder()
        .redirect(reqwest::redirect::Policy::none())
        .build()
        .unwrap();
    let redirect = plain.get(t.url(&path)).send().await.unwrap();
    assert_eq!(redirect.status(), 307);
    assert_eq!(redirect.headers()[header::CACHE_CONTROL], "no-store");
    let location = redirect.headers()[header::LOCATION]
        .to_str()
        .unwrap()
        .to_owned();
    let endpoint = bucket
        .options()
        .into_iter()
        .find(|(k, _)| k == "aws_endpoint");
    let endpoint = endpoint.map(|(_, v)| v).unwrap();
    assert!(location.starts_with(&endpoint), "{location}");
    assert!(location.contains("X-Amz-Expires=90"), "{location}");
    assert!(location.contains("X-Amz-Signature="), "{location}");
    // The answer's file name is signed into the URL (S3 honours it; moto ignores it).
    assert!(
        location
            .contains("response-content-disposition=attachment%3B%20filename%3D%22metrics.json%22"),
        "{location}"
    );

    // The bucket serves the object as the API would: content type, file name, ranges.
    let whole = plain.get(&location).send().await.unwrap();
    assert_eq!(whole.status(), 200);
    assert_eq!(whole.headers()[header::CONTENT_TYPE], "application/json");
    let bytes = whole.bytes().await.unwrap();
    assert_eq!(bytes.len(), size);
    let parsed: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
    assert!(parsed.is_object(), "{parsed}");
    let part = plain
        .get(&location)
        .header(header::RANGE, "bytes=2-9")
        .send()
        .await
        .unwrap();
    assert_eq!(part.status(), 206);
    assert_eq!(part.bytes().await.unwrap(), bytes[2..10]);

    // A client that follows redirects takes its Range header along.
    let followed = t.get_range(&path, "bytes=0-3").await;
    assert_eq!(followed.status(), 206);
    assert_eq!(followed.bytes().await.unwrap(), bytes[..4]);
    // A missing artifact is still the API's 404, not a URL.
    let missing = plain
        .get(t.url(&format!("/v1/jobs/{job}/artifacts/none.bin")))
        .send()
        .await
        .unwrap();
    assert_eq!(missing.status(), 404);
    t.server.shutdown().await;
}
