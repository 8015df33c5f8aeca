"""A client of the phygap reconstruction service (the REST API of ``phygap-api serve``).

    from phygap_client import Client

    with Client("http://127.0.0.1:8080") as phygap:
        capture = phygap.upload("capture/")              # a folder or a .zip/.tar archive
        job = capture.train({"iterations": 6000}).wait(on_event=print)
        job.download_all("result/")
        job.relight("studio.exr", rotate_deg=90).wait().download_all("relit/")

Every call raises only `PhygapError` and its subclasses; requests the service could not take
(a dropped connection, 429, 503) are retried with backoff within a deadline (`RetryPolicy`).
"""

from ._transport import RetryPolicy
from .client import DEFAULT_URL, PART_BYTES, Client, ProgressBar
from .errors import BadInput, ConnectionError, JobFailed, PhygapError, ServiceError, Timeout
from .models import ENDED, Artifact, Capture, Job, ProgressEvent, ServiceInfo, Upload

__version__ = "0.2.0"

__all__ = [
    "Artifact",
    "BadInput",
    "Capture",
    "Client",
    "ConnectionError",
    "DEFAULT_URL",
    "ENDED",
    "Job",
    "JobFailed",
    "PART_BYTES",
    "PhygapError",
    "ProgressBar",
    "ProgressEvent",
    "RetryPolicy",
    "ServiceError",
    "ServiceInfo",
    "Timeout",
    "Upload",
    "__version__",
]
