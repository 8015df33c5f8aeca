//! The deploy files use paths and flags that exist: their `serve` and `worker` command lines
//! parse with the binary's clap definition and appear in its `--help`, the environment variables
//! they set are ones the binary reads, the data dir matches the volume / state directory, health
//! checks and probes hit a real open route on the bound port, the Docker build names the real
//! package and binary, and the compose file and Kubernetes manifests reference only services,
//! secrets and keys they define.

use std::path::{Path, PathBuf};

use clap::Parser;
use phygap_api::cli::{Cli, Command};

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn read(relative: &str) -> String {
    std::fs::read_to_string(repo_root().join(relative))
        .unwrap_or_else(|e| panic!("{relative}: {e}"))
}

/// Dockerfile lines with `\` continuations joined.
fn dockerfile_instructions() -> Vec<String> {
    let text = read("deploy/Dockerfile");
    let mut out = Vec::new();
    let mut current = String::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('#') || (line.is_empty() && current.is_empty()) {
            continue;
        }
        if let Some(head) = line.strip_suffix('\\') {
            current.push_str(head);
            current.push(' ');
        } else {
            current.push_str(line);
            out.push(std::mem::take(&mut current));
        }
    }
    out
}

fn instruction<'a>(all: &'a [String], keyword: &str) -> Vec<&'a str> {
    all.iter()
        .filter_map(|i| i.strip_prefix(keyword).filter(|rest| rest.starts_with(' ')))
        .map(str::trim)
        .collect()
}

fn json_array(text: &str) -> Vec<String> {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not a JSON array: {text}: {e}"))
}

fn serve_args(argv: &[String]) -> phygap_api::cli::ServeArgs {
    match Cli::try_parse_from(argv)
        .unwrap_or_else(|e| panic!("{argv:?} does not parse: {e}"))
        .command
    {
        Command::Serve(args) | Command::Worker(args) => args,
        Command::Openapi(_) | Command::Stage(_) => {
            panic!("{argv:?} runs neither serve nor worker")
        }
    }
}

fn flags(argv: &[String]) -> Vec<&str> {
    argv.iter()
        .filter(|a| a.starts_with("--"))
        .map(String::as_str)
        .collect()
}

fn help(subcommand: &str) -> String {
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_phygap-api"))
        .args([subcommand, "--help"])
        .output()
        .unwrap();
    assert!(output.status.success());
    String::from_utf8(output.stdout).unwrap()
}

fn serve_help() -> String {
    help("serve")
}

/// The command line of a container (`phygap-api` and its arguments), checked: it parses, its
/// flags are in the subcommand's `--help`, and its data dir is the image's volume.
fn checked_command(args: &serde_yaml::Value, what: &str) -> (String, phygap_api::cli::ServeArgs) {
    let args: Vec<String> = args
        .as_sequence()
        .unwrap_or_else(|| panic!("{what}: no command"))
        .iter()
        .map(|a| a.as_str().unwrap().to_owned())
        .collect();
    let argv: Vec<String> = std::iter::once("phygap-api".to_owned())
        .chain(args.iter().cloned())
        .collect();
    let help = help(&args[0]);
    for flag in flags(&argv) {
        assert!(
            help.contains(flag),
            "{what}: {flag} is not in `phygap-api {} --help`",
            args[0]
        );
    }
    let parsed = serve_args(&argv);
    assert_eq!(parsed.data_dir, Path::new("/var/lib/phygap-api"), "{what}");
    (args[0].clone(), parsed)
}

/// Asserts that every `PHYGAP_*` variable in `names` is one the binary reads.
fn assert_known_variables<'a>(names: impl IntoIterator<Item = &'a str>, what: &str) {
    let help = serve_help();
    for name in names.into_iter().filter(|n| n.starts_with("PHYGAP_")) {
        assert!(
            help.contains(&format!("env: {name}")),
            "{what}: {name} is not read by the binary"
        );
    }
}

