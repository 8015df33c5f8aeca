"""What the service answers, as typed objects: a `Capture`, an `Upload`, a `Job` and its
`Artifact`s, a `ProgressEvent`, the `ServiceInfo`. Each keeps the client it came from, so its
methods (`Job.wait`, `Capture.train`, …) call the service directly; ``raw`` holds the answer as
it came, fields this version does not know included."""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Mapping, Optional, Union

if TYPE_CHECKING:
    from .client import Client

__all__ = ["Artifact", "Capture", "Job", "ProgressEvent", "ServiceInfo", "Upload", "ENDED"]

#: The states a job ends in.
ENDED = ("succeeded", "failed", "cancelled")

PathLike = Union[str, "os.PathLike[str]"]

_FRACTION = re.compile(r"(\.\d{6})\d+")


def parse_time(value: Any) -> Optional[datetime]:
    """An RFC 3339 time of the service as an aware `datetime` (None stays None)."""
    if value is None:
        return None
    text = str(value).replace("Z", "+00:00").replace("z", "+00:00")
    text = _FRACTION.sub(r"\1", text)  # Python before 3.11 reads at most microseconds
    try:
        parsed = datetime.fromisoformat(text)
    except ValueError:
        return None
    return parsed if parsed.tzinfo else parsed.replace(tzinfo=timezone.utc)


def _opt_int(value: Any) -> Optional[int]:
    return None if value is None else int(value)


def _opt_float(value: Any) -> Optional[float]:
    return None if value is None else float(value)


def _opt_str(value: Any) -> Optional[str]:
    return None if value is None else str(value)


@dataclass
class ServiceInfo:
    """What a deployment offers (`GET /v1/info`)."""

    version: str
    engines: dict[str, Any]
    limits: dict[str, Any]
    queue: dict[str, Any]
    workers: int
    account: Optional[dict[str, Any]]
    raw: dict[str, Any] = field(repr=False)

    @classmethod
    def from_json(cls, data: Mapping[str, Any]) -> ServiceInfo:
        """Reads the service's answer."""
        return cls(
            version=str(data.get("version", "")),
            engines=dict(data.get("engines") or {}),
            limits=dict(data.get("limits") or {}),
            queue=dict(data.get("queue") or {}),
            workers=int(data.get("workers") or 0),
            account=data.get("account"),
            raw=dict(data),
        )


@dataclass
class Capture:
    """An accepted capture: what a job trains on."""

    id: str
    views: int
    width: int
    height: int
    kinds: list[str]
    warnings: list[str]
    size_bytes: int
    created_at: Optional[datetime]
    raw: dict[str, Any] = field(repr=False)
    _client: Optional[Client] = field(default=None, repr=False, compare=False)

    @classmethod
    def from_json(cls, data: Mapping[str, Any], client: Optional[Client] = None) -> Capture:
        """Reads the service's answer."""
        return cls(
            id=str(data["id"]),
            views=int(data.get("views", 0)),
            width=int(data.get("width", 0)),
            height=int(data.get("height", 0)),
            kinds=[str(k) for k in data.get("kinds", [])],
            warnings=[str(w) for w in data.get("warnings", [])],
            size_bytes=int(data.get("size_bytes", 0)),
            created_at=parse_time(data.get("created_at")),
            raw=dict(data),
            _client=client,
        )

    def _service(self) -> Client:
        if self._client is None:
            raise RuntimeError("this Capture was made without a Client")
        return self._client

    def train(self, config: Optional[Mapping[str, Any]] = None, **options: Any) -> Job:
        """Queues a training job on this capture (`Client.train`'s options)."""
        return self._service().train(self.id, config, **options)

    def delete(self) -> None:
        """Removes the capture from the service."""
        self._service().delete_capture(self.id)


