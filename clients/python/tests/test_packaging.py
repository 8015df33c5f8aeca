"""The package as the ecosystem expects it: a version, type information, documentation on
every public name, a command (``phygap-client``, ``python -m phygap_client``)."""

from __future__ import annotations

import inspect
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import phygap_client
from conftest import CLIENT_ROOT, QUICK, TOKEN, Server


def test_version_and_type_information() -> None:
    pyproject = (CLIENT_ROOT / "pyproject.toml").read_text()
    version = re.search(r'^version = "([^"]+)"', pyproject, re.M)
    assert version and phygap_client.__version__ == version.group(1)
    assert (CLIENT_ROOT / "phygap_client" / "py.typed").exists()
    assert 'readme = "README.md"' in pyproject and (CLIENT_ROOT / "README.md").exists()


def test_every_public_name_has_a_docstring() -> None:
    missing = []
    for name in phygap_client.__all__:
        item = getattr(phygap_client, name)
        if not (inspect.isclass(item) or inspect.isfunction(item)):
            continue
        if not inspect.getdoc(item):
            missing.append(name)
        if inspect.isclass(item):
            for member, value in vars(item).items():
                if member.startswith("_"):
                    continue
                if isinstance(value, property):
                    value = value.fget
                if isinstance(value, classmethod):
                    value = value.__func__
                if inspect.isfunction(value) and not inspect.getdoc(value):
                    missing.append(f"{name}.{member}")
    assert missing == []


def run_command(server: Server, *args: str) -> subprocess.CompletedProcess[str]:
    environment = dict(
        os.environ,
        PHYGAP_URL=server.url,
        PHYGAP_TOKEN=TOKEN,
        PYTHONPATH=str(CLIENT_ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""),
    )
    return subprocess.run(
        [sys.executable, "-m", "phygap_client", *args],
        env=environment,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_submit_waits_and_downloads(server: Server, capture_dir: Path, tmp_path: Path) -> None:
    import json

    config = tmp_path / "config.json"
    config.write_text(json.dumps(QUICK))
    result = run_command(
        server,
        "submit",
        str(capture_dir),
        "--config",
        str(config),
        "--wait",
        "--download",
        str(tmp_path / "out"),
    )
    assert result.returncode == 0, result.stderr
    assert "succeeded" in result.stdout
    assert (tmp_path / "out" / "metrics.json").exists()
    assert (tmp_path / "out" / "captured" / "s0" / "000.png").exists()


def test_command_errors_exit_non_zero(server: Server, tmp_path: Path) -> None:
    result = run_command(server, "wait", "job_missing")
    assert result.returncode == 3 and "not_found" in result.stderr
    result = run_command(server, "submit", str(tmp_path / "missing"))
    assert result.returncode == 2 and "missing" in result.stderr


def test_console_script() -> None:
    script = shutil.which("phygap-client")
    if script is None:
        if os.environ.get("CI") == "true":
            pytest.fail("phygap-client is not installed (pip install ./clients/python)")
        pytest.skip("phygap-client is not installed (pip install ./clients/python)")
    result = subprocess.run([script, "--version"], capture_output=True, text=True)
    assert result.returncode == 0 and "phygap-client" in result.stdout
