"""What the Python client's tests share: a real radiantd on a loopback port with a temporary
job store (as tests/support/daemon.h starts it for the C++ service tests), and small scenes."""

from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest
from pathlib import Path
from typing import Any, Dict, List, Optional

#: The checkout: clients/python/tests/ is three levels down.
SOURCE_DIR = Path(__file__).resolve().parents[3]
PACKAGE_DIR = SOURCE_DIR / "clients" / "python"
EXAMPLES = SOURCE_DIR / "proto" / "examples"
SIMPLE_ROOM = EXAMPLES / "simple-room.json"
FURNISHED_OFFICE = EXAMPLES / "furnished-office" / "furnished-office.json"


def radiantd_path() -> Path:
    """$RADIANTD (ctest sets it to build/bin/radiantd), else the checkout's build."""
    return Path(os.environ.get("RADIANTD") or SOURCE_DIR / "build" / "bin" / "radiantd")


def require_radiantd() -> Path:
    path = radiantd_path()
    if not path.is_file():
        if os.environ.get("RADIANTD"):
            raise AssertionError(f"RADIANTD={path} does not exist")
        raise unittest.SkipTest(f"{path} is not built")
    return path


def free_port() -> int:
    """A loopback port that was free a moment ago (for a daemon that must restart on it)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Daemon:
    """``radiantd --listen 127.0.0.1:PORT --data DIR ARGS``; PORT 0 lets it pick a free one.
    ``start()`` returns once it printed ``listening on``; ``kill()`` is ``kill -9``."""

    def __init__(self, *args: str, port: int = 0, data: Optional[Path] = None):
        self._tmp = tempfile.TemporaryDirectory(prefix="radiant_py_test_")
        self.dir = Path(self._tmp.name)
        self.data = data or self.dir / "data"
        self.args = list(args)
        self.requested_port = port
        self.port = 0
        self.process: Optional[subprocess.Popen] = None
        self.log = self.dir / "radiantd.log"

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    def start(self) -> "Daemon":
        out = self.dir / "stdout"
        with open(out, "wb") as stdout, open(self.log, "ab") as stderr:
            self.process = subprocess.Popen(
                [str(require_radiantd()), "--listen", f"127.0.0.1:{self.requested_port}",
                 "--data", str(self.data), *self.args], stdout=stdout, stderr=stderr)
        deadline = time.monotonic() + 15
        prefix = "listening on 127.0.0.1:"
        while time.monotonic() < deadline:
            text = out.read_text(errors="replace")
            if text.startswith(prefix) and "\n" in text:
                self.port = int(text[len(prefix):text.index("\n")])
                self.requested_port = self.port  # a restart comes back on the same port
                return self
            if self.process.poll() is not None:
                break
            time.sleep(0.02)
        self.stop()
        raise AssertionError(f"radiantd did not start: {out.read_text()} {self.log.read_text()}")

    def kill(self) -> None:
        """Ends radiantd at once, as a crash would (the job store stays)."""
        if self.process and self.process.poll() is None:
            self.process.send_signal(signal.SIGKILL)
            self.process.wait(10)

    def stop(self) -> None:
        self.kill()

    def close(self) -> None:
        self.stop()
        self._tmp.cleanup()

    def __enter__(self) -> "Daemon":
        return self.start()

    def __exit__(self, *exc: Any) -> None:
        self.close()


def tiny_room(settings: Optional[Dict[str, Any]] = None) -> Dict[str, Any]:
    """tests/support/service_scenes.h's tiny room: well under a second at tolerance 0.1."""
    return {
        "format": "radiant-scene/1", "name": "tiny-room",
        "materials": {"wall": {"reflectance": 0.5},
                      "lamp": {"reflectance": 0.5, "emission": {"flux": 1000}}},
        "surfaces": [
            {"name": "room", "material": "wall",
             "box": {"min": [0, 0, 0], "max": [1, 1, 1], "facing": "in"}},
            {"name": "panel", "material": "lamp",
             "polygon": [[0.25, 0.25, 0.99], [0.25, 0.75, 0.99], [0.75, 0.75, 0.99],
                         [0.75, 0.25, 0.99]]}],
        "sensors": [{"name": "floor", "points": [[0.5, 0.5, 0]], "normal": [0, 0, 1]}],
        "settings": settings or {"tolerance": 0.1},
    }