/// Every YAML document of a file.
fn yaml_documents(relative: &str) -> Vec<serde_yaml::Value> {
    use serde::Deserialize;
    serde_yaml::Deserializer::from_str(&read(relative))
        .map(|doc| {
            serde_yaml::Value::deserialize(doc).unwrap_or_else(|e| panic!("{relative}: {e}"))
        })
        .collect()
}

fn text(value: &serde_yaml::Value) -> &str {
    value
        .as_str()
        .unwrap_or_else(|| panic!("not a string: {value:?}"))
}

#[test]
fn dockerfile_command_line_volume_and_healthcheck_are_real() {
    let all = dockerfile_instructions();
    let help = serve_help();
    let entrypoint = json_array(instruction(&all, "ENTRYPOINT")[0]);
    let cmd = json_array(instruction(&all, "CMD")[0]);
    assert_eq!(entrypoint, ["/usr/local/bin/phygap-api"]);
    let argv: Vec<String> = entrypoint.iter().chain(&cmd).cloned().collect();
    for flag in flags(&argv) {
        assert!(
            help.contains(flag),
            "{flag} is not in `phygap-api serve --help`"
        );
    }
    let args = serve_args(&argv);
    let volume = json_array(instruction(&all, "VOLUME")[0]);
    assert_eq!(volume, [args.data_dir.to_string_lossy().into_owned()]);
    // The binary the runtime stage copies is the one the build stage produced and the entrypoint runs.
    let copy = instruction(&all, "COPY")
        .into_iter()
        .find(|c| c.starts_with("--from=build"))
        .expect("runtime stage copies from the build stage");
    assert!(copy.ends_with(&entrypoint[0]), "{copy}");
    let build = instruction(&all, "RUN")
        .into_iter()
        .find(|r| r.contains("cargo build"))
        .expect("a cargo build step");
    let manifest: toml_lite::Manifest =
        toml_lite::Manifest::read(&repo_root().join("api/Cargo.toml"));
    assert!(
        build.contains(&format!("-p {}", manifest.package_name)),
        "{build}"
    );
    assert!(
        build.contains(&format!("target/release/{}", manifest.bin_name)),
        "{build}"
    );
    assert!(build.contains("--release"));
    // Health check: the documented open route, on the port the server binds.
    let health = instruction(&all, "HEALTHCHECK")[0];
    let port = args.bind.port();
    assert!(
        health.contains(&format!("http://127.0.0.1:{port}/healthz")),
        "{health}"
    );
    assert!(instruction(&all, "EXPOSE").contains(&port.to_string().as_str()));
    let healthz = phygap_api::http::route_table(1)
        .into_iter()
        .find(|r| r.path == "/healthz")
        .expect("a /healthz route");
    assert!(!healthz.protected, "/healthz must stay open");
    // Runtime stage: slim, non-root, Vulkan drivers.
    assert!(instruction(&all, "FROM").iter().any(|f| f.contains("slim")));
    assert!(instruction(&all, "USER").iter().all(|u| *u != "root"));
    assert!(all.iter().any(|i| i.contains("mesa-vulkan-drivers")));
    // On NVIDIA hosts the container toolkit mounts the Vulkan driver only for `graphics`.
    let capabilities = instruction(&all, "ENV")
        .into_iter()
        .find_map(|e| e.strip_prefix("NVIDIA_DRIVER_CAPABILITIES="))
        .expect("NVIDIA_DRIVER_CAPABILITIES is set");
    assert!(capabilities
        .split(',')
        .any(|c| c == "graphics" || c == "all"));
    // The build context excludes what must not be sent (build outputs, data).
    let ignore = read(".dockerignore");
    for entry in ["target", "shared", ".git"] {
        assert!(
            ignore.lines().any(|l| l.trim() == entry),
            "{entry} not in .dockerignore"
        );
    }
}

