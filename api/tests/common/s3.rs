//! A throwaway S3-compatible server for the tests: moto's server mode (`pip install
//! 'moto[server]'`), listening on a free loopback port with one empty bucket, killed on drop.

use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A running S3 server with one bucket.
pub struct TempS3 {
    child: Option<Child>,
    port: u16,
    /// The service's `--artifact-url` for the bucket (with a prefix, as deployments use).
    pub url: String,
}

fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
        .expect("binding a loopback port")
}

/// The request line answered by the server at `path` (`PUT` creates a bucket).
fn http(port: u16, method: &str, path: &str) -> std::io::Result<String> {
    use std::io::{Read, Write};
    let mut stream = std::net::TcpStream::connect(("127.0.0.1", port))?;
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    write!(
        stream,
        "{method} {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"
    )?;
    let mut answer = String::new();
    stream.read_to_string(&mut answer)?;
    Ok(answer.lines().next().unwrap_or_default().to_owned())
}

/// `moto_server`, or `python3 -m moto.server` where only the module is on the path.
fn moto_command() -> Option<Command> {
    let runs = |program: &str, args: &[&str]| {
        Command::new(program)
            .args(args)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    if runs("moto_server", &["--help"]) {
        Some(Command::new("moto_server"))
    } else if runs("python3", &["-c", "import moto.server"]) {
        let mut command = Command::new("python3");
        command.args(["-m", "moto.server"]);
        Some(command)
    } else {
        None
    }
}

impl TempS3 {
    /// Starts a server, or `None` with a printed notice where moto is not installed (under
    /// `CI=true` that is a failure: CI installs it).
    pub fn start() -> Option<TempS3> {
        let port = free_port();
        let Some(mut command) = moto_command() else {
            let notice = "moto is not installed (pip install 'moto[server]'); \
                          skipping the S3 object store tests";
            assert!(!phygap::testing::running_in_ci(), "{notice}");
            eprintln!("notice: {notice}");
            return None;
        };
        let child = command
            .args(["-H", "127.0.0.1", "-p", &port.to_string()])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("starting moto's server");
        let server = TempS3 {
            child: Some(child),
            port,
            url: "s3://phygap-test/deployment".into(),
        };
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            match http(port, "PUT", "/phygap-test") {
                Ok(status) if status.contains(" 200") => break,
                _ if Instant::now() < deadline => std::thread::sleep(Duration::from_millis(200)),
                other => panic!("moto_server on port {port} did not start: {other:?}"),
            }
        }
        Some(server)
    }

    /// The object-store settings a service needs to reach this server.
    pub fn options(&self) -> Vec<(String, String)> {
        [
            ("aws_endpoint", format!("http://127.0.0.1:{}", self.port)),
            ("aws_allow_http", "true".into()),
            ("aws_access_key_id", "test".into()),
            ("aws_secret_access_key", "test".into()),
            ("aws_region", "us-east-1".into()),
        ]
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect()
    }

    /// The same settings as environment variables, for a `phygap-api` child process.
    pub fn env(&self) -> Vec<(String, String)> {
        self.options()
            .into_iter()
            .map(|(k, v)| (k.to_uppercase(), v))
            .collect()
    }

    /// Kills the server (an outage); the bucket's contents are lost with it.
    pub fn stop(&mut self) {
        if let Some(mut child) = self.child.take() {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

impl Drop for TempS3 {
    fn drop(&mut self) {
        self.stop();
    }
}