def slow_room(seconds: float = 20) -> Dict[str, Any]:
    """The tiny room meshed finely and solved hierarchically (the Monte Carlo default would
    finish it in a second): it runs until cancelled or for ``seconds``."""
    return tiny_room({"tolerance": 0.001, "max_seconds": seconds, "method": "hierarchical"})


def wait_for_status(job: Any, status: str, timeout: float = 20) -> Dict[str, Any]:
    deadline = time.monotonic() + timeout
    while True:
        doc = job.status()
        if doc["status"] == status or time.monotonic() > deadline:
            return doc
        time.sleep(0.05)


class CuttingProxy:
    """A loopback TCP proxy to ``port`` that cuts the first event stream it carries in the
    middle of an event, after ``events`` whole ones. ``requests`` keeps each request's head and
    ``cut_stream`` the answer bytes the cut connection carried."""

    def __init__(self, port: int, events: int = 2):
        self._target = port
        self._events = events
        self._server = socket.create_server(("127.0.0.1", 0))
        self.port = self._server.getsockname()[1]
        self.requests: List[str] = []
        self.cut_stream = b""
        self._cut_done = False
        self._lock = threading.Lock()
        threading.Thread(target=self._accept, daemon=True).start()

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    def close(self) -> None:
        self._server.close()

    def _accept(self) -> None:
        while True:
            try:
                client, _ = self._server.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(client,), daemon=True).start()

    def _serve(self, client: socket.socket) -> None:
        upstream = socket.create_connection(("127.0.0.1", self._target))
        with client, upstream:
            head = client.recv(65536)
            with self._lock:
                self.requests.append(head.decode("latin-1"))
                cut = b"/events" in head.split(b"\r\n", 1)[0] and not self._cut_done
                self._cut_done = self._cut_done or cut
            upstream.sendall(head)
            threading.Thread(target=self._pump, args=(client, upstream), daemon=True).start()
            carried = b""
            while True:
                try:
                    data = upstream.recv(65536)
                except OSError:
                    return
                if not data:
                    return
                if cut:
                    full = carried + data
                    head_end = full.find(b"\r\n\r\n")
                    ends = [m.end() for m in re.finditer(b"\n\n", full[head_end + 4:])]
                    if head_end >= 0 and len(ends) >= self._events:
                        # Through the last wanted whole event, and a little of the next one.
                        end = head_end + 4 + ends[self._events - 1] + 12
                        keep = full[:max(len(carried), end)]
                        client.sendall(keep[len(carried):])
                        self.cut_stream = keep
                        client.shutdown(socket.SHUT_RDWR)
                        return
                    carried += data
                client.sendall(data)

    @staticmethod
    def _pump(client: socket.socket, upstream: socket.socket) -> None:
        try:
            while True:
                data = client.recv(65536)
                if not data:
                    break
                upstream.sendall(data)
        except OSError:
            pass


def checkout_copy(into: Path) -> Path:
    """``into`` with a copy of clients/python (pip builds in the tree it installs from, and the
    tests write nothing into the checkout) and the checkout's proto/ beside it; returns ``into``."""
    import shutil

    shutil.copytree(PACKAGE_DIR, into / "clients" / "python",
                    ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__", ".venv"))
    (into / "proto").symlink_to(SOURCE_DIR / "proto")
    return into


def debian_python_env(**extra: str) -> Dict[str, str]:
    """The environment for commands that say ``python3``: this interpreter's directory first on
    PATH (ctest runs Debian's /usr/bin/python3, whose setuptools build offline), no PYTHONPATH,
    so that an installed package is the one imported."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["PATH"] = os.path.dirname(os.path.realpath(sys.executable)) + os.pathsep + env["PATH"]
    env.update(extra)
    return env
