"""The service killed (SIGKILL) and started again on the same port and data dir while the
client waits for a job, and while it uploads."""

from __future__ import annotations

import threading
import time
from pathlib import Path

from conftest import QUICK, Server
from phygap_client import ProgressEvent, RetryPolicy


def restart_later(server: Server, after: float) -> threading.Thread:
    """Starts the server again `after` seconds from now, in a thread."""

    def run() -> None:
        time.sleep(after)
        server.start()

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread


def test_wait_rides_out_a_restart_and_resumes_its_events(
    own_server: Server, capture_dir: Path
) -> None:
    with own_server.client(retry=RetryPolicy(deadline=90)) as client:
        capture = client.upload(capture_dir)
        job = capture.train(dict(QUICK, iterations=200, checkpoint_interval=20, eval_interval=100))
        events: list[ProgressEvent] = []
        restarted: list[threading.Thread] = []

        def on_event(event: ProgressEvent) -> None:
            events.append(event)
            if event.type == "step" and not restarted:
                own_server.kill()
                restarted.append(restart_later(own_server, 1.0))

        done = job.wait(on_event, timeout=300, poll_interval=0.2)
        assert restarted, "the job ended before a step was reported"
        restarted[0].join()
        assert done.succeeded, done
        assert done.attempts >= 2, "the job ran again after the kill"
        seqs = [event.seq for event in events]
        assert seqs == list(range(len(seqs))), "every event once, in order"
        kinds = [event.type for event in events]
        assert kinds.count("started") >= 2 and kinds[-1] == "finished", kinds


def test_an_upload_rides_out_a_restart(own_server: Server, padded_capture_dir: Path) -> None:
    restarted: list[threading.Thread] = []

    def on_progress(done: int, total: int) -> None:
        if done >= 2 * (64 << 10) and not restarted:
            own_server.kill()
            restarted.append(restart_later(own_server, 1.0))

    with own_server.client(retry=RetryPolicy(deadline=90)) as client:
        capture = client.upload(padded_capture_dir, part_size=64 << 10, progress=on_progress)
        assert restarted
        restarted[0].join()
        assert capture.views == 10
        assert client.capture(capture.id).views == 10