#[test]
fn systemd_unit_command_line_and_state_directory_are_real() {
    let unit = read("deploy/phygap-api.service");
    let value = |key: &str| {
        unit.lines()
            .find_map(|l| l.strip_prefix(&format!("{key}=")))
            .unwrap_or_else(|| panic!("{key}= missing"))
            .trim()
            .to_string()
    };
    let argv: Vec<String> = value("ExecStart")
        .split_whitespace()
        .map(String::from)
        .collect();
    assert_eq!(argv[0], "/usr/local/bin/phygap-api");
    let help = serve_help();
    for flag in flags(&argv) {
        assert!(
            help.contains(flag),
            "{flag} is not in `phygap-api serve --help`"
        );
    }
    let args = serve_args(&argv);
    assert_eq!(
        args.data_dir,
        Path::new("/var/lib").join(value("StateDirectory"))
    );
    assert!(
        args.bind.ip().is_loopback(),
        "the unit serves on loopback (put a proxy in front)"
    );
    assert_eq!(value("KillSignal"), "SIGTERM");
    assert!(
        value("TimeoutStopSec").parse::<u32>().unwrap() >= 60,
        "time to checkpoint on stop"
    );
    // The token comes from the environment file as PHYGAP_TOKEN, which the CLI reads.
    assert!(help.contains("PHYGAP_TOKEN"));
}

/// Just enough TOML reading for the package and binary names.
mod toml_lite {
    use std::path::Path;

    pub struct Manifest {
        pub package_name: String,
        pub bin_name: String,
    }

    impl Manifest {
        pub fn read(path: &Path) -> Manifest {
            let text = std::fs::read_to_string(path).unwrap();
            let mut section = String::new();
            let (mut package_name, mut bin_name) = (None, None);
            for line in text.lines().map(str::trim) {
                if line.starts_with('[') {
                    section = line.to_string();
                } else if let Some(value) = line.strip_prefix("name = ") {
                    let value = value.trim_matches('"').to_string();
                    match section.as_str() {
                        "[package]" => package_name = Some(value),
                        "[[bin]]" => bin_name = Some(value),
                        _ => {}
                    }
                }
            }
            Manifest {
                package_name: package_name.expect("[package] name"),
                bin_name: bin_name.expect("[[bin]] name"),
            }
        }
    }
}

#[test]
fn compose_file_runs_two_apis_and_workers_on_postgres_and_a_bucket() {
    let compose = &yaml_documents("deploy/compose.yaml")[0];
    let services = compose["services"].as_mapping().expect("services");
    let mut apis = 0;
    let mut workers = 0;
    for (name, service) in services {
        let name = text(name);
        if let Some(depends) = service["depends_on"].as_mapping() {
            for dependency in depends.keys() {
                assert!(
                    services.contains_key(dependency),
                    "{name} depends on {dependency:?}"
                );
            }
        }
        if service["image"].as_str() != Some("phygap-api") {
            continue;
        }
        let (role, args) = checked_command(&service["command"], name);
        let environment = service["environment"].as_mapping().expect("environment");
        assert_known_variables(environment.keys().map(text), name);
        let database = text(&environment["PHYGAP_DATABASE_URL"]);
        let host = database
            .split('@')
            .nth(1)
            .and_then(|h| h.split(':').next())
            .unwrap();
        assert!(
            services.contains_key(host),
            "{name}: the database host {host} is a service"
        );
        let bucket = text(&environment["PHYGAP_ARTIFACT_URL"])
            .strip_prefix("s3://")
            .and_then(|rest| rest.split('/').next())
            .unwrap();
        let creates_bucket = services.values().any(|s| {
            s["entrypoint"].as_sequence().is_some_and(|e| {
                e.iter().any(|a| {
                    a.as_str().is_some_and(|a| {
                        a.contains(&format!("mb --ignore-existing store/{bucket}"))
                    })
                })
            })
        });
        assert!(
            creates_bucket,
            "{name}: nothing creates the bucket {bucket}"
        );
        match role.as_str() {
            "serve" => {
                assert_eq!(args.workers, 0, "{name}: the API replicas run no jobs");
                apis += 1;
            }
            "worker" => {
                assert!(args.workers >= 1, "{name}");
                workers += service["deploy"]["replicas"].as_u64().unwrap_or(1);
            }
            other => panic!("{name}: unknown role {other}"),
        }
    }
    assert_eq!(
        (apis, workers),
        (2, 3),
        "two API replicas and three workers"
    );
}

