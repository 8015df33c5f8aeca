"""A client of the phygap reconstruction service (the REST API of `phygap-api serve`).

    from phygap_client import Client

    with Client("http://127.0.0.1:8080", token="…") as phygap:
        capture = phygap.upload("capture.zip")        # resumable parts when it is large
        job = phygap.train(capture["id"], config={"iterations": 6000})
        job = phygap.wait(job["id"], on_event=print)     # progress events as they come
        phygap.download(job["id"], "model.glb", "model.glb")
        relit = phygap.wait(phygap.relight(job["id"], "studio.exr", rotate_deg=90)["id"])

Written on httpx rather than generated from api/openapi.yaml: the generators' output is
thousands of lines of models for an API of a dozen routes, and what a user needs (streaming an
archive up, following a run, resuming a download) is not in the document. Every error of the
service raises `PhygapError` with its stable `code`.
"""

from __future__ import annotations

import base64
import hashlib
import json
import os
import time
from pathlib import Path
from typing import Any, Callable, Iterator, Optional

import httpx

__all__ = ["Client", "PhygapError"]

#: The states a job ends in.
ENDED = ("succeeded", "failed", "cancelled")

#: Bytes a part of a resumable upload (the service takes 64 KiB to 128 MiB).
PART_BYTES = 64 << 20


class PhygapError(Exception):
    """An error the service answered: HTTP `status`, stable `code`, `message`, and for a
    rejected capture each `problems` entry (frame, key, message)."""

    def __init__(self, status: int, code: str, message: str, problems: list | None = None):
        super().__init__(f"{status} {code}: {message}")
        self.status = status
        self.code = code
        self.message = message
        self.problems = problems or []


