"""The Python client against a running service: `python3 test_client.py BASE_URL CAPTURE
ENVMAP` (api/tests/python_client.rs starts the service and runs this). Exits non-zero on the
first failed check."""

import hashlib
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from phygap_client import Client, PhygapError  # noqa: E402


def main(base_url: str, capture: str, envmap: str) -> None:
    with Client(base_url) as phygap, tempfile.TemporaryDirectory() as scratch:
        info = phygap.info()
        assert info["limits"]["max_views"] > 0, info
        assert "cpu" in info["engines"]["backends"], info

        # In resumable parts: an upload interrupted after two parts sends only the rest.
        class Interrupted(Exception):
            pass

        first: list[int] = []

        def interrupt_after_two(index: int, count: int) -> None:
            first.append(index)
            if len(first) == 2:
                raise Interrupted()

        try:
            phygap.upload(capture, part_bytes=64 << 10, on_part=interrupt_after_two)
        except Interrupted:
            pass
        else:
            raise AssertionError("the upload was not interrupted")
        assert Path(capture + ".phygap-upload").exists()
        second: list[tuple[int, int]] = []
        uploaded = phygap.upload(capture, part_bytes=64 << 10,
                                 on_part=lambda index, count: second.append((index, count)))
        count = second[0][1]
        assert count > 2 and sorted(first + [i for i, _ in second]) == list(range(count)), (
            first, second)
        assert not Path(capture + ".phygap-upload").exists()
        assert uploaded["views"] == 10, uploaded
        config = {"iterations": 20, "checkpoint_interval": 10, "eval_interval": 10,
                  "initial_surfels": 100, "max_surfels": 1000, "gridmap": False}
        job = phygap.train(uploaded["id"], config=config, idempotency_key="client-test-1",
                           max_runtime_seconds=600)
        again = phygap.train(uploaded["id"], config=config, idempotency_key="client-test-1",
                             max_runtime_seconds=600)
        assert again["id"] == job["id"], (job, again)
        assert (job["priority"], job["max_runtime_seconds"]) == (0, 600), job

        events = []
        done = phygap.wait(job["id"], on_event=events.append, poll_seconds=0.2,
                           timeout_seconds=240)
        assert done["state"] == "succeeded", done
        kinds = [event["type"] for event in events]
        assert kinds[0] == "started" and kinds[-1] == "finished", kinds
        assert "step" in kinds, kinds

        names = {a["name"]: a["size"] for a in phygap.artifacts(job["id"])}
        glb = Path(scratch) / "model.glb"
        phygap.download(job["id"], "model.glb", glb)
        assert glb.stat().st_size == names["model.glb"], (glb.stat().st_size, names)
        whole = glb.read_bytes()
        # A download cut short resumes from where it stopped, the same file guarded by its tag.
        part = glb.with_name("model.glb.part")
        part.write_bytes(whole[:1000])
        glb.with_name("model.glb.etag").write_text(
            phygap._http.get(f"/v1/jobs/{job['id']}/artifacts/model.glb").headers["etag"])
        glb.unlink()
        phygap.download(job["id"], "model.glb", glb)
        assert hashlib.sha256(glb.read_bytes()).digest() == hashlib.sha256(whole).digest()

        relit = phygap.relight(job["id"], envmap, rotate_deg=45)
        relit = phygap.wait(relit["id"], poll_seconds=0.2, timeout_seconds=240)
        assert relit["state"] == "succeeded", relit
        assert any(a["name"].endswith(".png") for a in phygap.artifacts(relit["id"]))

        for call, code in [
            (lambda: phygap.restart(job["id"]), "job_not_restartable"),
            (lambda: phygap.job("job_missing"), "not_found"),
        ]:
            try:
                call()
            except PhygapError as error:
                assert error.code == code, error
            else:
                raise AssertionError(f"expected {code}")
        garbage = Path(scratch) / "garbage.zip"
        garbage.write_bytes(b"not an archive at all")
        try:
            phygap.upload(garbage)
        except PhygapError as error:
            assert error.status == 415 and error.code == "unsupported_archive", error
        else:
            raise AssertionError("garbage was accepted")
    print("python client: every check passed")


if __name__ == "__main__":
    main(*sys.argv[1:4])