#[test]
fn kubernetes_manifests_use_real_commands_probes_and_secrets() {
    let kustomization = &yaml_documents("deploy/kubernetes/kustomization.yaml")[0];
    let docs: Vec<serde_yaml::Value> = kustomization["resources"]
        .as_sequence()
        .expect("resources")
        .iter()
        .flat_map(|r| yaml_documents(&format!("deploy/kubernetes/{}", text(r))))
        .collect();
    let of_kind = |kind: &str| -> Vec<&serde_yaml::Value> {
        docs.iter()
            .filter(|d| d["kind"].as_str() == Some(kind))
            .collect()
    };
    let secrets = of_kind("Secret");
    let config_maps = of_kind("ConfigMap");
    let healthz = phygap_api::http::route_table(1)
        .into_iter()
        .find(|r| r.path == "/healthz")
        .expect("a /healthz route");
    assert!(!healthz.protected);
    let mut roles = std::collections::BTreeMap::new();
    for deployment in of_kind("Deployment") {
        let name = text(&deployment["metadata"]["name"]);
        let template = &deployment["spec"]["template"];
        let labels = template["metadata"]["labels"].as_mapping().unwrap();
        for (key, value) in deployment["spec"]["selector"]["matchLabels"]
            .as_mapping()
            .unwrap()
        {
            assert_eq!(
                labels.get(key),
                Some(value),
                "{name}: selector matches the pods"
            );
        }
        let container = &template["spec"]["containers"][0];
        let (role, args) = checked_command(&container["args"], name);
        let port = &container["ports"][0];
        assert_eq!(
            port["containerPort"].as_u64(),
            Some(u64::from(args.bind.port())),
            "{name}"
        );
        for probe in ["readinessProbe", "livenessProbe"] {
            let get = &container[probe]["httpGet"];
            assert_eq!(get["path"].as_str(), Some(healthz.path), "{name} {probe}");
            assert_eq!(get["port"], port["name"], "{name} {probe}");
        }
        let env = container["env"].as_sequence().unwrap();
        assert_known_variables(env.iter().map(|e| text(&e["name"])), name);
        for reference in env
            .iter()
            .filter_map(|e| e["valueFrom"]["secretKeyRef"].as_mapping())
        {
            let (secret, key) = (&reference["name"], &reference["key"]);
            assert!(
                secrets.iter().any(|s| s["metadata"]["name"] == *secret && s["stringData"].get(key).is_some()),
                "{name}: secret {secret:?} has no key {key:?}"
            );
        }
        for source in container["envFrom"].as_sequence().unwrap() {
            let map = &source["configMapRef"]["name"];
            let config = config_maps
                .iter()
                .find(|c| c["metadata"]["name"] == *map)
                .expect("config map");
            let keys = config["data"].as_mapping().unwrap().keys();
            assert_known_variables(keys.map(text), name);
        }
        roles.insert(role.clone(), (deployment, container, args));
    }
    let (api, _, api_args) = &roles["serve"];
    assert_eq!(api_args.workers, 0, "the API replicas run no jobs");
    assert!(api["spec"]["replicas"].as_u64().unwrap() >= 2);
    let api_labels = &api["spec"]["template"]["metadata"]["labels"];
    let services = of_kind("Service");
    assert!(services.iter().any(|s| s["spec"]["selector"]
        .as_mapping()
        .unwrap()
        .iter()
        .all(|(k, v)| api_labels.get(k) == Some(v))));
    let (worker, worker_container, _) = &roles["worker"];
    assert!(worker_container["resources"]["limits"]["nvidia.com/gpu"].as_u64() >= Some(1));
    assert!(
        worker["spec"]["template"]["spec"]["terminationGracePeriodSeconds"].as_u64() >= Some(60),
        "time to checkpoint on stop"
    );
}
