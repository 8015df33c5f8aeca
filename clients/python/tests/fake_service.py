"""A scripted HTTP server on loopback for what the real service will not do on demand: answer
503 or 429 with Retry-After, drop a connection after reading a request, never answer."""

from __future__ import annotations

import json
import socket
import threading
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any, Callable, Iterator, Optional

#: What a script returns for a request: (status, headers, JSON body), or None to drop the
#: connection without answering.
Answer = Optional[tuple[int, dict[str, str], Any]]


@dataclass
class Seen:
    """A request the fake service received."""

    method: str
    path: str
    headers: dict[str, str]
    body: bytes


@dataclass
class FakeService:
    """Answers each request with `script(seen_so_far, request)`."""

    script: Callable[[list[Seen], Seen], Answer]
    seen: list[Seen] = field(default_factory=list)
    url: str = ""
    _server: Optional[ThreadingHTTPServer] = None

    def __enter__(self) -> FakeService:
        fake = self

        class Handler(BaseHTTPRequestHandler):
            protocol_version = "HTTP/1.1"

            def log_message(self, *_: Any) -> None:
                pass

            def _handle(self) -> None:
                length = int(self.headers.get("content-length") or 0)
                body = self.rfile.read(length) if length else b""
                request = Seen(
                    self.command,
                    self.path,
                    {k.lower(): v for k, v in self.headers.items()},
                    body,
                )
                answer = fake.script(list(fake.seen), request)
                fake.seen.append(request)
                if answer is None:
                    self.connection.shutdown(socket.SHUT_RDWR)
                    self.close_connection = True
                    return
                status, headers, payload = answer
                data = json.dumps(payload).encode()
                self.send_response(status)
                for name, value in headers.items():
                    self.send_header(name, value)
                self.send_header("content-type", "application/json")
                self.send_header("content-length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            do_GET = do_POST = do_PUT = do_DELETE = _handle

        self._server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self._server.daemon_threads = True
        self.url = f"http://127.0.0.1:{self._server.server_address[1]}"
        threading.Thread(target=self._server.serve_forever, daemon=True).start()
        return self

    def __exit__(self, *_: Any) -> None:
        assert self._server is not None
        self._server.shutdown()
        self._server.server_close()


def error(status: int, code: str, headers: Optional[dict[str, str]] = None) -> Answer:
    """The service's error shape."""
    return status, headers or {}, {"error": {"code": code, "message": f"{code} (fake)"}}


JOB = {
    "id": "job_fake",
    "kind": "train",
    "capture_id": "cap_fake",
    "state": "queued",
    "iteration": 0,
    "iterations": 20,
    "losses": {},
    "attempts": 0,
    "priority": 0,
    "created_at": "2026-01-02T03:04:05.123456789Z",
}


def silent_listener() -> Iterator[str]:
    """A loopback port that accepts connections and never answers (yields its URL)."""
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen(8)
    try:
        yield f"http://127.0.0.1:{listener.getsockname()[1]}"
    finally:
        listener.close()
