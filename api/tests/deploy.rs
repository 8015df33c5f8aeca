//! The deploy files use paths and flags that exist: their `serve` command lines parse with the
//! binary's clap definition and appear in its `--help`, the data dir matches the volume / state
//! directory, the health check hits a real route, and the Docker build names the real package and
//! binary.

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
    }
}

fn flags(argv: &[String]) -> Vec<&str> {
    argv.iter()
        .filter(|a| a.starts_with("--"))
        .map(String::as_str)
        .collect()
}

fn serve_help() -> String {
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_phygap-api"))
        .args(["serve", "--help"])
        .output()
        .unwrap();
    assert!(output.status.success());
    String::from_utf8(output.stdout).unwrap()
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
    let healthz = phygap_api::routes::route_table(1)
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