class Client:
    """The service at `base_url` (e.g. `http://127.0.0.1:8080`), with an optional bearer token
    (default: the `PHYGAP_TOKEN` variable)."""

    def __init__(self, base_url: str, token: Optional[str] = None, timeout: float = 60.0):
        token = token if token is not None else os.environ.get("PHYGAP_TOKEN")
        headers = {"authorization": f"Bearer {token}"} if token else {}
        self._http = httpx.Client(base_url=base_url.rstrip("/"), headers=headers, timeout=timeout)

    def __enter__(self) -> "Client":
        return self

    def __exit__(self, *_: Any) -> None:
        self.close()

    def close(self) -> None:
        self._http.close()

    # The routes.

    def info(self) -> dict:
        """Version, engines, limits and the queue (`GET /v1/info`)."""
        return self._json("GET", "/v1/info")

    def upload(
        self,
        archive: str | os.PathLike,
        part_bytes: int = PART_BYTES,
        retries: int = 5,
        on_part: Optional[Callable[[int, int], None]] = None,
    ) -> dict:
        """Uploads a capture archive (.zip or .tar); returns the capture.

        An archive of one part goes in one request. A larger one goes in resumable parts of
        `part_bytes`, each with its SHA-256: a part whose connection breaks is sent again (up to
        `retries` times in a row, backing off), and the upload's id is kept beside the archive
        (`ARCHIVE.phygap-upload`) until it commits, so calling `upload` again after an
        interruption sends only the parts the service lacks. `on_part(index, count)` is called
        after each part is stored."""
        path = Path(archive)
        size = path.stat().st_size
        if size <= part_bytes:
            return self._upload_whole(path)
        state_file = path.with_name(path.name + ".phygap-upload")
        upload = self._resumable_upload(path, size, part_bytes, state_file)
        count = upload["parts"]
        have = set(upload["received"])
        with path.open("rb") as file:
            for index in range(count):
                if index in have:
                    continue
                file.seek(index * upload["part_size"])
                part = file.read(upload["part_size"])
                self._retrying(retries, lambda: self._put_part(upload["id"], index, part))
                if on_part is not None:
                    on_part(index, count)
        capture = self._retrying(
            retries, lambda: self._json("POST", f"/v1/uploads/{upload['id']}/commit", timeout=None)
        )
        state_file.unlink(missing_ok=True)
        return capture

    def upload_status(self, upload_id: str) -> dict:
        """A resumable upload: its parts, which arrived, its state (`GET /v1/uploads/{id}`)."""
        return self._json("GET", f"/v1/uploads/{upload_id}")

    def _upload_whole(self, path: Path, chunk_bytes: int = 1 << 20) -> dict:
        kind = "application/zip" if path.suffix.lower() == ".zip" else "application/x-tar"

        def chunks() -> Iterator[bytes]:
            with path.open("rb") as file:
                while chunk := file.read(chunk_bytes):
                    yield chunk

        headers = {"content-type": kind, "content-length": str(path.stat().st_size)}
        return self._json("POST", "/v1/captures", content=chunks(), headers=headers, timeout=None)

    def _resumable_upload(self, path: Path, size: int, part_bytes: int, state_file: Path) -> dict:
        """The open upload recorded beside the archive for this very file, or a new one."""
        stamp = {"size": size, "mtime_ns": path.stat().st_mtime_ns}
        if state_file.exists():
            try:
                saved = json.loads(state_file.read_text())
                if saved.get("file") == stamp:
                    upload = self.upload_status(saved["id"])
                    if upload["state"] in ("open", "committing", "committed"):
                        return upload
            except (PhygapError, ValueError, KeyError):
                pass
        digest = hashlib.sha256()
        with path.open("rb") as file:
            while chunk := file.read(1 << 20):
                digest.update(chunk)
        upload = self._json(
            "POST",
            "/v1/uploads",
            json={"size": size, "part_size": part_bytes, "sha256": digest.hexdigest()},
        )
        state_file.write_text(json.dumps({"id": upload["id"], "file": stamp}))
        return upload

    def _put_part(self, upload_id: str, index: int, part: bytes) -> dict:
        digest = base64.b64encode(hashlib.sha256(part).digest()).decode()
        headers = {
            "content-digest": f"sha-256=:{digest}:",
            "content-type": "application/octet-stream",
        }
        return self._json(
            "PUT", f"/v1/uploads/{upload_id}/parts/{index}", content=part, headers=headers,
            timeout=None,
        )

    @staticmethod
    def _retrying(retries: int, call: Callable[[], Any]) -> Any:
        """`call()`, again after a broken connection or a 5xx, at most `retries` more times."""
        for attempt in range(retries + 1):
            try:
                return call()
            except httpx.TransportError:
                if attempt == retries:
                    raise
            except PhygapError as error:
                if error.status < 500 or attempt == retries:
                    raise
            time.sleep(min(30.0, 0.5 * 2**attempt))
        raise AssertionError("unreachable")

    def train(
        self,
        capture_id: str,
        config: Optional[dict] = None,
        webhook: Optional[str] = None,
        idempotency_key: Optional[str] = None,
        priority: Optional[int] = None,
        max_runtime_seconds: Optional[int] = None,
    ) -> dict:
        """Queues a training job; a retry with the same `idempotency_key` returns the same job.

        `priority` (higher starts first, within the token's bounds) and `max_runtime_seconds`
        (past it the job checkpoints and fails `time_limit`) are the service's defaults when
        left out."""
        body: dict[str, Any] = {"capture_id": capture_id, "config": config or {}}
        if webhook:
            body["webhook"] = webhook
        if priority is not None:
            body["priority"] = priority
        if max_runtime_seconds is not None:
            body["max_runtime_seconds"] = max_runtime_seconds
        headers = {"idempotency-key": idempotency_key} if idempotency_key else {}
        return self._json("POST", "/v1/jobs", json=body, headers=headers)

    def job(self, job_id: str) -> dict:
        return self._json("GET", f"/v1/jobs/{job_id}")

    def jobs(self, limit: int = 100) -> list[dict]:
        return self._json("GET", "/v1/jobs", params={"limit": limit})["jobs"]

    def progress(self, job_id: str, start: int = 0) -> dict:
        """Recorded events of a job from number `start`: `{"events": […], "next": N}`."""
        return self._json("GET", f"/v1/jobs/{job_id}/progress", params={"from": start})

    def wait(
        self,
        job_id: str,
        on_event: Optional[Callable[[dict], None]] = None,
        poll_seconds: float = 1.0,
        timeout_seconds: Optional[float] = None,
    ) -> dict:
        """Waits for a job to end, passing each progress event (step, evaluated, checkpoint,
        warning, …) to `on_event` as it is recorded; returns the job as it ended."""
        deadline = None if timeout_seconds is None else time.monotonic() + timeout_seconds
        seen = 0
        while True:
            job = self.job(job_id)
            if on_event is not None:
                page = self.progress(job_id, seen)
                for entry in page["events"]:
                    on_event(entry["event"])
                seen = page["next"]
            if job["state"] in ENDED:
                return job
            if deadline is not None and time.monotonic() > deadline:
                raise TimeoutError(f"job {job_id} is still {job['state']}")
            time.sleep(poll_seconds)

    def cancel(self, job_id: str) -> dict:
        return self._json("POST", f"/v1/jobs/{job_id}/cancel")

    def restart(self, job_id: str, config: Optional[dict] = None) -> dict:
        """Runs a failed or cancelled job again: resuming, or over with changed settings."""
        return self._json(
            "POST", f"/v1/jobs/{job_id}/restart", json={"config": config} if config else {}
        )

    def delete(self, job_id: str) -> None:
        self._request("DELETE", f"/v1/jobs/{job_id}")

    def artifacts(self, job_id: str) -> list[dict]:
        return self._json("GET", f"/v1/jobs/{job_id}/artifacts")["artifacts"]

    def download(
        self, job_id: str, name: str, target: str | os.PathLike, chunk_bytes: int = 1 << 20
    ) -> Path:
        """Downloads an artifact to `target`; a partial file there is resumed with a Range
        request, guarded by the artifact's ETag (a different file starts over)."""
        target = Path(target)
        partial = target.with_name(target.name + ".part")
        tag_file = target.with_name(target.name + ".etag")
        headers = {}
        have = partial.stat().st_size if partial.exists() else 0
        if have and tag_file.exists():
            headers = {"range": f"bytes={have}-", "if-range": tag_file.read_text()}
        # A service with presigned downloads answers 307 to the bucket; httpx drops the token on
        # the way there (another origin) and keeps the Range.
        with self._http.stream(
            "GET",
            f"/v1/jobs/{job_id}/artifacts/{name}",
            headers=headers,
            timeout=None,
            follow_redirects=True,
        ) as response:
            if response.status_code >= 400:
                response.read()
                raise _error(response)
            mode = "ab" if response.status_code == 206 else "wb"
            if "etag" in response.headers:
                tag_file.write_text(response.headers["etag"])
            with partial.open(mode) as file:
                for chunk in response.iter_bytes(chunk_bytes):
                    file.write(chunk)
        partial.replace(target)
        tag_file.unlink(missing_ok=True)
        return target

    def relight(
        self,
        job_id: str,
        envmap: str | os.PathLike,
        rotate_deg: float = 0.0,
        cameras: Optional[str | os.PathLike] = None,
        webhook: Optional[str] = None,
    ) -> dict:
        """Queues a relight of a trained job under an .exr or .hdr map; returns the new job."""
        files = {"envmap": (Path(envmap).name, Path(envmap).read_bytes())}
        if cameras is not None:
            files["cameras"] = ("cameras.json", Path(cameras).read_bytes())
        data = {"rotate_deg": str(rotate_deg)}
        if webhook:
            data["webhook"] = webhook
        return self._json("POST", f"/v1/jobs/{job_id}/relight", files=files, data=data)

    # Plumbing.

    def _request(self, method: str, path: str, **kwargs: Any) -> httpx.Response:
        response = self._http.request(method, path, **kwargs)
        if response.status_code >= 400:
            raise _error(response)
        return response

    def _json(self, method: str, path: str, **kwargs: Any) -> Any:
        return self._request(method, path, **kwargs).json()


def _error(response: httpx.Response) -> PhygapError:
    try:
        error = response.json()["error"]
        return PhygapError(
            response.status_code, error["code"], error["message"], error.get("problems")
        )
    except Exception:  # noqa: BLE001 - not the service's JSON shape
        return PhygapError(response.status_code, "http_error", response.text[:500])
