"""HTTP under the client: one place where requests are sent, retried and turned into the
client's exceptions."""

from __future__ import annotations

import email.utils
import enum
import random
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Optional, TypeVar

import httpx

from .errors import BadInput, ConnectionError, PhygapError, ServiceError, Timeout

T = TypeVar("T")


@dataclass(frozen=True)
class RetryPolicy:
    """How the client retries a request the service could not take.

    A request is tried again after a connection error, or an answer in `statuses` (429 Too Many
    Requests and 503 Service Unavailable by default, and the 502 and 504 of a proxy whose service
    is restarting), waiting `initial`, then twice as long each time up to `maximum` seconds,
    each wait drawn at random below that bound ("full jitter"), or what the answer's
    ``Retry-After`` asks for. It gives up once `deadline` seconds have passed since the call
    began (a last try is made at the deadline; a Retry-After that ends past it is not waited
    for). ``RetryPolicy(deadline=0)`` never
    retries.
    """

    deadline: float = 120.0
    initial: float = 0.25
    maximum: float = 8.0
    statuses: frozenset[int] = field(default_factory=lambda: frozenset({429, 502, 503, 504}))

    def backoff(self, attempt: int) -> float:
        """The wait before retry number `attempt` (from 0) when the service named none."""
        return random.uniform(0.0, min(self.maximum, self.initial * 2.0**attempt))


class Safety(enum.Enum):
    """Which failures a request may be retried after."""

    #: Repeating it is harmless (GET, PUT of a part, commit, a submit with an Idempotency-Key):
    #: retried after any connection error, even one that cut the answer off.
    REPEATABLE = "repeatable"
    #: It may have taken effect once it reached the service: retried only when it certainly did
    #: not (the connection was refused or never opened, or the service answered 429 or 503).
    UNSENT = "unsent"


def retry_after(response: httpx.Response) -> Optional[float]:
    """The seconds a ``Retry-After`` header asks for (a number or an HTTP date), if any."""
    value = response.headers.get("retry-after")
    if value is None:
        return None
    value = value.strip()
    try:
        return max(0.0, float(value))
    except ValueError:
        pass
    try:
        when = email.utils.parsedate_to_datetime(value)
    except (TypeError, ValueError):
        return None
    return max(0.0, when.timestamp() - time.time())


def service_error(response: httpx.Response) -> ServiceError:
    """The service's ``{error: {code, message, problems?}}`` answer as an exception."""
    try:
        response.read()
        error = response.json()["error"]
        return ServiceError(
            response.status_code, str(error["code"]), str(error["message"]), error.get("problems")
        )
    except Exception:  # noqa: BLE001 - not the service's JSON shape (a proxy's page, say)
        text = ""
        try:
            text = response.text[:500]
        except Exception:  # noqa: BLE001
            pass
        return ServiceError(response.status_code, "http_error", text or response.reason_phrase)


def _never_sent(error: httpx.TransportError) -> bool:
    """Whether the request certainly did not reach the service."""
    return isinstance(error, (httpx.ConnectError, httpx.ConnectTimeout, httpx.PoolTimeout))


def translate(error: httpx.HTTPError) -> PhygapError:
    """An httpx error as the client's exception."""
    if isinstance(error, httpx.TimeoutException):
        return Timeout(f"timed out: {error}")
    if isinstance(error, (httpx.UnsupportedProtocol, httpx.InvalidURL)):
        return BadInput(f"bad URL: {error}")
    return ConnectionError(
        f"{type(error).__name__}: {error}" if str(error) else type(error).__name__
    )


class Transport:
    """An httpx client with the retry policy and the client's exceptions."""

    def __init__(self, http: httpx.Client, policy: RetryPolicy) -> None:
        self.http = http
        self.policy = policy

    def call(
        self,
        safety: Safety,
        attempt: Callable[[], httpx.Response],
        deadline: Optional[float] = None,
    ) -> httpx.Response:
        """Runs `attempt` (one request) until it answers below 400 or a status outside the
        policy's, retrying as `safety` allows until the policy's deadline (or `deadline`, a
        `time.monotonic()` instant, if earlier). Raises `ServiceError` for an answer of 400 or
        more, `ConnectionError` or `Timeout` when the service could not answer."""
        start = time.monotonic()
        end = start + self.policy.deadline
        if deadline is not None:
            end = min(end, deadline)
        tries = 0
        while True:
            failure: PhygapError
            wait: Optional[float] = None
            try:
                response = attempt()
            except httpx.TransportError as error:
                failure = translate(error)
                if isinstance(error, (httpx.UnsupportedProtocol, httpx.InvalidURL)):
                    raise failure from error
                if safety is Safety.UNSENT and not _never_sent(error):
                    raise failure from error
                cause: BaseException = error
            except httpx.HTTPError as error:
                raise translate(error) from error
            else:
                if response.status_code < 400:
                    return response
                failure = service_error(response)
                if response.status_code not in self.policy.statuses:
                    raise failure
                wait = retry_after(response)
                cause = failure
            now = time.monotonic()
            if wait is None:
                # A last try at the deadline rather than none past it.
                wait = min(self.policy.backoff(tries), end - now)
            tries += 1
            if now >= end or now + wait > end:
                raise failure from (cause if cause is not failure else None)
            time.sleep(wait)

    def request(
        self,
        safety: Safety,
        method: str,
        path: str,
        deadline: Optional[float] = None,
        **kwargs: Any,
    ) -> httpx.Response:
        """One request (its body, if any, must be bytes or made anew by `content_factory`)."""
        factory: Optional[Callable[[], Any]] = kwargs.pop("content_factory", None)

        def attempt() -> httpx.Response:
            if factory is not None:
                return self.http.request(method, path, content=factory(), **kwargs)
            return self.http.request(method, path, **kwargs)

        return self.call(safety, attempt, deadline)

    def json(
        self,
        safety: Safety,
        method: str,
        path: str,
        deadline: Optional[float] = None,
        **kwargs: Any,
    ) -> Any:
        """`request`'s answer parsed as JSON."""
        response = self.request(safety, method, path, deadline, **kwargs)
        try:
            return response.json()
        except ValueError as error:
            raise ServiceError(
                response.status_code, "invalid_answer", f"not JSON: {response.text[:200]}"
            ) from error


def guarded(call: Callable[[], T]) -> T:
    """`call()` with any stray httpx or OS error turned into the client's exceptions."""
    try:
        return call()
    except PhygapError:
        raise
    except httpx.HTTPError as error:
        raise translate(error) from error
    except (FileNotFoundError, IsADirectoryError, NotADirectoryError, PermissionError) as error:
        raise BadInput(str(error)) from error
