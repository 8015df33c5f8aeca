//! The OpenAPI document against the code: the committed `api/openapi.yaml` is the document the
//! code generates, `phygap-api openapi` writes it, and real answers of a live service, for every
//! operation, validate against the schema the document declares for their route and status.

mod common;

use std::collections::{BTreeMap, BTreeSet};

use base64::Engine as _;
use common::*;
use phygap_api::accounts::auth::AccountToken;
use phygap_api::http::openapi::REGENERATE;
use reqwest::Method;
use serde_json::{json, Value};
use sha2::Digest as _;

const ADMIN: &str = "admin-token-for-the-openapi-test";
const ACCOUNT: &str = "account-token-for-the-openapi-test";

/// The first place where two JSON values differ, as a JSON pointer (`None`: equal).
fn first_difference(a: &Value, b: &Value, at: &str) -> Option<String> {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            let keys: BTreeSet<&String> = x.keys().chain(y.keys()).collect();
            keys.into_iter()
                .find_map(|key| match (x.get(key), y.get(key)) {
                    (Some(u), Some(v)) => first_difference(u, v, &format!("{at}/{key}")),
                    _ => Some(format!("{at}/{key}")),
                })
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => x
            .iter()
            .zip(y)
            .enumerate()
            .find_map(|(i, (u, v))| first_difference(u, v, &format!("{at}/{i}"))),
        _ if a == b => None,
        _ => Some(at.to_string()),
    }
}

#[test]
fn committed_openapi_yaml_is_the_generated_document() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/openapi.yaml");
    let text = std::fs::read_to_string(path).unwrap();
    let committed: Value = serde_yaml::from_str(&text).unwrap();
    let generated = phygap_api::http::openapi::spec_json().unwrap();
    if let Some(at) = first_difference(&committed, &generated, "") {
        panic!(
            "api/openapi.yaml is not the document the code generates (first difference at \
             `{at}`: committed {}, generated {}); regenerate it from the workspace root with\n\n    \
             {REGENERATE}\n",
            pointer_or_absent(&committed, &at),
            pointer_or_absent(&generated, &at),
        );
    }
    assert_eq!(generated["openapi"], "3.1.0");
}

fn pointer_or_absent(value: &Value, pointer: &str) -> String {
    value
        .pointer(pointer)
        .map_or("nothing".to_string(), Value::to_string)
}

