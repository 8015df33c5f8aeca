"""Exceptions and retries, against a scripted server (503, 429 with Retry-After, dropped
connections, silence) and against nothing at all."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from fake_service import JOB, FakeService, Seen, error, silent_listener
from phygap_client import (
    BadInput,
    Client,
    ConnectionError,
    PhygapError,
    RetryPolicy,
    ServiceError,
    Timeout,
)
from conftest import free_port


def test_no_service_is_a_connection_error_after_the_deadline() -> None:
    url = f"http://127.0.0.1:{free_port()}"
    started = time.monotonic()
    with Client(url, retry=RetryPolicy(deadline=1.5, initial=0.1)) as client:
        with pytest.raises(ConnectionError):
            client.info()
    elapsed = time.monotonic() - started
    assert 1.4 < elapsed < 4, elapsed


def test_a_url_the_client_cannot_use_is_bad_input() -> None:
    with Client("ftp://example.invalid") as client:
        with pytest.raises(BadInput):
            client.info()
    with Client("not a url at all") as client:
        with pytest.raises(PhygapError):
            client.job("job_x")


def test_a_silent_service_is_a_timeout() -> None:
    for url in silent_listener():
        with Client(url, timeout=0.3, retry=RetryPolicy(deadline=0)) as client:
            with pytest.raises(Timeout):
                client.info()


def test_503_and_429_are_retried_honouring_retry_after() -> None:
    def script(seen: list[Seen], request: Seen):  # type: ignore[no-untyped-def]
        if request.path == "/v1/info":
            if len([s for s in seen if s.path == "/v1/info"]) < 2:
                return error(503, "store_unavailable", {"retry-after": "1"})
            return (
                200,
                {},
                {
                    "version": "9",
                    "engines": {},
                    "limits": {},
                    "queue": {},
                    "workers": 1,
                    "account": None,
                },
            )
        if request.path == "/v1/jobs":
            if not [s for s in seen if s.path == "/v1/jobs"]:
                return error(429, "queued_job_limit", {"retry-after": "1"})
            return 201, {}, JOB
        return error(404, "not_found")

    with FakeService(script) as fake, Client(fake.url, retry=RetryPolicy(initial=0.05)) as client:
        started = time.monotonic()
        assert client.info().version == "9"
        assert time.monotonic() - started >= 1.9  # two Retry-After: 1
        started = time.monotonic()
        job = client.train("cap_fake", {"iterations": 20})
        assert time.monotonic() - started >= 0.9
        assert job.id == "job_fake" and job.created_at is not None
        submits = [s for s in fake.seen if s.path == "/v1/jobs"]
        assert len(submits) == 2
        keys = {s.headers["idempotency-key"] for s in submits}
        assert len(keys) == 1 and keys.pop(), "one Idempotency-Key for both tries"


def test_the_deadline_bounds_the_retries() -> None:
    with FakeService(lambda seen, request: error(503, "store_unavailable")) as fake:
        with Client(fake.url, retry=RetryPolicy(deadline=1.0, initial=0.2)) as client:
            started = time.monotonic()
            with pytest.raises(ServiceError) as raised:
                client.info()
            assert raised.value.status == 503 and raised.value.code == "store_unavailable"
            assert time.monotonic() - started < 2.0
            assert len(fake.seen) >= 2
        # A Retry-After past the deadline is not waited for.
        with Client(fake.url, retry=RetryPolicy(deadline=1.0)) as client:
            fake.script = lambda seen, request: error(429, "busy", {"retry-after": "30"})
            started = time.monotonic()
            with pytest.raises(ServiceError):
                client.info()
            assert time.monotonic() - started < 1.0


def test_other_errors_are_not_retried() -> None:
    with FakeService(lambda seen, request: error(422, "invalid_config")) as fake:
        with Client(fake.url) as client:
            with pytest.raises(ServiceError) as raised:
                client.train("cap_fake", {"iterations": -5})
            assert raised.value.code == "invalid_config" and raised.value.status == 422
            assert len(fake.seen) == 1


def test_a_dropped_answer_is_retried_only_where_repeating_is_safe() -> None:
    def script(seen: list[Seen], request: Seen):  # type: ignore[no-untyped-def]
        if not [s for s in seen if s.path == request.path]:
            return None  # read the request, then hang up without answering
        return 200, {}, dict(JOB, state="queued")

    with FakeService(script) as fake, Client(fake.url, retry=RetryPolicy(initial=0.05)) as client:
        assert client.job("job_fake").state == "queued"  # GET: again
        assert client.train("cap_fake").id == "job_fake"  # keyed POST: again
        assert client.cancel("job_fake").id == "job_fake"  # cancel: again
        with pytest.raises(ConnectionError):
            client.restart("job_fake")  # may have taken effect: not again
        paths = [s.path for s in fake.seen]
        assert paths.count("/v1/jobs/job_fake") == 2
        assert paths.count("/v1/jobs") == 2
        assert paths.count("/v1/jobs/job_fake/restart") == 1


def test_local_files_are_bad_input(tmp_path: Path) -> None:
    with Client(f"http://127.0.0.1:{free_port()}", retry=RetryPolicy(deadline=0)) as client:
        with pytest.raises(BadInput):
            client.upload(tmp_path / "missing.zip")
        with pytest.raises(BadInput):
            client.relight("job_x", tmp_path / "missing.exr")
        with pytest.raises(BadInput):
            client.relight("job_x", tmp_path)  # a folder, not a map
