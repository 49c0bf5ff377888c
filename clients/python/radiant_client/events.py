"""Server-sent events (``GET /v1/jobs/{id}/events``) as Python objects."""

from __future__ import annotations

import base64
import json
import sys
from array import array
from dataclasses import dataclass
from typing import Any, Callable, Dict, Iterable, Iterator, Mapping, Optional


@dataclass(frozen=True)
class Event:
    """One event of a job's stream.

    ``kind`` is ``progress``, ``mesh``, ``radiosity`` or ``done`` (see proto/openapi.yaml);
    ``id`` the event id (one increasing sequence per job, what ``Last-Event-ID`` resumes from);
    ``data`` the parsed JSON payload (the raw text when it is not JSON).
    """

    kind: str
    id: Optional[int]
    data: Any


class EventParser:
    """Turns the lines of a ``text/event-stream`` into events (the WHATWG HTML rules: ``field:
    value`` lines, ``:`` comments, a blank line ends an event, ``data`` lines join with ``\\n``).

    ``parse_data(kind)`` says whether an event's data is parsed as JSON; events it declines are
    still returned, with the text as ``data`` (radiosity events are large: parsing them only to
    drop them is slow).
    """

    def __init__(self, parse_data: Callable[[str], bool] = lambda kind: True):
        self._parse_data = parse_data
        self._kind = ""
        self._data: list = []
        self._id: Optional[int] = None
        #: The id of the last event seen: what a reconnection sends as ``Last-Event-ID``.
        self.last_event_id: Optional[int] = None

    def feed(self, line: str) -> Optional[Event]:
        """Takes one line (without its line ending); returns the event it completes, if any."""
        if line == "":
            return self._dispatch()
        if line.startswith(":"):
            return None  # a comment: the service's keep-alive
        field, _, value = line.partition(":")
        if value.startswith(" "):
            value = value[1:]
        if field == "event":
            self._kind = value
        elif field == "data":
            self._data.append(value)
        elif field == "id":
            try:
                self._id = int(value)
            except ValueError:
                pass
        return None

    def _dispatch(self) -> Optional[Event]:
        kind, data, event_id = self._kind or "message", self._data, self._id
        self._kind, self._data, self._id = "", [], None
        if event_id is not None:
            self.last_event_id = event_id
        if not data:
            return None
        text = "\n".join(data)
        payload: Any = text
        if self._parse_data(kind):
            try:
                payload = json.loads(text)
            except ValueError:
                pass
        return Event(kind, event_id, payload)


def parse_events(lines: Iterable[str]) -> Iterator[Event]:
    """The events in ``lines`` (a whole stream's text split into lines)."""
    parser = EventParser()
    for line in lines:
        event = parser.feed(line)
        if event is not None:
            yield event


#: The arrays of ``mesh`` and ``radiosity`` events and their element types: ``f`` float32,
#: ``i`` int32.
EVENT_ARRAYS = {"vertices": "f", "triangles": "i", "triangle_surface": "i",
                "triangle_radiosity": "f", "vertex_radiosity": "f"}


def decode_arrays(data: Mapping[str, Any]) -> Dict[str, Any]:
    """A ``mesh`` or ``radiosity`` event's data with its arrays decoded.

    The service sends them as base64 of little-endian float32 and int32 values
    (``"encoding": "base64-le"``, docs/service.md); here each becomes an :class:`array.array`
    (``vertices`` holds x, y, z of each vertex in turn, ``triangles`` three vertex indices per
    triangle). Other members are copied as they are. Raises ``ValueError`` for another
    encoding or an array that is not whole values.
    """
    out = dict(data)
    if data.get("encoding") != "base64-le":
        raise ValueError(f"unknown array encoding {data.get('encoding')!r}")
    for key, kind in EVENT_ARRAYS.items():
        if key not in data:
            continue
        values = array(kind)
        raw = base64.b64decode(data[key], validate=True)
        if len(raw) % values.itemsize:
            raise ValueError(f"{key}: {len(raw)} bytes are not whole {values.itemsize}-byte values")
        values.frombytes(raw)
        if sys.byteorder == "big":
            values.byteswap()
        out[key] = values
    return out