@dataclass
class Upload:
    """A resumable upload: its parts, which of them arrived, where it stands."""

    id: str
    state: str
    size: int
    part_size: int
    parts: int
    received: list[int]
    received_bytes: int
    sha256: Optional[str]
    capture_id: Optional[str]
    error: Optional[dict[str, Any]]
    created_at: Optional[datetime]
    expires_at: Optional[datetime]
    raw: dict[str, Any] = field(repr=False)
    _client: Optional[Client] = field(default=None, repr=False, compare=False)

    @classmethod
    def from_json(cls, data: Mapping[str, Any], client: Optional[Client] = None) -> Upload:
        """Reads the service's answer."""
        return cls(
            id=str(data["id"]),
            state=str(data.get("state", "")),
            size=int(data.get("size", 0)),
            part_size=int(data.get("part_size", 0)),
            parts=int(data.get("parts", 0)),
            received=[int(i) for i in data.get("received", [])],
            received_bytes=int(data.get("received_bytes", 0)),
            sha256=_opt_str(data.get("sha256")),
            capture_id=_opt_str(data.get("capture_id")),
            error=data.get("error"),
            created_at=parse_time(data.get("created_at")),
            expires_at=parse_time(data.get("expires_at")),
            raw=dict(data),
            _client=client,
        )

    def _service(self) -> Client:
        if self._client is None:
            raise RuntimeError("this Upload was made without a Client")
        return self._client

    @property
    def missing(self) -> list[int]:
        """The parts the service has not received yet."""
        have = set(self.received)
        return [index for index in range(self.parts) if index not in have]

    def refresh(self) -> Upload:
        """The upload as the service has it now."""
        return self._service().upload_status(self.id)

    def delete(self) -> None:
        """Abandons the upload: the service removes it with its parts."""
        self._service().delete_upload(self.id)


@dataclass
class ProgressEvent:
    """One recorded event of a job's runs: `type` is ``started``, ``step`` (with ``iteration``,
    ``loss``, ``eta_seconds`` … in `data`), ``evaluated``, ``checkpoint``, ``warning``,
    ``decided`` (a setting left to ``auto``: ``setting``, ``on``, ``evidence``) or ``finished``;
    `seq` numbers it in the job's history, across its runs."""

    seq: int
    type: str
    data: dict[str, Any]

    @classmethod
    def from_json(cls, entry: Mapping[str, Any]) -> ProgressEvent:
        """Reads one entry of a progress page (``{seq, event}``)."""
        event = dict(entry.get("event") or {})
        return cls(seq=int(entry.get("seq", 0)), type=str(event.get("type", "")), data=event)


@dataclass
class Artifact:
    """One file a job produced."""

    job_id: str
    name: str
    size: int
    content_type: str
    _client: Optional[Client] = field(default=None, repr=False, compare=False)

    def download(self, target: PathLike) -> Path:
        """Downloads it to `target` (a file path; parent folders are made)."""
        if self._client is None:
            raise RuntimeError("this Artifact was made without a Client")
        return self._client.download(self.job_id, self.name, target)