#[test]
fn openapi_subcommand_writes_the_generated_document() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("openapi.yaml");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_phygap-api"))
        .args(["openapi", "--out"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    let written = std::fs::read_to_string(&out).unwrap();
    assert_eq!(written, phygap_api::http::openapi::spec_yaml().unwrap());
    assert!(written.starts_with(&format!("# Generated from the code by `{REGENERATE}`")));
    let printed = std::process::Command::new(env!("CARGO_BIN_EXE_phygap-api"))
        .arg("openapi")
        .output()
        .unwrap();
    assert!(printed.status.success());
    assert_eq!(String::from_utf8(printed.stdout).unwrap(), written);
}

/// Adds `additionalProperties: false` to every object schema that lists its properties and
/// says nothing of others, so an answer with a field the document does not declare fails too.
fn close_objects(value: &mut Value) {
    match value {
        Value::Object(map) => {
            if map.get("type") == Some(&json!("object"))
                && map.get("properties").is_some_and(Value::is_object)
                && !map.contains_key("additionalProperties")
            {
                map.insert("additionalProperties".into(), json!(false));
            }
            map.values_mut().for_each(close_objects);
        }
        Value::Array(items) => items.iter_mut().for_each(close_objects),
        _ => {}
    }
}

/// An answer as the checker saw it.
struct Answer {
    status: u16,
    body: Vec<u8>,
    /// The body parsed, when it is JSON (else `null`).
    json: Value,
}

impl Answer {
    /// The status and the error code of an error answer (`""` when the body has none).
    fn error(&self) -> (u16, &str) {
        let code = self.json["error"]["code"].as_str().unwrap_or("");
        (self.status, code)
    }
}

/// The served document, and the checks of answers against it.
struct Spec {
    doc: Value,
    /// (METHOD, path template) → statuses seen.
    seen: BTreeMap<(String, String), BTreeSet<u16>>,
}

impl Spec {
    fn new(served: Value) -> Spec {
        let mut doc = served;
        close_objects(&mut doc);
        Spec {
            doc,
            seen: BTreeMap::new(),
        }
    }

    fn operation(&self, method: &Method, template: &str) -> &Value {
        let operation = &self.doc["paths"][template][method.as_str().to_ascii_lowercase()];
        assert!(
            operation.is_object(),
            "the document has no {method} {template}"
        );
        operation
    }

    /// Validates `instance` against `schema`, whose `$ref`s point into the document's
    /// components (JSON Schema 2020-12, as OpenAPI 3.1 uses).
    fn validate(&self, schema: &Value, instance: &Value, what: &str) {
        let mut root = match schema {
            Value::Object(map) => map.clone(),
            other => [("allOf".to_string(), json!([other]))]
                .into_iter()
                .collect(),
        };
        root.insert("components".into(), self.doc["components"].clone());
        let root = Value::Object(root);
        let validator = jsonschema::draft202012::new(&root)
            .unwrap_or_else(|e| panic!("{what}: the declared schema does not compile: {e}"));
        let errors: Vec<String> = validator
            .iter_errors(instance)
            .map(|e| format!("{e} (at `{}`)", e.instance_path()))
            .collect();
        assert!(
            errors.is_empty(),
            "{what} does not match the schema the document declares:\n  {}\nbody: {instance:#}\nschema: {schema:#}",
            errors.join("\n  ")
        );
    }

    /// Validates a JSON request body against the operation's declared request body.
    fn check_request(&self, method: Method, template: &str, body: &Value) {
        let schema = &self.operation(&method, template)["requestBody"]["content"]
            ["application/json"]["schema"];
        assert!(schema.is_object(), "{method} {template} takes no JSON body");
        self.validate(
            schema,
            body,
            &format!("the request body of {method} {template}"),
        );
    }

    /// Checks an answer of `method template`: the document declares its status, the media type
    /// (or no body, when it declares none), and its JSON body validates against the declared
    /// schema.
    /// Sends `method path` (a path of the operation `template`) as `client` and checks the answer.
    async fn request(
        &mut self,
        client: &ApiClient,
        method: Method,
        template: &str,
        path: &str,
    ) -> Answer {
        let response = client.send(method.clone(), path).await;
        self.check(method, template, response).await
    }

    async fn check(
        &mut self,
        method: Method,
        template: &str,
        response: reqwest::Response,
    ) -> Answer {
        let status = response.status().as_u16();
        let media_type = response
            .headers()
            .get(reqwest::header::CONTENT_TYPE)
            .map(|v| {
                v.to_str()
                    .unwrap()
                    .split(';')
                    .next()
                    .unwrap()
                    .trim()
                    .to_string()
            });
        let body = response.bytes().await.unwrap().to_vec();
        let what = format!("{method} {template} → {status}");
        let declared = &self.operation(&method, template)["responses"][status.to_string()];
        assert!(
            declared.is_object(),
            "{what}: the document declares no {status} for it; body: {}",
            String::from_utf8_lossy(&body)
        );
        let json = match declared.get("content").and_then(Value::as_object) {
            None => {
                assert!(
                    body.is_empty(),
                    "{what}: a body the document does not declare"
                );
                Value::Null
            }
            Some(content) => {
                let media_type = media_type.unwrap_or_else(|| panic!("{what}: no content type"));
                // A file answered with its own type (`*/*`) is bytes whatever that type is.
                let declared_type = [media_type.as_str(), "*/*"]
                    .into_iter()
                    .find(|t| content.contains_key(*t))
                    .unwrap_or_else(|| {
                        panic!(
                            "{what}: answered {media_type}, the document declares {:?}",
                            content.keys().collect::<Vec<_>>()
                        )
                    });
                let entry = &content[declared_type];
                if declared_type == "application/json" {
                    let json: Value = serde_json::from_slice(&body)
                        .unwrap_or_else(|e| panic!("{what}: not JSON: {e}"));
                    self.validate(&entry["schema"], &json, &what);
                    json
                } else {
                    assert!(!body.is_empty(), "{what}: an empty {media_type} body");
                    Value::Null
                }
            }
        };
        self.seen
            .entry((method.to_string(), template.to_string()))
            .or_default()
            .insert(status);
        Answer { status, body, json }
    }

    /// The component schema `name` (closed), as a `$ref` to validate against.
    fn component(&self, name: &str) -> Value {
        assert!(
            self.doc["components"]["schemas"][name].is_object(),
            "no component {name}"
        );
        json!({ "$ref": format!("#/components/schemas/{name}") })
    }
}

/// Sends `method path` with `client` and returns the answer.
/// The `data` of each event of a server-sent event stream, with its event name.
fn sse_events(text: &str) -> Vec<(String, Value)> {
    text.split("\n\n")
        .filter_map(|block| {
            let mut event = None;
            let mut data = None;
            for line in block.lines() {
                if let Some(name) = line.strip_prefix("event:") {
                    event = Some(name.trim().to_string());
                } else if let Some(text) = line.strip_prefix("data:") {
                    data = Some(serde_json::from_str(text.trim()).unwrap());
                }
            }
            Some((event?, data?))
        })
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn live_answers_match_the_declared_schemas() {
    let (dir, t) = TestServer::start_fresh_with(|config| {
        config.token = Some(ADMIN.into());
        config.account_tokens = vec![AccountToken::new("acme", ACCOUNT)];
        config.max_upload_bytes = 4 << 20;
    })
    .await;
    let anonymous = &t.api;
    let admin = ApiClient::with_token(t.base.clone(), ADMIN);
    let account = ApiClient::with_token(t.base.clone(), ACCOUNT);

    let served = admin.get_json("/v1/openapi.json").await;
    assert_eq!(served.0, 200);
    assert_eq!(served.1, phygap_api::http::openapi::spec_json().unwrap());
    let mut spec = Spec::new(served.1);
    let response = admin.send(Method::GET, "/v1/openapi.json").await;
    spec.check(Method::GET, "/v1/openapi.json", response).await;

    // Service routes, and the token checks every protected route shares.
    let answer = spec
        .request(anonymous, Method::GET, "/healthz", "/healthz")
        .await;
    assert_eq!(
        (answer.status, answer.json),
        (200, json!({ "status": "ok" }))
    );
    let answer = spec
        .request(anonymous, Method::GET, "/metrics", "/metrics")
        .await;
    assert_eq!(answer.error(), (401, "unauthorized"));
    let answer = spec
        .request(&account, Method::GET, "/metrics", "/metrics")
        .await;
    assert_eq!(answer.error(), (403, "forbidden"));
    let answer = spec
        .request(&admin, Method::GET, "/metrics", "/metrics")
        .await;
    assert_eq!(answer.status, 200);
    assert!(String::from_utf8(answer.body).unwrap().contains("phygap_"));
    let answer = spec
        .request(anonymous, Method::GET, "/v1/jobs", "/v1/jobs")
        .await;
    assert_eq!(answer.status, 401);

    // Captures: one accepted, bad ones refused.
    let upload = |client: &ApiClient, body: Vec<u8>| {
        client
            .client
            .post(client.url("/v1/captures"))
            .header("content-type", "application/zip")
            .body(body)
            .send()
    };
    let answer = spec
        .check(
            Method::POST,
            "/v1/captures",
            upload(&admin, capture_zip()).await.unwrap(),
        )
        .await;
    assert_eq!((answer.status, &answer.json["views"]), (201, &json!(10)));
    let capture_id = answer.json["id"].as_str().unwrap().to_string();
    for (body, status, code) in [
        (Vec::new(), 400, "empty_upload"),
        (b"not an archive".to_vec(), 415, "unsupported_archive"),
        (vec![0u8; 5 << 20], 413, "payload_too_large"),
        (
            zip_of(&[("images/a.png".to_string(), b"x".to_vec())]),
            422,
            "invalid_capture",
        ),
    ] {
        let answer = spec
            .check(
                Method::POST,
                "/v1/captures",
                upload(&admin, body).await.unwrap(),
            )
            .await;
        assert_eq!(answer.error(), (status, code));
    }
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/captures/{id}",
            &format!("/v1/captures/{capture_id}"),
        )
        .await;
    assert_eq!(
        (answer.status, &answer.json["id"]),
        (200, &json!(capture_id))
    );
    // Another account's capture is not found.
    let answer = spec
        .request(
            &account,
            Method::GET,
            "/v1/captures/{id}",
            &format!("/v1/captures/{capture_id}"),
        )
        .await;
    assert_eq!(answer.status, 404);

    // Jobs: a short training job, and a long one queued behind it (one worker). The short one
    // is submitted with the longest Idempotency-Key the document allows, twice.
    let longest_key = spec.operation(&Method::POST, "/v1/jobs")["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "Idempotency-Key")
        .unwrap()["schema"]["maxLength"]
        .as_u64()
        .unwrap() as usize;
    let key = "k".repeat(longest_key);
    let request = json!({ "capture_id": capture_id, "config": train_config(10, 5) });
    spec.check_request(Method::POST, "/v1/jobs", &request);
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs",
            admin.post_job(&request, Some(&key)).await,
        )
        .await;
    assert_eq!(
        (answer.status, &answer.json["state"]),
        (201, &json!("queued"))
    );
    assert_eq!(answer.json["config"]["iterations"], 10);
    let trained = answer.json["id"].as_str().unwrap().to_string();
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs",
            admin.post_job(&request, Some(&key)).await,
        )
        .await;
    assert_eq!((answer.status, &answer.json["id"]), (200, &json!(trained)));
    let long = json!({ "capture_id": capture_id, "config": train_config(100_000, 100_000) });
    spec.check_request(Method::POST, "/v1/jobs", &long);
    let answer = spec
        .check(Method::POST, "/v1/jobs", admin.post_job(&long, None).await)
        .await;
    assert_eq!(answer.status, 201);
    let queued = answer.json["id"].as_str().unwrap().to_string();
    for (body, status, code) in [
        (json!({ "capture_id": "cap_none" }), 422, "unknown_capture"),
        (
            json!({ "capture_id": capture_id, "colour": 1 }),
            422,
            "invalid_request",
        ),
        (
            json!({ "capture_id": capture_id, "config": { "iterations": 0 } }),
            422,
            "invalid_config",
        ),
    ] {
        let answer = spec
            .check(Method::POST, "/v1/jobs", admin.post_job(&body, None).await)
            .await;
        assert_eq!(answer.error(), (status, code));
    }
    let too_long = "k".repeat(longest_key + 1);
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs",
            admin.post_job(&request, Some(&too_long)).await,
        )
        .await;
    assert_eq!(answer.error(), (400, "invalid_idempotency_key"));
    let not_json = admin
        .client
        .post(admin.url("/v1/jobs"))
        .body("{not json")
        .send()
        .await
        .unwrap();
    let answer = spec.check(Method::POST, "/v1/jobs", not_json).await;
    assert_eq!(answer.error(), (400, "invalid_json"));

    // The queued job holds the capture, and has no model yet.
    let answer = spec
        .check(
            Method::DELETE,
            "/v1/captures/{id}",
            admin.delete_capture(&capture_id).await,
        )
        .await;
    assert_eq!(answer.error(), (409, "capture_in_use"));
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}/material-mesh",
            &format!("/v1/jobs/{queued}/material-mesh"),
        )
        .await;
    assert_eq!(answer.error(), (409, "model_not_ready"));
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}/ground-truth/{kind}/{view}",
            &format!("/v1/jobs/{queued}/ground-truth/s0/000.png"),
        )
        .await;
    assert_eq!(answer.error(), (409, "model_not_ready"));
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs/{id}/relight",
            admin.relight(&queued, b"#?RADIANCE\n".to_vec(), "0").await,
        )
        .await;
    assert_eq!(answer.error(), (409, "model_not_ready"));
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs/{id}/cancel",
            admin.cancel(&queued).await,
        )
        .await;
    assert_eq!(answer.status, 200);
    assert!(
        answer.json["state"] == "cancelled" || answer.json["cancel_requested"] == true,
        "{}",
        answer.json
    );
    // Its event stream ends with the job as it ended.
    admin.wait_state(&queued, "cancelled", LONG).await;
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}/events",
            &format!("/v1/jobs/{queued}/events"),
        )
        .await;
    let events = sse_events(&String::from_utf8(answer.body).unwrap());
    assert_eq!(events.len(), 1, "{events:?}");
    assert_eq!(
        (events[0].0.as_str(), &events[0].1["state"]),
        ("end", &json!("cancelled"))
    );
    let job_schema = spec.component("Job");
    spec.validate(
        &job_schema,
        &events[0].1,
        "an event of /v1/jobs/{id}/events",
    );
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs/{id}/cancel",
            admin.cancel(&queued).await,
        )
        .await;
    assert_eq!(answer.error(), (409, "job_finished"));

    // Restarts: a bad setting, then the cancelled job back in the queue, then a queued one.
    let restart = "/v1/jobs/{id}/restart";
    let restart_path = format!("/v1/jobs/{queued}/restart");
    let post = |body: Value| {
        admin
            .client
            .post(admin.url(&restart_path))
            .json(&body)
            .send()
    };
    let answer = spec
        .check(
            Method::POST,
            restart,
            post(json!({"config": {"iterations": 0}})).await.unwrap(),
        )
        .await;
    assert_eq!(answer.error(), (422, "invalid_config"));
    let answer = spec
        .check(
            Method::POST,
            restart,
            post(json!({"config": {"iterations": 30}})).await.unwrap(),
        )
        .await;
    assert_eq!(
        (answer.status, &answer.json["state"]),
        (200, &json!("queued"))
    );
    let answer = spec
        .check(Method::POST, restart, post(json!({})).await.unwrap())
        .await;
    assert_eq!(answer.error(), (409, "job_not_restartable"));

    // A resumable upload: created, a part refused and sent, incomplete, committed twice; one
    // abandoned.
    let archive = capture_zip();
    let create = |body: Value| {
        admin
            .client
            .post(admin.url("/v1/uploads"))
            .json(&body)
            .send()
    };
    let answer = spec
        .check(
            Method::POST,
            "/v1/uploads",
            create(json!({"size": 0})).await.unwrap(),
        )
        .await;
    assert_eq!(answer.error(), (422, "invalid_upload"));
    let answer = spec
        .check(
            Method::POST,
            "/v1/uploads",
            create(json!({"size": archive.len(), "part_size": 65536}))
                .await
                .unwrap(),
        )
        .await;
    assert_eq!(answer.status, 201);
    let upload_id = answer.json["id"].as_str().unwrap().to_owned();
    let parts: Vec<&[u8]> = archive.chunks(65536).collect();
    let put = |index: usize, bytes: &[u8], digest_of: &[u8]| {
        admin
            .client
            .put(admin.url(&format!("/v1/uploads/{upload_id}/parts/{index}")))
            .header(
                "content-digest",
                format!(
                    "sha-256=:{}:",
                    base64::engine::general_purpose::STANDARD
                        .encode(sha2::Sha256::digest(digest_of))
                ),
            )
            .body(bytes.to_vec())
            .send()
    };
    let part_route = "/v1/uploads/{id}/parts/{index}";
    let answer = spec
        .check(
            Method::PUT,
            part_route,
            put(0, parts[0], b"other").await.unwrap(),
        )
        .await;
    assert_eq!(answer.error(), (400, "digest_mismatch"));
    let commit_route = "/v1/uploads/{id}/commit";
    let commit_path = format!("/v1/uploads/{upload_id}/commit");
    if parts.len() > 1 {
        let answer = spec
            .request(&admin, Method::POST, commit_route, &commit_path)
            .await;
        assert_eq!(answer.error(), (409, "upload_incomplete"));
    }
    for (index, part) in parts.iter().enumerate() {
        let answer = spec
            .check(
                Method::PUT,
                part_route,
                put(index, part, part).await.unwrap(),
            )
            .await;
        assert_eq!(answer.status, 200);
    }
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/uploads/{id}",
            &format!("/v1/uploads/{upload_id}"),
        )
        .await;
    assert_eq!(
        answer.json["received"].as_array().unwrap().len(),
        parts.len()
    );
    let answer = spec
        .request(&admin, Method::POST, commit_route, &commit_path)
        .await;
    assert_eq!((answer.status, &answer.json["views"]), (201, &json!(10)));
    let answer = spec
        .request(&admin, Method::POST, commit_route, &commit_path)
        .await;
    assert_eq!(answer.status, 200);
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/uploads/{id}",
            "/v1/uploads/upl_none",
        )
        .await;
    assert_eq!(answer.error(), (404, "not_found"));
    let answer = spec
        .check(
            Method::POST,
            "/v1/uploads",
            create(json!({"size": 10})).await.unwrap(),
        )
        .await;
    let abandoned = answer.json["id"].as_str().unwrap().to_owned();
    let answer = spec
        .request(
            &admin,
            Method::DELETE,
            "/v1/uploads/{id}",
            &format!("/v1/uploads/{abandoned}"),
        )
        .await;
    assert_eq!(answer.status, 204);

    // What the deployment offers, to the admin and to an account.
    for client in [&admin, &account] {
        let answer = spec
            .request(client, Method::GET, "/v1/info", "/v1/info")
            .await;
        assert_eq!(answer.status, 200);
        assert!(answer.json["limits"]["max_views"].as_u64() > Some(0));
        assert!(answer.json["engines"]["backends"]["cpu"].is_string());
    }

    // The trained job, its history, list, artifacts and viewer routes.
    admin.wait_succeeded(&trained).await;
    let history = "/v1/jobs/{id}/progress";
    let answer = spec
        .request(
            &admin,
            Method::GET,
            history,
            &format!("/v1/jobs/{trained}/progress"),
        )
        .await;
    let events = answer.json["events"].as_array().unwrap().clone();
    let kinds: Vec<&str> = events
        .iter()
        .map(|e| e["event"]["type"].as_str().unwrap())
        .collect();
    assert_eq!(kinds.first(), Some(&"started"), "{kinds:?}");
    assert_eq!(kinds.last(), Some(&"finished"), "{kinds:?}");
    assert!(
        kinds.contains(&"step") && kinds.contains(&"evaluated"),
        "{kinds:?}"
    );
    assert_eq!(answer.json["next"].as_u64(), Some(events.len() as u64));
    let page = spec
        .request(
            &admin,
            Method::GET,
            history,
            &format!("/v1/jobs/{trained}/progress?from=2&limit=1"),
        )
        .await;
    assert_eq!(page.json["events"][0], events[2]);
    assert_eq!(page.json["next"], 3);
    let bad = spec
        .request(
            &admin,
            Method::GET,
            history,
            &format!("/v1/jobs/{trained}/progress?from=soon"),
        )
        .await;
    assert_eq!(bad.error(), (400, "invalid_query"));
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}",
            &format!("/v1/jobs/{trained}"),
        )
        .await;
    assert_eq!(
        (answer.status, &answer.json["state"]),
        (200, &json!("succeeded"))
    );
    // A 10-step run on 24×24 views: it scores 9.99 dB at the normalized exposure.
    assert!(
        answer.json["test_psnr"].as_f64().unwrap() > 8.0,
        "{}",
        answer.json
    );
    let answer = spec
        .request(&admin, Method::GET, "/v1/jobs", "/v1/jobs?limit=5")
        .await;
    let listed: Vec<&str> = answer.json["jobs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|job| job["id"].as_str().unwrap())
        .collect();
    assert_eq!(listed, [queued.as_str(), trained.as_str()]);
    let answer = spec
        .request(&admin, Method::GET, "/v1/jobs", "/v1/jobs?limit=many")
        .await;
    assert_eq!(answer.error(), (400, "invalid_query"));
    let answer = spec
        .request(
            &account,
            Method::GET,
            "/v1/jobs/{id}",
            &format!("/v1/jobs/{trained}"),
        )
        .await;
    assert_eq!(answer.status, 404);

    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}/artifacts",
            &format!("/v1/jobs/{trained}/artifacts"),
        )
        .await;
    let artifacts = answer.json["artifacts"].as_array().unwrap().clone();
    assert!(
        artifacts.iter().any(|a| a["name"] == "surfels.ply"),
        "{artifacts:?}"
    );
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}/artifacts",
            "/v1/jobs/job_none/artifacts",
        )
        .await;
    assert_eq!(answer.status, 404);
    let download = "/v1/jobs/{id}/artifacts/{name}";
    let metrics_path = format!("/v1/jobs/{trained}/artifacts/metrics.json");
    let answer = spec
        .request(&admin, Method::GET, download, &metrics_path)
        .await;
    assert_eq!(answer.status, 200);
    assert!(serde_json::from_slice::<Value>(&answer.body).is_ok());
    let answer = spec
        .check(
            Method::GET,
            download,
            admin.get_range(&metrics_path, "bytes=0-3").await,
        )
        .await;
    assert_eq!((answer.status, answer.body.len()), (206, 4));
    let answer = spec
        .check(
            Method::GET,
            download,
            admin.get_range(&metrics_path, "bytes=999999999-").await,
        )
        .await;
    assert_eq!(answer.status, 416);
    let missing = format!("/v1/jobs/{trained}/artifacts/nothing.bin");
    let answer = spec.request(&admin, Method::GET, download, &missing).await;
    assert_eq!(answer.status, 404);
    let etag = admin
        .send(Method::GET, &metrics_path)
        .await
        .headers()
        .get("etag")
        .unwrap()
        .to_str()
        .unwrap()
        .to_owned();
    let cached = admin
        .client
        .get(admin.url(&metrics_path))
        .header("if-none-match", etag)
        .send()
        .await
        .unwrap();
    let answer = spec.check(Method::GET, download, cached).await;
    assert_eq!((answer.status, answer.body.len()), (304, 0));

    // The HTTP layer's own errors, declared on every operation.
    let answer = spec
        .request(&admin, Method::GET, "/v1/jobs/{id}", "/v1/jobs/%FF")
        .await;
    assert_eq!(answer.error(), (400, "bad_request"));
    let long = format!("/v1/jobs/{}", "x".repeat(9000));
    let answer = spec
        .request(&admin, Method::GET, "/v1/jobs/{id}", &long)
        .await;
    assert_eq!(answer.error(), (414, "uri_too_long"));
    let padded = admin
        .client
        .get(admin.url("/v1/jobs"))
        .header("x-padding", "p".repeat(40_000))
        .send()
        .await
        .unwrap();
    let answer = spec.check(Method::GET, "/v1/jobs", padded).await;
    assert_eq!(answer.error(), (431, "headers_too_large"));
    let oversized = admin
        .client
        .post(admin.url("/v1/jobs"))
        .header("content-type", "application/json")
        .body(vec![b' '; 3 << 20])
        .send()
        .await
        .unwrap();
    let answer = spec.check(Method::POST, "/v1/jobs", oversized).await;
    assert_eq!(answer.error(), (413, "payload_too_large"));

    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}/material-mesh",
            &format!("/v1/jobs/{trained}/material-mesh"),
        )
        .await;
    assert_eq!((answer.status, &answer.body[..3]), (200, &b"ply"[..]));
    let ground_truth = "/v1/jobs/{id}/ground-truth/{kind}/{view}";
    let answer = spec
        .request(
            &admin,
            Method::GET,
            ground_truth,
            &format!("/v1/jobs/{trained}/ground-truth/dolp/000.png"),
        )
        .await;
    assert_eq!((answer.status, &answer.body[1..4]), (200, &b"PNG"[..]));
    // The kinds the document lists are the ones answered.
    let kinds = spec.operation(&Method::GET, ground_truth)["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "kind")
        .unwrap()["schema"]["enum"]
        .clone();
    assert_eq!(kinds, json!(["s0", "dolp", "aolp"]));
    let answer = spec
        .request(
            &admin,
            Method::GET,
            ground_truth,
            &format!("/v1/jobs/{trained}/ground-truth/normal/000.png"),
        )
        .await;
    assert_eq!(answer.status, 404);

    // Relighting the trained job: the form fields the handler knows are the documented ones.
    let form_ref = spec.operation(&Method::POST, "/v1/jobs/{id}/relight")["requestBody"]["content"]
        ["multipart/form-data"]["schema"]["$ref"]
        .as_str()
        .unwrap()
        .rsplit('/')
        .next()
        .unwrap()
        .to_string();
    let documented: BTreeSet<String> = spec.doc["components"]["schemas"][&form_ref]["properties"]
        .as_object()
        .unwrap()
        .keys()
        .cloned()
        .collect();
    let form = reqwest::multipart::Form::new().text("bogus", "1");
    let response = admin
        .client
        .post(admin.url(&format!("/v1/jobs/{trained}/relight")))
        .multipart(form)
        .send()
        .await
        .unwrap();
    let answer = spec
        .check(Method::POST, "/v1/jobs/{id}/relight", response)
        .await;
    assert_eq!(answer.error(), (400, "unknown_field"));
    let message = answer.json["error"]["message"].as_str().unwrap();
    let accepted: BTreeSet<String> = message
        .split_once("(expected ")
        .and_then(|(_, rest)| rest.strip_suffix(')'))
        .unwrap_or_else(|| panic!("{message}"))
        .split(", ")
        .map(str::to_string)
        .collect();
    assert_eq!(accepted, documented);
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs/{id}/relight",
            admin.relight(&trained, b"not an image".to_vec(), "0").await,
        )
        .await;
    assert_eq!(answer.error(), (415, "unsupported_envmap"));
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs/{id}/relight",
            admin
                .relight(&trained, b"#?RADIANCE\n".to_vec(), "ninety")
                .await,
        )
        .await;
    assert_eq!(answer.error(), (422, "invalid_rotate_deg"));
    let envmap_path = dir.path().join("sky.exr");
    phygap::formats::image_io::write_exr(
        &envmap_path,
        &phygap::formats::image_io::Image::filled(8, 4, 3, 2.0),
    )
    .unwrap();
    let envmap = std::fs::read(&envmap_path).unwrap();
    let answer = spec
        .check(
            Method::POST,
            "/v1/jobs/{id}/relight",
            admin.relight(&trained, envmap, "90").await,
        )
        .await;
    assert_eq!(
        (answer.status, &answer.json["kind"]),
        (201, &json!("relight"))
    );
    assert_eq!(answer.json["parent_job_id"], json!(trained));
    assert!(answer.json.get("config").is_none(), "{}", answer.json);
    let relit = answer.json["id"].as_str().unwrap().to_string();
    admin.wait_succeeded(&relit).await;
    let answer = spec
        .request(
            &admin,
            Method::GET,
            "/v1/jobs/{id}",
            &format!("/v1/jobs/{relit}"),
        )
        .await;
    assert_eq!(
        (answer.status, &answer.json["state"]),
        (200, &json!("succeeded"))
    );

    // Deletions: the cancelled job, then a capture no job uses.
    let job_path = format!("/v1/jobs/{queued}");
    let answer = spec
        .request(&admin, Method::DELETE, "/v1/jobs/{id}", &job_path)
        .await;
    assert_eq!(answer.status, 204);
    let answer = spec
        .request(&admin, Method::DELETE, "/v1/jobs/{id}", &job_path)
        .await;
    assert_eq!(answer.status, 404);
    let answer = spec
        .check(
            Method::POST,
            "/v1/captures",
            upload(&account, capture_zip()).await.unwrap(),
        )
        .await;
    assert_eq!(answer.status, 201);
    let spare = answer.json["id"].as_str().unwrap().to_string();
    let answer = spec
        .check(
            Method::DELETE,
            "/v1/captures/{id}",
            account.delete_capture(&spare).await,
        )
        .await;
    assert_eq!(answer.status, 204);
    let answer = spec
        .check(
            Method::DELETE,
            "/v1/captures/{id}",
            account.delete_capture(&spare).await,
        )
        .await;
    assert_eq!(answer.status, 404);

    // Every operation the document declares was answered and checked.
    let documented: BTreeSet<(String, String)> =
        phygap_api::http::openapi::spec_operations(&spec.doc)
            .into_iter()
            .collect();
    let checked: BTreeSet<(String, String)> = spec.seen.keys().cloned().collect();
    assert_eq!(checked, documented);
    for ((method, path), statuses) in &spec.seen {
        println!("{method} {path}: {statuses:?}");
    }
    t.server.shutdown().await;
}
