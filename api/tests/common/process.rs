//! The `phygap-api serve` binary as a separate process on a free loopback port, for tests that
//! must see the server survive (or measure it) from outside: its `/healthz`, its resident memory
//! and its open sockets are read from the process itself.

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use super::ApiClient;

/// A running `phygap-api serve`, killed when dropped.
pub struct ServerProcess {
    pub child: Child,
    pub api: ApiClient,
    pub port: u16,
}

/// A loopback port free at the time of asking.
pub fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port()
}

impl ServerProcess {
    /// Starts `phygap-api serve` on `data_dir` with `flags` (beside `--bind` and `--data-dir`)
    /// and waits until it answers `/healthz`.
    pub async fn start(data_dir: &Path, flags: &[&str]) -> ServerProcess {
        let port = free_port();
        let child = Command::new(env!("CARGO_BIN_EXE_phygap-api"))
            .arg("serve")
            .args(["--bind", &format!("127.0.0.1:{port}")])
            .arg("--data-dir")
            .arg(data_dir)
            .args(flags)
            .env("RUST_LOG", "warn")
            .stdout(Stdio::null())
            .spawn()
            .unwrap();
        let server = ServerProcess {
            child,
            api: ApiClient::new(format!("http://127.0.0.1:{port}")),
            port,
        };
        let deadline = Instant::now() + Duration::from_secs(30);
        while !server.healthy().await {
            assert!(Instant::now() < deadline, "the server did not start");
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
        server
    }

    /// Whether the process still runs and answers `/healthz` with 200.
    pub async fn healthy(&self) -> bool {
        let client = reqwest::Client::builder()
            .timeout(Duration::from_secs(5))
            .build()
            .unwrap();
        client
            .get(self.api.url("/healthz"))
            .send()
            .await
            .is_ok_and(|r| r.status() == 200)
    }

    /// Asserts that the server is alive and answering.
    pub async fn assert_up(&self, after: &str) {
        assert!(self.healthy().await, "the server is down after {after}");
    }

    /// The process's resident memory, bytes (`VmRSS`).
    pub fn resident_bytes(&self) -> u64 {
        status_field(self.child.id(), "VmRSS:") * 1024
    }

    /// How many sockets the process holds open (its listener among them).
    pub fn open_sockets(&self) -> usize {
        std::fs::read_dir(format!("/proc/{}/fd", self.child.id()))
            .map(|fds| {
                fds.filter_map(Result::ok)
                    .filter_map(|fd| std::fs::read_link(fd.path()).ok())
                    .filter(|target| target.to_string_lossy().starts_with("socket:"))
                    .count()
            })
            .unwrap_or(0)
    }
}

/// A `kB` field of `/proc/PID/status`.
fn status_field(pid: u32, field: &str) -> u64 {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .ok()
        .and_then(|status| {
            let line = status.lines().find(|l| l.starts_with(field))?;
            line.split_whitespace().nth(1)?.parse().ok()
        })
        .unwrap_or(0)
}

impl Drop for ServerProcess {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
