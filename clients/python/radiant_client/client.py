"""The client of radiantd's JSON API (proto/openapi.yaml), on the standard library alone."""

from __future__ import annotations

import http.client
import json
import os
import socket
import time
from typing import (Any, Callable, Collection, Dict, Iterator, List, Mapping, Optional, Tuple,
                    Union)
from urllib.parse import quote, urlencode, urlsplit

from . import workplane
from .errors import (HTTPError, JobFailedError, RadiantConnectionError, RadiantError,
                     RadiantTimeout, ServiceUnavailableError, error_from_response)
from .events import Event, EventParser
from .scene_files import SceneSource, scene_body

__all__ = ["Client", "Job", "DEFAULT_URL"]

#: What ``Client()`` talks to without a URL: ``$RADIANT_SERVER``, as for the ``radiant`` CLI.
DEFAULT_URL = "http://127.0.0.1:8080"

ProgressCallback = Callable[[Dict[str, Any]], None]


def _default_url() -> str:
    return os.environ.get("RADIANT_SERVER") or DEFAULT_URL


def _default_token() -> Optional[str]:
    return os.environ.get("RADIANT_TOKEN") or None


class _Transport:
    """One HTTP/1.1 connection per request, as the CLI does: a job's calls are few, and a
    fresh connection never finds one the server closed while idle."""

    def __init__(self, url: str, timeout: float, token: Optional[str] = None):
        parts = urlsplit(url)
        if parts.scheme not in ("http", "https") or not parts.hostname:
            raise ValueError(f"expected http://HOST[:PORT][/PREFIX], got {url!r}")
        self.url = url.rstrip("/")
        self.timeout = timeout
        self._token = token
        self._https = parts.scheme == "https"
        self._host = parts.hostname
        self._port = parts.port
        self._prefix = parts.path.rstrip("/")

    def _connection(self, timeout: Optional[float]) -> http.client.HTTPConnection:
        kind = http.client.HTTPSConnection if self._https else http.client.HTTPConnection
        return kind(self._host, self._port, timeout=timeout)

    def _fail(self, e: BaseException) -> Exception:
        if isinstance(e, socket.timeout):
            return RadiantTimeout(f"{self.url}: timed out")
        why = getattr(e, "strerror", None) or str(e) or type(e).__name__
        return RadiantConnectionError(f"cannot talk to {self.url}: {why}")

    def open(self, method: str, path: str, body: Optional[bytes] = None,
             headers: Optional[Mapping[str, str]] = None, timeout: Optional[float] = None
             ) -> Tuple[http.client.HTTPConnection, http.client.HTTPResponse]:
        """Sends a request; returns the connection and the response with its body unread.
        Raises the :class:`HTTPError` of an error status (the body read then)."""
        all_headers = {"User-Agent": "radiant-python", **(headers or {})}
        if self._token:
            all_headers["Authorization"] = f"Bearer {self._token}"
        if body is not None:
            all_headers.setdefault("Content-Type", "application/json")
        connection = self._connection(self.timeout if timeout is None else timeout)
        try:
            connection.request(method, self._prefix + path, body=body, headers=all_headers)
            response = connection.getresponse()
            if response.status >= 400:
                text = response.read().decode("utf-8", "replace")
                raise error_from_response(response.status, text, response.getheader("Retry-After"))
            return connection, response
        except HTTPError:
            connection.close()
            raise
        except (OSError, http.client.HTTPException) as e:
            connection.close()
            raise self._fail(e) from e

    def call(self, method: str, path: str, body: Optional[bytes] = None,
             headers: Optional[Mapping[str, str]] = None) -> Tuple[int, bytes]:
        """One whole request: the status and body of a success, else the error raised."""
        connection, response = self.open(method, path, body, headers)
        try:
            return response.status, response.read()
        except (OSError, http.client.HTTPException) as e:
            raise self._fail(e) from e
        finally:
            connection.close()

    def json(self, method: str, path: str, body: Optional[bytes] = None,
             headers: Optional[Mapping[str, str]] = None) -> Any:
        _, data = self.call(method, path, body, headers)
        try:
            return json.loads(data)
        except ValueError as e:
            raise RadiantConnectionError(f"{self.url}{path}: the answer is not JSON: {e}") from e


