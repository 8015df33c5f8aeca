"""The client against the real service: uploads (folders, archives, resumed), jobs as objects,
waiting, failures, downloads, relighting."""

from __future__ import annotations

import hashlib
import json
import tarfile
import zipfile
from pathlib import Path

import pytest

from conftest import QUICK, TOKEN, Server
from phygap_client import (
    BadInput,
    Capture,
    Client,
    Job,
    JobFailed,
    ProgressEvent,
    ServiceError,
    ServiceInfo,
)


def test_info_is_typed(phygap: Client) -> None:
    info = phygap.info()
    assert isinstance(info, ServiceInfo)
    assert info.version and info.limits["max_views"] > 0
    assert "cpu" in info.engines["backends"]


def test_a_wrong_token_is_a_service_error(server: Server) -> None:
    with Client(server.url, "not-the-token") as client:
        with pytest.raises(ServiceError) as raised:
            client.info()
    assert raised.value.status == 401


def test_a_folder_uploads_as_a_tar(phygap: Client, capture_dir: Path) -> None:
    reports: list[tuple[int, int]] = []
    capture = phygap.upload(capture_dir, progress=lambda done, total: reports.append((done, total)))
    assert isinstance(capture, Capture)
    assert capture.views == 10 and capture.width == 24 and "stokes" in capture.kinds
    assert reports and reports[-1][0] == reports[-1][1] == capture.size_bytes
    assert phygap.capture(capture.id) == capture


def test_archives_upload_zip_and_tar(phygap: Client, capture_dir: Path, tmp_path: Path) -> None:
    zipped = tmp_path / "capture.zip"
    with zipfile.ZipFile(zipped, "w") as archive:
        for file in sorted(capture_dir.rglob("*")):
            if file.is_file():
                archive.write(file, f"capture/{file.relative_to(capture_dir).as_posix()}")
    tarred = tmp_path / "capture.tar"
    with tarfile.open(tarred, "w") as archive:
        archive.add(capture_dir, arcname=".")
    for archive_path in (zipped, tarred):
        assert phygap.upload(archive_path).views == 10


def test_a_large_upload_resumes_where_it_stopped(phygap: Client, padded_capture_dir: Path) -> None:
    class Interrupted(Exception):
        pass

    first: list[int] = []

    def interrupt_after_two_parts(done: int, total: int) -> None:
        first.append(done)
        if len(first) == 3:  # the report before any part, then two parts
            raise Interrupted()

    with pytest.raises(Interrupted):
        phygap.upload(padded_capture_dir, part_size=64 << 10, progress=interrupt_after_two_parts)
    state = padded_capture_dir.with_name("capture.phygap-upload")
    assert state.exists()
    upload = phygap.upload_status(json.loads(state.read_text())["id"])
    assert len(upload.received) == 2 and upload.parts > 4
    second: list[int] = []
    capture = phygap.upload(
        padded_capture_dir, part_size=64 << 10, progress=lambda done, total: second.append(done)
    )
    assert second[0] == 2 * (64 << 10), "the second call began after the two parts sent"
    assert len(second) == upload.parts - 2 + 1
    assert not state.exists()
    assert capture.views == 10


def test_garbage_is_refused_by_the_service(phygap: Client, tmp_path: Path) -> None:
    garbage = tmp_path / "garbage.zip"
    garbage.write_bytes(b"not an archive at all")
    with pytest.raises(ServiceError) as raised:
        phygap.upload(garbage)
    assert raised.value.status == 415 and raised.value.code == "unsupported_archive"


def test_unknown_things_are_not_found(phygap: Client) -> None:
    for call in (lambda: phygap.job("job_missing"), lambda: phygap.capture("cap_missing")):
        with pytest.raises(ServiceError) as raised:
            call()
        assert raised.value.status == 404 and raised.value.code == "not_found"


def test_a_job_runs_and_reports_its_events(phygap: Client, capture_dir: Path) -> None:
    capture = phygap.upload(capture_dir)
    job = capture.train(QUICK, idempotency_key="client-test-events", max_runtime_seconds=600)
    again = phygap.train(
        capture.id, QUICK, idempotency_key="client-test-events", max_runtime_seconds=600
    )
    assert again.id == job.id
    assert (job.priority, job.max_runtime_seconds, job.kind) == (0, 600, "train")
    events: list[ProgressEvent] = []
    done = job.wait(events.append, timeout=300, poll_interval=0.2)
    assert done.succeeded and done.ended and done.iteration == 20
    kinds = [event.type for event in events]
    assert kinds[0] == "started" and kinds[-1] == "finished" and "step" in kinds, kinds
    seqs = [event.seq for event in events]
    assert seqs == list(range(len(seqs)))
    # The object goes on from the last event it passed on: nothing is replayed.
    more: list[ProgressEvent] = []
    assert job.wait(more.append, timeout=30).succeeded and more == []
    assert job.next_event == len(events)
    # Or from an event asked for.
    tail: list[ProgressEvent] = []
    job.wait(tail.append, from_event=len(events) - 2, timeout=30)
    assert [event.seq for event in tail] == seqs[-2:]


def test_download_all_keeps_the_folders(trained: Job, tmp_path: Path) -> None:
    artifacts = {artifact.name: artifact for artifact in trained.artifacts()}
    assert "captured/aolp/000.png" in artifacts and "metrics.json" in artifacts
    seen: list[str] = []
    files = trained.download_all(tmp_path / "result", on_file=lambda a: seen.append(a.name))
    assert sorted(seen) == sorted(artifacts)
    assert len(files) == len(artifacts)
    for name, artifact in artifacts.items():
        assert (tmp_path / "result" / name).stat().st_size == artifact.size, name
    assert not list((tmp_path / "result").rglob("*.part"))


