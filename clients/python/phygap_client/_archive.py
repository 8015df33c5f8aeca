"""A capture folder as a tar archive, written to a temporary file a block at a time (never held
in memory), the same bytes for the same files, so that an upload of a folder can resume."""

from __future__ import annotations

import hashlib
import os
import stat
import tarfile
import tempfile
from pathlib import Path
from typing import BinaryIO, Iterator, Optional

#: Bytes read at a time from a file.
CHUNK = 1 << 20


def capture_files(folder: Path) -> list[tuple[str, Path]]:
    """The regular files under `folder` (links followed), by their names inside it, sorted."""
    found: list[tuple[str, Path]] = []
    for root, dirs, files in os.walk(folder, followlinks=True):
        dirs.sort()
        for name in sorted(files):
            path = Path(root) / name
            try:
                if not stat.S_ISREG(path.stat().st_mode):
                    continue
            except OSError:
                continue
            found.append((path.relative_to(folder).as_posix(), path))
    found.sort()
    return found


def write_tar(folder: Path, target: BinaryIO) -> None:
    """Writes the files under `folder` into `target` as a ustar archive (names relative to
    `folder`; owners, groups and modes left out, so the bytes depend on the files only)."""
    with tarfile.open(fileobj=target, mode="w", format=tarfile.USTAR_FORMAT) as archive:
        for name, path in capture_files(folder):
            info = tarfile.TarInfo(name)
            status = path.stat()
            info.size = status.st_size
            info.mtime = int(status.st_mtime)
            info.mode = 0o644
            with path.open("rb") as source:
                archive.addfile(info, source)


def folder_to_tar(folder: Path, scratch: Optional[Path] = None) -> Path:
    """The folder as a tar file in `scratch` (the system's temporary folder by default); the
    caller removes it."""
    handle, name = tempfile.mkstemp(prefix="phygap-", suffix=".tar", dir=scratch)
    try:
        with os.fdopen(handle, "wb") as target:
            write_tar(folder, target)
    except BaseException:
        os.unlink(name)
        raise
    return Path(name)


def chunks(path: Path, start: int = 0, length: Optional[int] = None) -> Iterator[bytes]:
    """`length` bytes of the file from `start` (to its end by default), a block at a time."""
    with path.open("rb") as file:
        file.seek(start)
        left = length
        while left is None or left > 0:
            block = file.read(CHUNK if left is None else min(CHUNK, left))
            if not block:
                break
            if left is not None:
                left -= len(block)
            yield block


def sha256_of(path: Path, start: int = 0, length: Optional[int] = None) -> bytes:
    """The SHA-256 of a range of the file, read a block at a time."""
    digest = hashlib.sha256()
    for block in chunks(path, start, length):
        digest.update(block)
    return digest.digest()