class Client:
    """A radiantd service.

    >>> client = Client("http://127.0.0.1:8080")        # doctest: +SKIP
    >>> job = client.submit("proto/examples/simple-room.json")  # doctest: +SKIP
    >>> job.wait(progress=lambda p: print(p["fraction"]))  # doctest: +SKIP

    ``url`` defaults to ``$RADIANT_SERVER``, else ``http://127.0.0.1:8080``; ``timeout`` is each
    request's socket timeout in seconds; ``token`` (default ``$RADIANT_TOKEN``) is sent as
    ``Authorization: Bearer`` to a service started with ``--token-file``. A client holds no
    connection and may be shared by threads.
    """

    def __init__(self, url: Optional[str] = None, timeout: float = 30.0,
                 token: Optional[str] = None):
        self._transport = _Transport(url or _default_url(), timeout, token or _default_token())

    @property
    def url(self) -> str:
        """The service's base URL."""
        return self._transport.url

    @property
    def timeout(self) -> float:
        """Each request's socket timeout, in seconds."""
        return self._transport.timeout

    def __repr__(self) -> str:
        return f"Client({self.url!r})"

    def health(self) -> Dict[str, Any]:
        """``GET /healthz``: ``{"status": "ok", "store": "writable"}`` while the daemon is alive
        (``"store": "unwritable"`` and ``store_reason`` after its store refused a write;
        ``/readyz`` asks the store now); raises :class:`RadiantConnectionError` when it cannot be
        reached."""
        return self._transport.json("GET", "/healthz")

    def metrics(self) -> str:
        """``GET /metrics``: the Prometheus text (jobs by state, queue length, solve seconds)."""
        return self._transport.call("GET", "/metrics")[1].decode("utf-8")

    def submit(self, scene_or_path: SceneSource, settings: Optional[Mapping[str, Any]] = None,
               *, base_dir: Union[str, "os.PathLike[str]", None] = None,
               idempotency_key: Optional[str] = None, queue_wait: float = 0.0) -> "Job":
        """Submits a scene; returns its :class:`Job` once the service accepted it (202).

        ``scene_or_path`` is a scene dict or the path of a scene JSON file. Every file it names
        (``obj_file``, ``gltf_file``, ``ies_file``, ``ldt_file``) is read and inlined first,
        relative to the scene file's directory (for a dict: ``base_dir``, default the current
        directory). ``settings`` (``tolerance``, ``max_seconds``, ``method``) override the
        scene's own. ``idempotency_key`` makes a retried submission return the first one's job.
        When the queue is full (429) and ``queue_wait`` > 0, the submission is retried after the
        service's ``Retry-After`` for up to ``queue_wait`` seconds.

        Raises :class:`SceneFileError` for a file that cannot be read, :class:`InvalidSceneError`
        (``pointer``, ``message``, ``problems``) for a scene the service refuses,
        :class:`PayloadTooLargeError`, :class:`QueueFullError` (``retry_after``) and
        :class:`ServiceUnavailableError`.
        """
        scene, body = scene_body(scene_or_path, settings, base_dir)
        headers = {"Idempotency-Key": idempotency_key} if idempotency_key else {}
        deadline = time.monotonic() + queue_wait
        while True:
            try:
                accepted = self._transport.json("POST", "/v1/jobs", body, headers)
                return Job(self, str(accepted["id"]), scene)
            except HTTPError as e:
                remaining = deadline - time.monotonic()
                if e.status != 429 or remaining <= 0:
                    raise
                time.sleep(min(remaining, e.retry_after if e.retry_after else 1.0))

    def job(self, job_id: str) -> "Job":
        """The :class:`Job` of a known id (no request is made)."""
        return Job(self, job_id)

    def jobs(self, limit: Optional[int] = None) -> List[Dict[str, Any]]:
        """``GET /v1/jobs``: the jobs' status documents, newest first, following the pages;
        at most ``limit`` of them (all when None)."""
        out: List[Dict[str, Any]] = []
        after: Optional[str] = None
        while limit is None or len(out) < limit:
            page_size = 1000 if limit is None else min(1000, limit - len(out))
            query: Dict[str, Any] = {"limit": page_size}
            if after:
                query["after"] = after
            page = self._transport.json("GET", "/v1/jobs?" + urlencode(query))
            out.extend(page.get("jobs", []))
            after = page.get("next")
            if not after:
                break
        return out

    # Used by Job.
    def _path(self, job_id: str, tail: str = "") -> str:
        return "/v1/jobs/" + quote(job_id, safe="") + tail