def test_a_cut_download_resumes(trained: Job, tmp_path: Path) -> None:
    name = next(
        a.name for a in trained.artifacts() if a.name.endswith(".ply") or a.name == "surfels.ply"
    )
    target = tmp_path / "whole" / name
    trained.download(name, target)
    whole = target.read_bytes()
    # A download cut short resumes from where it stopped, the same file guarded by its tag.
    client = trained._client
    assert client is not None
    etag = client._transport.http.get(f"/v1/jobs/{trained.id}/artifacts/{name}").headers["etag"]
    cut = tmp_path / "cut" / name
    cut.parent.mkdir(parents=True)
    cut.with_name(cut.name + ".part").write_bytes(whole[:1000])
    cut.with_name(cut.name + ".etag").write_text(etag)
    trained.download(name, cut)
    assert hashlib.sha256(cut.read_bytes()).digest() == hashlib.sha256(whole).digest()
    # A part of another file (another tag) starts over.
    cut.with_name(cut.name + ".part").write_bytes(b"x" * 1000)
    cut.with_name(cut.name + ".etag").write_text('"another"')
    trained.download(name, cut)
    assert cut.read_bytes() == whole


def test_relight_under_the_jobs_own_light(trained: Job, tmp_path: Path) -> None:
    light = trained.download("envmap.hdr", tmp_path / "sky.hdr")
    relit = trained.relight(light, rotate_deg=45).wait(timeout=300, poll_interval=0.2)
    assert relit.kind == "relight" and relit.parent_job_id == trained.id
    assert any(artifact.name.endswith(".png") for artifact in relit.artifacts())


def test_a_failed_job_raises_job_failed(phygap: Client, capture_dir: Path) -> None:
    capture = phygap.upload(capture_dir)
    # Far more steps than a second allows: the job checkpoints and fails time_limit.
    job = capture.train(dict(QUICK, iterations=100_000), max_runtime_seconds=1)
    with pytest.raises(JobFailed) as raised:
        job.wait(timeout=120, poll_interval=0.2)
    assert raised.value.code == "time_limit" and raised.value.job.state == "failed"
    assert raised.value.message and raised.value.job.error == raised.value.message
    ended = job.wait(raise_on_failure=False, timeout=30)
    assert ended.state == "failed" and ended.error_code == "time_limit"
    # A restart with changed settings runs over (under the same one-second limit).
    restarted = ended.restart({"iterations": 20})
    assert restarted.state == "queued" and restarted.iterations == 20
    again = restarted.wait(timeout=300, poll_interval=0.2, raise_on_failure=False)
    assert again.ended and again.config is not None and again.config["iterations"] == 20


def test_cancel_then_wait_raises(phygap: Client, capture_dir: Path) -> None:
    capture = phygap.upload(capture_dir)
    job = capture.train(dict(QUICK, iterations=100_000))
    job.cancel()
    with pytest.raises(JobFailed) as raised:
        job.wait(timeout=120, poll_interval=0.2)
    assert raised.value.job.state == "cancelled"
    with pytest.raises(ServiceError) as again:
        job.cancel()
    assert again.value.code == "job_finished"
    job.delete()
    with pytest.raises(ServiceError):
        job.refresh()


def test_a_wait_times_out(phygap: Client, capture_dir: Path) -> None:
    from phygap_client import Timeout

    capture = phygap.upload(capture_dir)
    job = capture.train(dict(QUICK, iterations=100_000))
    try:
        with pytest.raises(Timeout):
            job.wait(timeout=1, poll_interval=0.2)
    finally:
        job.cancel()
        job.wait(raise_on_failure=False, timeout=120)


def test_relight_of_a_missing_map_is_bad_input(trained: Job, tmp_path: Path) -> None:
    with pytest.raises(BadInput):
        trained.relight(tmp_path / "nothing.exr")


def test_negative_iterations_name_the_field_and_its_range(
    phygap: Client, capture_dir: Path
) -> None:
    capture = phygap.upload(capture_dir)
    with pytest.raises(ServiceError) as raised:
        capture.train({"iterations": -5})
    assert raised.value.status == 422
    assert (
        "iterations" in raised.value.message and "1..=1000000" in raised.value.message
    ), raised.value.message


def test_token_travels_from_the_environment(
    server: Server, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("PHYGAP_TOKEN", TOKEN)
    monkeypatch.setenv("PHYGAP_URL", server.url)
    with Client() as client:
        assert client.info().version


def test_a_job_without_a_surface_succeeds_without_the_mesh(
    phygap: Client, full_size_capture_dir: Path, tmp_path: Path
) -> None:
    capture = phygap.upload(full_size_capture_dir)
    # 100 random surfels after 20 steps leave no coherent depth to fuse.
    quick = {"iterations": 20, "gridmap": False, "initial_surfels": 100}
    job = capture.train(quick).wait(timeout=300, poll_interval=0.2)
    assert job.succeeded
    assert job.warning and "no zero crossing" in job.warning, job.warning
    names = {artifact.name for artifact in job.artifacts()}
    assert "mesh.ply" not in names and "model.glb" not in names
    assert {"envmap.exr", "surfels.ply", "metrics.json"} <= names
    assert any(name.startswith("renders/") for name in names)
    metrics = json.loads(job.download("metrics.json", tmp_path / "metrics.json").read_text())
    assert any("no zero crossing" in warning for warning in metrics["warnings"])
    assert any(event.type == "warning" for event in job.events())
    # Asked for as required, the mesh's absence fails the job.
    with pytest.raises(JobFailed) as raised:
        capture.train(dict(quick, require_mesh=True)).wait(timeout=300, poll_interval=0.2)
    assert raised.value.code == "export_failed"
    assert "no zero crossing" in raised.value.message
