"""The ``phygap-client`` command (also ``python -m phygap_client``): upload a capture, train,
follow, download, from a shell.

    phygap-client submit CAPTURE [--config FILE|JSON] [--iterations N] [--wait] [--download DIR]
    phygap-client wait JOB [--download DIR]
    phygap-client download JOB DIR
    phygap-client cancel JOB
    phygap-client info

The service's address comes from ``--url`` or ``PHYGAP_URL``, its token from ``--token`` or
``PHYGAP_TOKEN``. Exits 0 on success, 1 when a job failed, 2 on a usage error, 3 when the
service refused or could not be reached.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any, Optional, Sequence

from . import __version__
from .client import Client
from .errors import BadInput, JobFailed, PhygapError
from .models import Job, ProgressEvent

__all__ = ["main"]


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="phygap-client", description="Client of the phygap reconstruction service."
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument("--url", help="the service (default: PHYGAP_URL or 127.0.0.1:8080)")
    parser.add_argument("--token", help="bearer token (default: PHYGAP_TOKEN)")
    parser.add_argument("--quiet", "-q", action="store_true", help="no progress output")
    commands = parser.add_subparsers(dest="command", required=True)

    submit = commands.add_parser("submit", help="upload a capture and queue a training job")
    submit.add_argument("capture", help="a capture folder, or a .zip or .tar archive of one")
    submit.add_argument("--config", help="training settings: a JSON file, or JSON text")
    submit.add_argument("--iterations", help="training steps (a number, or auto)")
    submit.add_argument("--wait", action="store_true", help="wait for the job to end")
    submit.add_argument(
        "--download", metavar="DIR", help="download every artifact (implies --wait)"
    )

    wait = commands.add_parser("wait", help="wait for a job to end")
    wait.add_argument("job")
    wait.add_argument("--download", metavar="DIR", help="download every artifact after")

    download = commands.add_parser("download", help="download every artifact of a job")
    download.add_argument("job")
    download.add_argument("folder")

    cancel = commands.add_parser("cancel", help="cancel a job")
    cancel.add_argument("job")

    commands.add_parser("info", help="what the service offers")
    return parser


def _config(args: argparse.Namespace) -> dict[str, Any]:
    config: dict[str, Any] = {}
    if args.config:
        text = args.config
        if not text.lstrip().startswith("{"):
            text = Path(text).read_text()
        loaded = json.loads(text)
        if not isinstance(loaded, dict):
            raise ValueError("--config must be a JSON object")
        config.update(loaded)
    if args.iterations:
        config["iterations"] = (
            int(args.iterations) if args.iterations.isdigit() else args.iterations
        )
    return config


def _follow(job: Job, quiet: bool) -> Job:
    def show(event: ProgressEvent) -> None:
        if event.type == "step":
            eta = event.data.get("eta_seconds")
            line = f"\rstep {event.data.get('iteration', '?')}"
            if isinstance(eta, (int, float)):
                line += f"  eta {eta:.0f} s"
            sys.stderr.write(line + "   ")
        else:
            sys.stderr.write(f"\n{event.type}\n" if event.type != "finished" else "\n")
        sys.stderr.flush()

    return job.wait(on_event=None if quiet else show)


def _download(job: Job, folder: str, quiet: bool) -> None:
    def show(artifact: Any) -> None:
        if not quiet:
            sys.stderr.write(f"{artifact.name}\n")

    files = job.download_all(folder, on_file=show)
    print(f"{len(files)} files in {folder}")


def run(args: argparse.Namespace) -> int:
    """Runs one parsed command; returns the exit status."""
    with Client(args.url, args.token) as phygap:
        if args.command == "info":
            print(json.dumps(phygap.info().raw, indent=2))
            return 0
        if args.command == "cancel":
            print(phygap.cancel(args.job).state)
            return 0
        if args.command == "download":
            _download(phygap.job(args.job), args.folder, args.quiet)
            return 0
        job: Optional[Job] = None
        if args.command == "submit":
            capture = phygap.upload(args.capture, progress=not args.quiet)
            job = capture.train(_config(args))
            print(job.id)
            if not (args.wait or args.download):
                return 0
        else:
            job = phygap.job(args.job)
        job = _follow(job, args.quiet)
        print(f"{job.id} {job.state}")
        if job.warning:
            print(f"warning: {job.warning}", file=sys.stderr)
        if args.download:
            _download(job, args.download, args.quiet)
        return 0


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command's entry point: parses `argv` (default: the process's), runs, returns the
    exit status."""
    args = _parser().parse_args(argv)
    try:
        return run(args)
    except JobFailed as error:
        print(f"phygap-client: {error}", file=sys.stderr)
        return 1
    except (BadInput, ValueError, OSError) as error:
        print(f"phygap-client: {error}", file=sys.stderr)
        return 2
    except PhygapError as error:
        print(f"phygap-client: {error}", file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        return 130