class Job:
    """A job of the service: ``id``, and ``scene`` (the inlined scene as sent, when this client
    submitted it; :meth:`rows` of a scene ``grid`` set needs it)."""

    def __init__(self, client: Client, job_id: str, scene: Optional[Dict[str, Any]] = None):
        self.client = client
        self.id = job_id
        self.scene = scene

    def __repr__(self) -> str:
        return f"Job({self.id!r})"

    @property
    def _transport(self) -> _Transport:
        return self.client._transport

    def status(self) -> Dict[str, Any]:
        """``GET /v1/jobs/{id}``: ``status`` (queued, running, done, failed, cancelled),
        ``progress``, ``created``, ``started``, ``finished`` and, when failed, ``error``."""
        return self._transport.json("GET", self.client._path(self.id))

    def result(self, include_mesh: bool = False) -> Dict[str, Any]:
        """``GET /v1/jobs/{id}/result``: the ``radiant-result/1`` document; while the job runs,
        its latest state (``"status": "running"``). ``include_mesh`` adds the solved mesh.
        Raises :class:`NotFoundError` while the job is queued."""
        query = "?include=mesh" if include_mesh else ""
        return self._transport.json("GET", self.client._path(self.id, "/result" + query))

    def result_glb(self) -> bytes:
        """``GET /v1/jobs/{id}/result.glb``: the solved mesh and sensors as binary glTF 2.0."""
        return self._transport.call("GET", self.client._path(self.id, "/result.glb"))[1]

    def sensors_csv(self) -> str:
        """``GET /v1/jobs/{id}/sensors.csv``: every sensor point as CSV (``set, index, x, y, z,
        nx, ny, nz, lux``; metres and lux), as ``radiant solve --csv`` writes it."""
        return self._transport.call("GET", self.client._path(self.id, "/sensors.csv"))[1].decode()

    def plan_png(self, sensors: Optional[str] = None, size: Optional[int] = None,
                 max_lux: Optional[float] = None) -> bytes:
        """``GET /v1/jobs/{id}/plan.png``: a sensor set's false-colour map (default: the first
        set), drawn from the finished job's result without solving again."""
        return self._picture("/plan.png", sensors=sensors, size=size, max_lux=max_lux)

    def view_png(self, eye: Optional[Tuple[float, float, float]] = None,
                 target: Optional[Tuple[float, float, float]] = None,
                 up: Optional[Tuple[float, float, float]] = None, fov: Optional[float] = None,
                 width: Optional[int] = None, height: Optional[int] = None,
                 falsecolor: bool = False, max_lux: Optional[float] = None,
                 exposure: Optional[float] = None) -> bytes:
        """``GET /v1/jobs/{id}/view.png``: a perspective picture of the solved room, luminance or
        (``falsecolor``) lux; ``eye``, ``target`` and ``up`` in metres. No solve."""
        def xyz(v: Optional[Tuple[float, float, float]]) -> Optional[str]:
            return None if v is None else ",".join(repr(float(c)) for c in v)
        return self._picture("/view.png", eye=xyz(eye), target=xyz(target), up=xyz(up),
                             fov=fov, width=width, height=height,
                             falsecolor="1" if falsecolor else None, max_lux=max_lux,
                             exposure=exposure)

    def _picture(self, tail: str, **query: Any) -> bytes:
        given = {k: v for k, v in query.items() if v is not None}
        suffix = "?" + urlencode(given) if given else ""
        return self._transport.call("GET", self.client._path(self.id, tail + suffix))[1]

    def cancel(self) -> Dict[str, Any]:
        """``DELETE /v1/jobs/{id}``: cancels the job; returns its status document (a running
        solve stops within about a second; its best result so far stays readable)."""
        return self._transport.json("DELETE", self.client._path(self.id))

    def events(self, last_event_id: Optional[int] = None,
               kinds: Optional[Collection[str]] = None, *, reconnect: bool = True,
               max_retries: int = 5, timeout: Optional[float] = None) -> Iterator[Event]:
        """The job's server-sent events (``progress``, ``mesh``, ``radiosity``, ``done``),
        ending after ``done``.

        ``last_event_id`` resumes after that event id. A stream that breaks before ``done`` (a
        dropped connection, a daemon restart) is reopened with ``Last-Event-ID``, so no event
        is lost or repeated, up to ``max_retries`` times in a row with a growing pause; then
        :class:`RadiantConnectionError`. ``kinds`` keeps only those kinds (the others' data is
        not even parsed). ``timeout`` bounds the whole stream (:class:`RadiantTimeout`).
        """
        deadline = None if timeout is None else time.monotonic() + timeout
        wanted = None if kinds is None else frozenset(kinds)
        last = last_event_id
        failures = 0
        while True:
            read_timeout = self.client.timeout
            if deadline is not None:
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    raise RadiantTimeout(f"job {self.id}: no done event within {timeout} s")
                read_timeout = min(read_timeout, remaining)
            headers = {"Accept": "text/event-stream"}
            if last is not None:
                headers["Last-Event-ID"] = str(last)
            parser = EventParser(lambda kind: wanted is None or kind in wanted)
            broke: Optional[BaseException] = None
            try:
                connection, response = self._transport.open(
                    "GET", self.client._path(self.id, "/events"), None, headers, read_timeout)
            except (RadiantConnectionError, RadiantTimeout, ServiceUnavailableError) as e:
                broke, connection = e, None
            if connection is not None:
                try:
                    while True:
                        raw = response.readline()
                        if not raw:
                            break  # the server closed the stream
                        event = parser.feed(raw.decode("utf-8", "replace").rstrip("\r\n"))
                        if parser.last_event_id is not None:
                            last = parser.last_event_id
                        if event is None:
                            continue
                        failures = 0
                        if wanted is None or event.kind in wanted:
                            yield event
                        if event.kind == "done":
                            return
                        if deadline is not None and time.monotonic() > deadline:
                            raise RadiantTimeout(f"job {self.id}: no done event within {timeout} s")
                except RadiantError:
                    raise  # RadiantTimeout is an OSError too
                except (OSError, http.client.HTTPException) as e:
                    broke = e
                finally:
                    connection.close()
            if deadline is not None and time.monotonic() >= deadline:
                raise RadiantTimeout(f"job {self.id}: no done event within {timeout} s")
            if not reconnect or failures >= max_retries:
                why = f": {broke}" if broke else ""
                raise RadiantConnectionError(f"job {self.id}: the event stream ended before "
                                             f"done{why}") from broke
            time.sleep(min(4.0, 0.25 * 2 ** failures))
            failures += 1

    def wait(self, progress: Optional[ProgressCallback] = None,
             timeout: Optional[float] = None) -> Dict[str, Any]:
        """Follows the job until it ends; returns its final status document.

        ``progress`` is called with each ``progress`` event's data (``fraction``, ``stage``,
        ``iterations``, ``error_estimate``, ``elapsed_seconds``...). Raises
        :class:`JobFailedError` when the job failed, :class:`RadiantTimeout` after ``timeout``
        seconds. A cancelled job is returned, not raised.
        """
        for event in self.events(kinds=("progress", "done"), timeout=timeout):
            if event.kind == "progress" and progress is not None and isinstance(event.data, dict):
                progress(event.data)
        job = self.status()
        if job.get("status") == "failed":
            raise JobFailedError(job)
        return job

    def light_scene(self, name: str, dimming: Mapping[str, float]) -> Dict[str, Any]:
        """``POST /v1/jobs/{id}/scenes``: the light scene ``name`` with each group's ``dimming``
        (0–1; a group it does not name is off), from the finished job's stored solution without
        solving again. Returns ``{"name", "dimming", "error_estimate", "sensors", "observers"}``,
        each sensor set as in the result. Raises :class:`BadRequestError` (its ``pointer``) for an
        unknown group or a dimming outside [0, 1], :class:`HTTPError` 409 while the job runs or
        when its scene names no groups.
        """
        body = json.dumps({"name": name, "dimming": dict(dimming)}).encode("utf-8")
        return self._transport.json("POST", self.client._path(self.id, "/scenes"), body,
                                    {"Content-Type": "application/json"})

    def metrics(self, result: Optional[Mapping[str, Any]] = None) -> List[workplane.SensorMetrics]:
        """Each sensor set's E_avg, E_min, E_max, U0 (of ``result``, default :meth:`result`)."""
        return workplane.sensor_metrics(self.result() if result is None else result)

    def rows(self, name: str, result: Optional[Mapping[str, Any]] = None) -> workplane.Rows:
        """Grid sensor set ``name`` as rows of lux (see :func:`radiant_client.sensor_rows`)."""
        return workplane.sensor_rows(self.result() if result is None else result, name, self.scene)

    def table(self, result: Optional[Mapping[str, Any]] = None) -> str:
        """The metrics and every grid's rows as text (see :func:`radiant_client.format_table`)."""
        return workplane.format_table(self.result() if result is None else result, self.scene)
