"""`Client`: the service's routes as methods that answer typed objects (`models`)."""

from __future__ import annotations

import base64
import contextlib
import functools
import json
import os
import sys
import time
import uuid
from pathlib import Path, PurePosixPath
from typing import IO, Any, Callable, Iterator, Mapping, Optional, TypeVar, Union, cast

import httpx

from . import _archive
from ._transport import RetryPolicy, Safety, Transport, guarded
from .errors import BadInput, ConnectionError, JobFailed, PhygapError, ServiceError, Timeout
from .models import ENDED, Artifact, Capture, Job, PathLike, ProgressEvent, ServiceInfo, Upload

__all__ = ["Client", "ProgressBar", "PART_BYTES", "DEFAULT_URL"]

#: Bytes a part of a resumable upload (the service takes 64 KiB to 128 MiB).
PART_BYTES = 64 << 20

#: Where the client looks when neither an address nor ``PHYGAP_URL`` is given.
DEFAULT_URL = "http://127.0.0.1:8080"

#: Longest wait for the answer to a request that makes the service check a whole capture (an
#: upload's last byte, a commit), seconds.
VALIDATION_SECONDS = 900.0

F = TypeVar("F", bound=Callable[..., Any])

#: A progress report: bytes done, bytes in all.
ProgressCallback = Callable[[int, int], None]


def _public(method: F) -> F:
    """Makes a public method raise only the client's exceptions."""

    @functools.wraps(method)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        return guarded(lambda: method(*args, **kwargs))

    return cast(F, wrapper)


class ProgressBar:
    """A one-line text progress bar on standard error (what ``progress=True`` shows)."""

    def __init__(self, label: str, stream: Optional[IO[str]] = None) -> None:
        self.label = label
        self.stream = stream if stream is not None else sys.stderr
        self._shown = -1.0

    def __call__(self, done: int, total: int) -> None:
        """Shows `done` of `total` bytes (redrawn at most every half per cent)."""
        fraction = done / total if total else 1.0
        if fraction - self._shown < 0.005 and done < total:
            return
        self._shown = fraction
        width = 30
        filled = int(width * fraction)
        self.stream.write(
            f"\r{self.label} [{'#' * filled}{'.' * (width - filled)}] {fraction:6.1%} "
            f"{done / 2**20:.1f}/{total / 2**20:.1f} MiB"
        )
        if done >= total:
            self.stream.write("\n")
        self.stream.flush()


def _reporter(
    progress: Union[ProgressCallback, bool, None], label: str
) -> Optional[ProgressCallback]:
    if progress is True:
        return ProgressBar(label)
    if progress is False or progress is None:
        return None
    return progress


def _id_of(item: Union[str, Job, Capture, Upload]) -> str:
    return item if isinstance(item, str) else item.id