@dataclass
class Job:
    """A training or relight job and its progress, as the service last answered it.

    Methods act on the service and return what it answers; `refresh` and `wait` return the job
    anew (this object is left as it was)."""

    id: str
    kind: str
    capture_id: str
    state: str
    stage: Optional[str]
    iteration: int
    iterations: int
    losses: dict[str, float]
    test_psnr: Optional[float]
    eta_seconds: Optional[float]
    error: Optional[str]
    error_code: Optional[str]
    warning: Optional[str]
    created_at: Optional[datetime]
    started_at: Optional[datetime]
    finished_at: Optional[datetime]
    attempts: int
    resumed_from: Optional[int]
    backend: Optional[str]
    resolution: Optional[str]
    peak_rss_bytes: Optional[int]
    cancel_requested: bool
    priority: int
    max_runtime_seconds: Optional[int]
    parent_job_id: Optional[str]
    config: Optional[dict[str, Any]]
    webhook: Optional[dict[str, Any]]
    raw: dict[str, Any] = field(repr=False)
    _client: Optional[Client] = field(default=None, repr=False, compare=False)
    #: The number of the next progress event `wait` passes on (it resumes from there).
    next_event: int = field(default=0, repr=False, compare=False)

    @classmethod
    def from_json(cls, data: Mapping[str, Any], client: Optional[Client] = None) -> Job:
        """Reads the service's answer."""
        return cls(
            id=str(data["id"]),
            kind=str(data.get("kind", "train")),
            capture_id=str(data.get("capture_id", "")),
            state=str(data.get("state", "")),
            stage=_opt_str(data.get("stage")),
            iteration=int(data.get("iteration") or 0),
            iterations=int(data.get("iterations") or 0),
            losses={str(k): float(v) for k, v in (data.get("losses") or {}).items()},
            test_psnr=_opt_float(data.get("test_psnr")),
            eta_seconds=_opt_float(data.get("eta_seconds")),
            error=_opt_str(data.get("error")),
            error_code=_opt_str(data.get("error_code")),
            warning=_opt_str(data.get("warning")),
            created_at=parse_time(data.get("created_at")),
            started_at=parse_time(data.get("started_at")),
            finished_at=parse_time(data.get("finished_at")),
            attempts=int(data.get("attempts") or 0),
            resumed_from=_opt_int(data.get("resumed_from")),
            backend=_opt_str(data.get("backend")),
            resolution=_opt_str(data.get("resolution")),
            peak_rss_bytes=_opt_int(data.get("peak_rss_bytes")),
            cancel_requested=bool(data.get("cancel_requested", False)),
            priority=int(data.get("priority") or 0),
            max_runtime_seconds=_opt_int(data.get("max_runtime_seconds")),
            parent_job_id=_opt_str(data.get("parent_job_id")),
            config=data.get("config"),
            webhook=data.get("webhook"),
            raw=dict(data),
            _client=client,
        )

    def _service(self) -> Client:
        if self._client is None:
            raise RuntimeError("this Job was made without a Client")
        return self._client

    @property
    def ended(self) -> bool:
        """Whether the job is over (succeeded, failed or cancelled)."""
        return self.state in ENDED

    @property
    def succeeded(self) -> bool:
        """Whether the job ended well: its artifacts are there."""
        return self.state == "succeeded"

    def refresh(self) -> Job:
        """The job as the service has it now."""
        job = self._service().job(self.id)
        job.next_event = self.next_event
        return job

    def wait(
        self,
        on_event: Optional[Callable[[ProgressEvent], None]] = None,
        *,
        timeout: Optional[float] = None,
        poll_interval: float = 1.0,
        raise_on_failure: bool = True,
        from_event: Optional[int] = None,
    ) -> Job:
        """Waits for the job to end (`Client.wait`), passing on the progress events not seen by
        an earlier `wait` of this object; returns the job as it ended."""
        start = self.next_event if from_event is None else from_event
        job = self._service().wait(
            self.id,
            on_event,
            timeout=timeout,
            poll_interval=poll_interval,
            raise_on_failure=raise_on_failure,
            from_event=start,
            _progress=self,
        )
        return job

    def events(self, from_event: int = 0) -> list[ProgressEvent]:
        """The job's recorded progress events from number `from_event`."""
        events, _ = self._service().progress(self.id, from_event)
        return events

    def cancel(self) -> Job:
        """Asks the service to stop the job (it checkpoints first); returns the job."""
        return self._service().cancel(self.id)

    def restart(self, config: Optional[Mapping[str, Any]] = None) -> Job:
        """Runs a failed or cancelled job again: from its checkpoint, or over with the settings
        in `config` changed; returns the job, queued."""
        return self._service().restart(self.id, config)

    def delete(self) -> None:
        """Removes the job, its checkpoints and its artifacts from the service."""
        self._service().delete_job(self.id)

    def artifacts(self) -> list[Artifact]:
        """The job's files (empty until it has succeeded)."""
        return self._service().artifacts(self.id)

    def download(self, name: str, target: PathLike) -> Path:
        """Downloads the artifact `name` to the file `target`."""
        return self._service().download(self.id, name, target)

    def download_all(
        self, folder: PathLike, on_file: Optional[Callable[[Artifact], None]] = None
    ) -> list[Path]:
        """Downloads every artifact into `folder`, keeping their relative names
        (``renders/s0/000.png``); returns the files."""
        return self._service().download_all(self.id, folder, on_file=on_file)

    def relight(
        self,
        envmap: PathLike,
        rotate_deg: float = 0.0,
        cameras: Optional[PathLike] = None,
        webhook: Optional[str] = None,
    ) -> Job:
        """Queues a relight of this trained job under an .exr or .hdr environment map; returns
        the new job."""
        return self._service().relight(self.id, envmap, rotate_deg, cameras, webhook)
