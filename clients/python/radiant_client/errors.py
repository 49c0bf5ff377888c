"""Exceptions raised by the Radiant client.

Every exception is a :class:`RadiantError`. Refused scenes carry the JSON pointer and message the
service (or, for files the scene names, the client) gives, the same ones ``radiant validate``
prints as ``FILE: /json/pointer: message``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List, Optional


class RadiantError(Exception):
    """The base of every error this package raises."""


class RadiantConnectionError(RadiantError, ConnectionError):
    """The service could not be reached, or the connection broke before a whole answer."""


class RadiantTimeout(RadiantError, TimeoutError):
    """A request, or :meth:`radiant_client.Job.wait`, ran out of time."""


@dataclass(frozen=True)
class Problem:
    """One problem of a refused scene: an RFC 6901 pointer into it ("" = the whole document)."""

    pointer: str
    message: str

    def __str__(self) -> str:
        return f"{self.pointer}: {self.message}"


class SceneError(RadiantError):
    """A scene was refused. ``pointer`` and ``message`` are its first problem's; ``problems``
    holds them all, in the order ``radiant validate`` lists them."""

    def __init__(self, problems: List[Problem], text: Optional[str] = None):
        self.problems: List[Problem] = list(problems) or [Problem("", "the scene was refused")]
        self.pointer: str = self.problems[0].pointer
        self.message: str = self.problems[0].message
        RadiantError.__init__(self, text or "; ".join(str(p) for p in self.problems))


class SceneFileError(SceneError):
    """A file that the scene names (``obj_file``, ``ies_file``...) or the scene file itself
    cannot be read. Raised by the client before anything is sent."""

    def __init__(self, pointer: str, message: str, path: Optional[str] = None):
        self.path = path
        super().__init__([Problem(pointer, message)])


class HTTPError(RadiantError):
    """The service answered with an error status.

    ``status`` is the HTTP status, ``code`` the service's error code (``invalid_scene``,
    ``queue_full``, ``not_found``...), ``message`` and ``pointer`` its explanation, and ``body``
    the parsed error document (or the raw text when it was not JSON).
    """

    def __init__(self, status: int, code: str, message: str, pointer: str = "",
                 body: Any = None, retry_after: Optional[float] = None):
        self.status = status
        self.code = code
        self.message = message
        self.pointer = pointer
        self.body = body
        #: Seconds the service asked to wait before retrying (``Retry-After``), if it said.
        self.retry_after = retry_after
        # Not super(): InvalidSceneError is also a SceneError, whose __init__ takes problems.
        RadiantError.__init__(
            self, f"HTTP {status} {code}: {message}" if code else f"HTTP {status}: {message}")


class BadRequestError(HTTPError):
    """400: the request was malformed (a bad query value, for instance)."""


class InvalidSceneError(BadRequestError, SceneError):
    """400 ``invalid_scene`` or ``invalid_json``: the service refused the scene.

    ``pointer``/``message`` are the first problem's; ``problems`` lists every one.
    """

    def __init__(self, status: int, code: str, problems: List[Problem], body: Any = None):
        SceneError.__init__(self, problems)
        HTTPError.__init__(self, status, code, self.message, self.pointer, body)
        self.args = (f"HTTP {status} {code}: " + "; ".join(str(p) for p in self.problems),)


class NotFoundError(HTTPError):
    """404: no such job, or no result yet (the job is queued, or ended before it had one)."""


class PayloadTooLargeError(HTTPError):
    """413: the scene is over the service's ``--max-body-bytes``."""


class QueueFullError(HTTPError):
    """429: the service's queue is full; ``retry_after`` says how many seconds to wait."""


class ServiceUnavailableError(HTTPError):
    """503: the service is shutting down (or not ready)."""


class ServerError(HTTPError):
    """Any other 5xx: the service failed."""


class JobFailedError(RadiantError):
    """The job ended ``failed``; ``job`` is its final status document, ``error`` its reason."""

    def __init__(self, job: dict):
        self.job = job
        self.error: str = str(job.get("error", "unknown error"))
        super().__init__(f"job {job.get('id', '?')} failed: {self.error}")


def error_from_response(status: int, body_text: str, retry_after: Optional[str]) -> HTTPError:
    """The exception for an error answer: ``status``, its body and its ``Retry-After`` header."""
    import json

    try:
        body: Any = json.loads(body_text)
    except ValueError:
        body = body_text
    error = body.get("error") if isinstance(body, dict) else None
    error = error if isinstance(error, dict) else {}
    code = str(error.get("code", ""))
    message = str(error.get("message", "") or (body_text.strip() if not error else ""))
    pointer = str(error.get("pointer", ""))
    seconds: Optional[float] = None
    if retry_after is not None:
        try:
            seconds = float(retry_after)
        except ValueError:
            seconds = None  # an HTTP date: rare, and the caller can read the body
    if status == 400 and code in ("invalid_scene", "invalid_json"):
        problems = [Problem(str(p.get("pointer", "")), str(p.get("message", "")))
                    for p in error.get("problems", []) if isinstance(p, dict)]
        return InvalidSceneError(status, code, problems or [Problem(pointer, message)], body)
    kinds = {400: BadRequestError, 404: NotFoundError, 413: PayloadTooLargeError,
             429: QueueFullError, 503: ServiceUnavailableError}
    kind = kinds.get(status, ServerError if status >= 500 else HTTPError)
    return kind(status, code, message, pointer, body, seconds)
