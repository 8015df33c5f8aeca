"""Fixtures: the real service (``target/release/phygap-api serve``) on a free loopback port
with a temporary data dir and a token, small synthetic captures (``phygap synth``), and a
trained job shared by the tests that only read it.

The binaries are looked for in ``PHYGAP_BIN_DIR``, else the repository's ``target/release``
(``cargo build --release`` makes them); without them the tests fail, they do not skip."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Iterator, Optional

import httpx
import pytest

CLIENT_ROOT = Path(__file__).resolve().parents[1]
REPO_ROOT = CLIENT_ROOT.parents[1]
sys.path.insert(0, str(CLIENT_ROOT))

from phygap_client import Client, Job, RetryPolicy  # noqa: E402

TOKEN = "client-test-token"

#: A short run: the service is under test, not the reconstruction.
QUICK = {
    "iterations": 20,
    "checkpoint_interval": 10,
    "eval_interval": 10,
    "initial_surfels": 100,
    "max_surfels": 1000,
    "gridmap": False,
}


def binary(name: str) -> Path:
    """A binary of the workspace's release build (in PHYGAP_BIN_DIR, else cargo's target folder:
    CARGO_TARGET_DIR when set, as cargo itself reads it)."""
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO_ROOT / "target"))
    folder = Path(os.environ.get("PHYGAP_BIN_DIR", target / "release"))
    path = folder / name
    if not path.is_file():
        pytest.fail(f"{path} is missing: run `cargo build --release --workspace` first")
    return path


def free_port() -> int:
    """A loopback port free at the time of asking."""
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


class Server:
    """A ``phygap-api serve`` process that a test may kill and start again on the same port
    and data dir."""

    def __init__(self, data_dir: Path, extra: Optional[list[str]] = None) -> None:
        self.data_dir = data_dir
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.extra = extra or []
        self.process: Optional[subprocess.Popen[bytes]] = None
        self.log = data_dir.parent / f"{data_dir.name}.log"

    def start(self) -> None:
        """Starts the server and waits until it answers ``/healthz``."""
        command = [
            str(binary("phygap-api")),
            "serve",
            "--bind",
            f"127.0.0.1:{self.port}",
            "--data-dir",
            str(self.data_dir),
            "--workers",
            "1",
            "--lease-seconds",
            "2",
            *self.extra,
        ]
        environment = dict(os.environ, PHYGAP_TOKEN=TOKEN, RUST_LOG="warn")
        with self.log.open("ab") as log:
            self.process = subprocess.Popen(
                command, env=environment, stdout=log, stderr=subprocess.STDOUT
            )
        deadline = time.monotonic() + 60
        while True:
            try:
                if httpx.get(f"{self.url}/healthz", timeout=2).status_code == 200:
                    return
            except httpx.HTTPError:
                pass
            if self.process.poll() is not None:
                raise RuntimeError(f"the server exited: {self.log.read_text()[-2000:]}")
            if time.monotonic() > deadline:
                raise RuntimeError("the server did not start within 60 s")
            time.sleep(0.05)

    def kill(self) -> None:
        """Kills the server with SIGKILL: no shutdown, no checkpoint."""
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGKILL)
            self.process.wait()

    def stop(self) -> None:
        """Stops the server gracefully (SIGTERM), killing it after 30 s."""
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.kill()

    def client(self, **options: object) -> Client:
        """A client of this server with its token."""
        return Client(self.url, TOKEN, **options)  # type: ignore[arg-type]


@pytest.fixture(scope="session")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    """One service for the tests that do not stop it."""
    root = tmp_path_factory.mktemp("service")
    (root / "data").mkdir()
    running = Server(root / "data")
    running.start()
    yield running
    running.stop()


@pytest.fixture
def own_server(tmp_path: Path) -> Iterator[Server]:
    """A service of the test's own, which it may kill and restart."""
    (tmp_path / "data").mkdir()
    running = Server(tmp_path / "data")
    running.start()
    yield running
    running.kill()


@pytest.fixture(scope="session")
def phygap(server: Server) -> Iterator[Client]:
    """A client of the shared service, retrying for up to 60 s."""
    with server.client(retry=RetryPolicy(deadline=60)) as client:
        yield client


def synth(folder: Path, views: int = 10, size: Optional[int] = 24) -> Path:
    """A synthetic full-Stokes capture (``phygap synth``) in `folder` (`size` None: synth's
    default)."""
    command = [str(binary("phygap")), "synth", "--out", str(folder), "--views", str(views)]
    if size is not None:
        command += ["--size", str(size)]
    subprocess.run(command, check=True, capture_output=True)
    return folder


@pytest.fixture(scope="session")
def capture_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 10-view 24×24 synthetic capture folder."""
    return synth(tmp_path_factory.mktemp("synth") / "capture")


@pytest.fixture(scope="session")
def full_size_capture_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 10-view synthetic capture at synth's default size, whose 20-step model of 100
    surfels has no surface to extract a mesh from."""
    return synth(tmp_path_factory.mktemp("full") / "capture", size=None)


@pytest.fixture(scope="session")
def padded_capture_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The capture with 300 kB of noise beside it (a file transforms.json does not name), so
    that it spans several 64 KiB parts."""
    folder = synth(tmp_path_factory.mktemp("padded") / "capture")
    (folder / "notes").mkdir()
    (folder / "notes" / "noise.bin").write_bytes(os.urandom(300_000))
    return folder


@pytest.fixture(scope="session")
def trained(phygap: Client, capture_dir: Path) -> Job:
    """A 20-step job, succeeded, on the shared service."""
    capture = phygap.upload(capture_dir)
    job = capture.train(QUICK, max_runtime_seconds=600)
    return job.wait(timeout=300, poll_interval=0.2)
