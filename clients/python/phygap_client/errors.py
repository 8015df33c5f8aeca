"""The exceptions of the client: every public call raises a `PhygapError` or one of its
subclasses, never an error of the HTTP library or of the file system."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

if TYPE_CHECKING:
    from .models import Job

__all__ = [
    "PhygapError",
    "ConnectionError",
    "Timeout",
    "ServiceError",
    "JobFailed",
    "BadInput",
]


class PhygapError(Exception):
    """The base of every error the client raises."""


class ConnectionError(PhygapError):  # noqa: A001 - the client's own, as in requests
    """The service could not be reached, or the connection broke, and retrying did not help
    within the call's deadline."""


class Timeout(PhygapError):
    """A request, or a wait for a job, took longer than allowed."""


class ServiceError(PhygapError):
    """An error the service answered.

    Attributes:
        status: The HTTP status (e.g. 404, 422, 503).
        code: The service's stable name of the error (e.g. ``not_found``, ``invalid_config``).
        message: The service's explanation, for people.
        problems: For a refused capture, each problem found (``frame``, ``key``, ``message``).
    """

    def __init__(
        self,
        status: int,
        code: str,
        message: str,
        problems: Optional[list[dict[str, Any]]] = None,
    ) -> None:
        super().__init__(f"{status} {code}: {message}")
        self.status = status
        self.code = code
        self.message = message
        self.problems: list[dict[str, Any]] = problems or []


class JobFailed(PhygapError):
    """A job ended without succeeding (failed, or cancelled) while it was waited for.

    Attributes:
        job: The job as it ended.
        code: The service's ``error_code`` of the job (``cancelled`` for a cancelled job).
        message: The service's ``error`` of the job.
    """

    def __init__(self, job: Job) -> None:
        code = job.error_code or ("cancelled" if job.state == "cancelled" else "failed")
        message = job.error or f"job {job.id} {job.state}"
        super().__init__(f"job {job.id} {job.state}: {code}: {message}")
        self.job = job
        self.code = code
        self.message = message


class BadInput(PhygapError):
    """An argument the client cannot use: a missing file, a folder where a file is needed, a
    file that is not an archive, a malformed URL."""