class Client:
    """The service at `base_url` (default: ``PHYGAP_URL``, else ``http://127.0.0.1:8080``)
    with an optional bearer `token` (default: ``PHYGAP_TOKEN``).

    `timeout` bounds each network operation (connecting, each read and write), seconds;
    `retry` says how requests the service could not take are retried (`RetryPolicy`: by
    default for up to two minutes, which a restart of the service fits in). Every method
    raises only `PhygapError` and its subclasses. Use it as a context manager, or `close` it.
    """

    def __init__(
        self,
        base_url: Optional[str] = None,
        token: Optional[str] = None,
        *,
        timeout: float = 60.0,
        retry: Optional[RetryPolicy] = None,
    ) -> None:
        base_url = base_url or os.environ.get("PHYGAP_URL") or DEFAULT_URL
        token = token if token is not None else os.environ.get("PHYGAP_TOKEN")
        headers = {"authorization": f"Bearer {token}"} if token else {}
        self.base_url = base_url.rstrip("/")
        self.retry = retry or RetryPolicy()
        try:
            http = httpx.Client(
                base_url=self.base_url,
                headers=headers,
                timeout=httpx.Timeout(timeout),
                follow_redirects=False,
            )
        except (httpx.HTTPError, ValueError, TypeError) as error:
            raise BadInput(f"cannot use {base_url!r}: {error}") from error
        self._transport = Transport(http, self.retry)
        self._timeout = timeout

    def __enter__(self) -> Client:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    def close(self) -> None:
        """Closes the connections."""
        self._transport.http.close()

    def __repr__(self) -> str:
        return f"Client({self.base_url!r})"

    # What the service offers.

    @_public
    def info(self) -> ServiceInfo:
        """Version, engines, limits and the queue (``GET /v1/info``)."""
        return ServiceInfo.from_json(self._transport.json(Safety.REPEATABLE, "GET", "/v1/info"))

    # Captures and uploads.

    @_public
    def upload(
        self,
        source: PathLike,
        *,
        part_size: int = PART_BYTES,
        progress: Union[ProgressCallback, bool, None] = None,
        scratch: Optional[PathLike] = None,
    ) -> Capture:
        """Uploads a capture, a folder or a ``.zip``/``.tar`` archive; returns the capture.

        A folder is written into a tar archive in a temporary file (in `scratch`, the system's
        temporary folder by default) a block at a time, never whole in memory. An archive of
        at most `part_size` bytes goes in one request; a larger one in resumable parts of
        `part_size`, each sent again after a dropped connection or a restart of the service,
        and the upload's id is kept beside the source (``SOURCE.phygap-upload``) until it
        commits, so the same call after a crash sends only the parts the service lacks.
        `progress` is called with (bytes sent, bytes in all), or ``True`` shows a bar.
        """
        path = Path(source)
        report = _reporter(progress, f"upload {path.name}")
        if not path.exists():
            raise BadInput(f"{path}: no such file or folder")
        if path.is_dir():
            tar = _archive.folder_to_tar(path, Path(scratch) if scratch is not None else None)
            try:
                return self._upload_archive(tar, path, part_size, report, folder=True)
            finally:
                tar.unlink(missing_ok=True)
        return self._upload_archive(path, path, part_size, report, folder=False)

    def _upload_archive(
        self,
        archive: Path,
        source: Path,
        part_size: int,
        report: Optional[ProgressCallback],
        folder: bool,
    ) -> Capture:
        size = archive.stat().st_size
        if size <= part_size:
            return self._upload_whole(archive, size, report)
        state_file = source.with_name(source.name + ".phygap-upload")
        digest: Optional[str] = None
        if folder:
            # The folder's tar is new each time: its hash says whether it is the one recorded.
            digest = _archive.sha256_of(archive).hex()
            stamp: dict[str, Any] = {"size": size, "sha256": digest}
        else:
            stamp = {"size": size, "mtime_ns": archive.stat().st_mtime_ns}
        upload = self._recorded_upload(state_file, stamp)
        if upload is None:
            if digest is None:
                digest = _archive.sha256_of(archive).hex()
            upload = self.create_upload(size, part_size=part_size, sha256=digest)
            with contextlib.suppress(OSError):
                state_file.write_text(json.dumps({"id": upload.id, "file": stamp}))
        done = upload.received_bytes
        if report is not None:
            report(done, size)
        for index in upload.missing:
            start = index * upload.part_size
            length = min(upload.part_size, size - start)
            self._put_part(upload.id, archive, index, start, length)
            done += length
            if report is not None:
                report(min(done, size), size)
        data = self._transport.json(
            Safety.REPEATABLE,
            "POST",
            f"/v1/uploads/{upload.id}/commit",
            timeout=httpx.Timeout(self._timeout, read=VALIDATION_SECONDS),
        )
        with contextlib.suppress(OSError):
            state_file.unlink()
        return Capture.from_json(data, self)

    def _recorded_upload(self, state_file: Path, stamp: dict[str, Any]) -> Optional[Upload]:
        """The open upload recorded in `state_file` for this very archive, if any."""
        try:
            saved = json.loads(state_file.read_text())
        except (OSError, ValueError):
            return None
        if not isinstance(saved, dict) or saved.get("file") != stamp:
            return None
        try:
            upload = self.upload_status(str(saved["id"]))
        except (ServiceError, KeyError):
            return None
        return upload if upload.state in ("open", "committing", "committed") else None

    def _upload_whole(
        self, archive: Path, size: int, report: Optional[ProgressCallback]
    ) -> Capture:
        with archive.open("rb") as file:
            head = file.read(4)
        kind = "application/zip" if head.startswith(b"PK") else "application/x-tar"

        def body() -> Iterator[bytes]:
            sent = 0
            for block in _archive.chunks(archive):
                yield block
                sent += len(block)
                if report is not None:
                    report(sent, size)

        data = self._transport.json(
            Safety.UNSENT,
            "POST",
            "/v1/captures",
            content_factory=body,
            headers={"content-type": kind, "content-length": str(size)},
            timeout=httpx.Timeout(self._timeout, read=VALIDATION_SECONDS),
        )
        return Capture.from_json(data, self)

    def _put_part(self, upload_id: str, archive: Path, index: int, start: int, length: int) -> None:
        digest = base64.b64encode(_archive.sha256_of(archive, start, length)).decode()
        self._transport.request(
            Safety.REPEATABLE,
            "PUT",
            f"/v1/uploads/{upload_id}/parts/{index}",
            content_factory=lambda: _archive.chunks(archive, start, length),
            headers={
                "content-digest": f"sha-256=:{digest}:",
                "content-type": "application/octet-stream",
                "content-length": str(length),
            },
        )

    @_public
    def create_upload(
        self, size: int, *, part_size: Optional[int] = None, sha256: Optional[str] = None
    ) -> Upload:
        """Declares a resumable upload of an archive of `size` bytes (``POST /v1/uploads``);
        `upload` does this and the rest."""
        body: dict[str, Any] = {"size": size}
        if part_size is not None:
            body["part_size"] = part_size
        if sha256 is not None:
            body["sha256"] = sha256
        return Upload.from_json(
            self._transport.json(Safety.UNSENT, "POST", "/v1/uploads", json=body), self
        )

    @_public
    def upload_status(self, upload_id: str) -> Upload:
        """A resumable upload: its parts, which arrived, its state."""
        return Upload.from_json(
            self._transport.json(Safety.REPEATABLE, "GET", f"/v1/uploads/{upload_id}"), self
        )

    @_public
    def delete_upload(self, upload: Union[str, Upload]) -> None:
        """Abandons a resumable upload: the service removes it with its parts."""
        self._transport.request(Safety.REPEATABLE, "DELETE", f"/v1/uploads/{_id_of(upload)}")

    @_public
    def capture(self, capture_id: str) -> Capture:
        """A capture by its id."""
        return Capture.from_json(
            self._transport.json(Safety.REPEATABLE, "GET", f"/v1/captures/{capture_id}"), self
        )

    @_public
    def delete_capture(self, capture: Union[str, Capture]) -> None:
        """Removes a capture from the service."""
        self._transport.request(Safety.REPEATABLE, "DELETE", f"/v1/captures/{_id_of(capture)}")

    # Jobs.

    @_public
    def train(
        self,
        capture: Union[str, Capture],
        config: Optional[Mapping[str, Any]] = None,
        *,
        webhook: Optional[str] = None,
        idempotency_key: Optional[str] = None,
        priority: Optional[int] = None,
        max_runtime_seconds: Optional[int] = None,
    ) -> Job:
        """Queues a training job on a capture; returns it.

        `config` holds training settings (``phygap config`` lists them; e.g.
        ``{"iterations": 6000}``). The request carries an Idempotency-Key (`idempotency_key`,
        or a random one), so the client may send it again after a dropped connection without
        queueing a second job; the same key in a later call also answers the same job.
        `priority` (higher starts first, within the token's bounds) and `max_runtime_seconds`
        (past it the job checkpoints and fails ``time_limit``) are the service's defaults when
        left out; `webhook` is a URL the job's end is POSTed to."""
        body: dict[str, Any] = {"capture_id": _id_of(capture), "config": dict(config or {})}
        if webhook:
            body["webhook"] = webhook
        if priority is not None:
            body["priority"] = priority
        if max_runtime_seconds is not None:
            body["max_runtime_seconds"] = max_runtime_seconds
        key = idempotency_key or f"phygap-client-{uuid.uuid4().hex}"
        data = self._transport.json(
            Safety.REPEATABLE, "POST", "/v1/jobs", json=body, headers={"idempotency-key": key}
        )
        return Job.from_json(data, self)

    @_public
    def job(self, job_id: str) -> Job:
        """A job by its id, as it stands now."""
        return self._job(job_id)

    def _job(self, job_id: str, deadline: Optional[float] = None) -> Job:
        data = self._transport.json(Safety.REPEATABLE, "GET", f"/v1/jobs/{job_id}", deadline)
        return Job.from_json(data, self)

    @_public
    def jobs(self, limit: int = 100) -> list[Job]:
        """The token's jobs, newest first."""
        data = self._transport.json(Safety.REPEATABLE, "GET", "/v1/jobs", params={"limit": limit})
        return [Job.from_json(item, self) for item in data["jobs"]]

    @_public
    def progress(self, job_id: str, from_event: int = 0) -> tuple[list[ProgressEvent], int]:
        """A job's recorded progress events from number `from_event`, and the number that
        continues after them."""
        return self._progress(job_id, from_event)

    def _progress(
        self, job_id: str, from_event: int, deadline: Optional[float] = None
    ) -> tuple[list[ProgressEvent], int]:
        data = self._transport.json(
            Safety.REPEATABLE,
            "GET",
            f"/v1/jobs/{job_id}/progress",
            deadline,
            params={"from": from_event},
        )
        events = [ProgressEvent.from_json(entry) for entry in data.get("events", [])]
        return events, int(data.get("next", from_event))

    @_public
    def wait(
        self,
        job: Union[str, Job],
        on_event: Optional[Callable[[ProgressEvent], None]] = None,
        *,
        timeout: Optional[float] = None,
        poll_interval: float = 1.0,
        raise_on_failure: bool = True,
        from_event: int = 0,
        _progress: Optional[Job] = None,
    ) -> Job:
        """Waits for a job to end; returns it as it ended.

        Each progress event recorded from number `from_event` on is passed to `on_event` as it
        comes (`Job.wait` goes on from the last event an earlier wait passed on). A restart of
        the service, or a dropped connection, is ridden out: the client reconnects (within its
        retry policy's deadline for each outage) and goes on from the last event it saw. Raises
        `JobFailed` (the job's ``error_code`` and ``error``) when the job failed or was
        cancelled, unless `raise_on_failure` is false, and `Timeout` when it has not ended
        within `timeout` seconds."""
        job_id = _id_of(job)
        end = None if timeout is None else time.monotonic() + timeout
        seen = from_event
        while True:
            try:
                current = self._job(job_id, end)
                if on_event is not None:
                    events, upcoming = self._progress(job_id, seen, end)
                    for event in events:
                        if event.seq < seen:
                            continue
                        seen = event.seq + 1
                        if _progress is not None:
                            _progress.next_event = seen
                        on_event(event)
                    seen = max(seen, upcoming)
                    if _progress is not None:
                        _progress.next_event = seen
            except (ConnectionError, Timeout, ServiceError) as error:
                if end is not None and time.monotonic() >= end:
                    raise Timeout(
                        f"job {job_id} did not end within {timeout} s (last: {error})"
                    ) from error
                raise
            current.next_event = seen
            if current.state in ENDED:
                if raise_on_failure and current.state != "succeeded":
                    raise JobFailed(current)
                return current
            if end is not None and time.monotonic() >= end:
                raise Timeout(f"job {job_id} is still {current.state} after {timeout} s")
            pause = poll_interval
            if end is not None:
                pause = max(0.0, min(pause, end - time.monotonic()))
            time.sleep(pause)

    @_public
    def cancel(self, job: Union[str, Job]) -> Job:
        """Asks the service to stop a queued or running job (it checkpoints first)."""
        data = self._transport.json(Safety.REPEATABLE, "POST", f"/v1/jobs/{_id_of(job)}/cancel")
        return Job.from_json(data, self)

    @_public
    def restart(self, job: Union[str, Job], config: Optional[Mapping[str, Any]] = None) -> Job:
        """Runs a failed or cancelled job again: from its last checkpoint, or over with the
        settings in `config` changed. Sent again only when it certainly did not arrive."""
        body: dict[str, Any] = {"config": dict(config)} if config else {}
        data = self._transport.json(
            Safety.UNSENT, "POST", f"/v1/jobs/{_id_of(job)}/restart", json=body
        )
        return Job.from_json(data, self)

    @_public
    def delete_job(self, job: Union[str, Job]) -> None:
        """Removes a job, its checkpoints and its artifacts (cancelling it first)."""
        self._transport.request(
            Safety.REPEATABLE,
            "DELETE",
            f"/v1/jobs/{_id_of(job)}",
            timeout=httpx.Timeout(self._timeout, read=max(self._timeout, 120.0)),
        )

    @_public
    def artifacts(self, job: Union[str, Job]) -> list[Artifact]:
        """A job's files (empty until it has succeeded), sorted by name."""
        job_id = _id_of(job)
        data = self._transport.json(Safety.REPEATABLE, "GET", f"/v1/jobs/{job_id}/artifacts")
        return [
            Artifact(
                job_id=job_id,
                name=str(item["name"]),
                size=int(item.get("size", 0)),
                content_type=str(item.get("content_type", "")),
                _client=self,
            )
            for item in data.get("artifacts", [])
        ]

    @_public
    def download(self, job: Union[str, Job], name: str, target: PathLike) -> Path:
        """Downloads the artifact `name` of a job to the file `target` (its folder is made).

        Bytes arrive in ``TARGET.part``, renamed when complete; a connection that drops goes on
        from where it stopped (a Range request guarded by the artifact's ETag, so a different
        file starts over), within the retry policy's deadline, and so does a later call after
        a crash."""
        return self._download(_id_of(job), name, Path(target))

    def _download(self, job_id: str, name: str, target: Path) -> Path:
        target.parent.mkdir(parents=True, exist_ok=True)
        partial = target.with_name(target.name + ".part")
        tag_file = target.with_name(target.name + ".etag")

        def attempt() -> httpx.Response:
            have = partial.stat().st_size if partial.exists() else 0
            headers: dict[str, str] = {}
            if have and tag_file.exists():
                headers = {"range": f"bytes={have}-", "if-range": tag_file.read_text().strip()}
            # A service with presigned downloads answers 307 to the bucket; httpx drops the
            # token on the way there (another origin) and keeps the Range.
            with self._transport.http.stream(
                "GET",
                f"/v1/jobs/{job_id}/artifacts/{name}",
                headers=headers,
                follow_redirects=True,
            ) as response:
                if response.status_code == 416:
                    # What is here is already the whole file, or not this file: start over.
                    partial.unlink(missing_ok=True)
                    tag_file.unlink(missing_ok=True)
                    raise httpx.ReadError("range not satisfiable; starting over")
                if response.status_code >= 400:
                    response.read()
                    return response
                mode = "ab" if response.status_code == 206 else "wb"
                if "etag" in response.headers:
                    tag_file.write_text(response.headers["etag"])
                with partial.open(mode) as file:
                    for block in response.iter_bytes(1 << 20):
                        file.write(block)
                return response

        self._transport.call(Safety.REPEATABLE, attempt)
        partial.replace(target)
        tag_file.unlink(missing_ok=True)
        return target

    @_public
    def download_all(
        self,
        job: Union[str, Job],
        folder: PathLike,
        *,
        on_file: Optional[Callable[[Artifact], None]] = None,
    ) -> list[Path]:
        """Downloads every artifact of a job into `folder`, under their names (nested ones,
        such as ``captured/aolp/000.png``, in their folders); returns the files. `on_file` is
        called with each artifact before it is downloaded."""
        root = Path(folder)
        paths = []
        for artifact in self.artifacts(job):
            relative = PurePosixPath(artifact.name)
            if relative.is_absolute() or ".." in relative.parts or not relative.parts:
                raise PhygapError(
                    f"the service named an artifact outside the folder: {artifact.name!r}"
                )
            if on_file is not None:
                on_file(artifact)
            paths.append(
                self._download(artifact.job_id, artifact.name, root.joinpath(*relative.parts))
            )
        return paths

    @_public
    def relight(
        self,
        job: Union[str, Job],
        envmap: PathLike,
        rotate_deg: float = 0.0,
        cameras: Optional[PathLike] = None,
        webhook: Optional[str] = None,
    ) -> Job:
        """Queues a relight of a trained job under an .exr or .hdr environment map (rotated by
        `rotate_deg` about the up axis; seen from `cameras`, a transforms.json, or the
        capture's test views); returns the new job. Sent again only when it certainly did not
        arrive."""
        envmap_path = Path(envmap)
        cameras_path = Path(cameras) if cameras is not None else None
        for path in (envmap_path, cameras_path):
            if path is not None and not path.is_file():
                raise BadInput(f"{path}: no such file")
        form = {"rotate_deg": str(rotate_deg)}
        if webhook:
            form["webhook"] = webhook

        def attempt() -> httpx.Response:
            with contextlib.ExitStack() as stack:
                files: dict[str, Any] = {
                    "envmap": (envmap_path.name, stack.enter_context(envmap_path.open("rb")))
                }
                if cameras_path is not None:
                    files["cameras"] = (
                        "cameras.json",
                        stack.enter_context(cameras_path.open("rb")),
                    )
                return self._transport.http.post(
                    f"/v1/jobs/{_id_of(job)}/relight", files=files, data=form
                )

        response = self._transport.call(Safety.UNSENT, attempt)
        return Job.from_json(response.json(), self)
