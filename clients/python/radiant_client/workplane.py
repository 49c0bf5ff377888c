"""Work-plane numbers from a ``radiant-result/1`` document (proto/schema/result.schema.json).

Each sensor set of a result has ``illuminance`` (lux, in the order of its points) and its
``min``, ``max``, ``average``, ``u0`` (= min / average) and ``ud`` (= min / max). A work plane
(a scene sensor set with ``workplane``) also has ``grid``: ``nu`` × ``nv`` cells and the cell
``(iu, iv)`` of each point, some cells empty where furniture or the floor's edge leaves them out.
A scene's ``grid`` sensor set has no such member in the result: its points are the ``nu`` × ``nv``
cell centres, row-major with u fastest, so its rows need the scene.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, List, Mapping, Optional, Sequence

Rows = List[List[Optional[float]]]


@dataclass(frozen=True)
class SensorMetrics:
    """One sensor set's illuminance statistics, in lux (EN 12464-1 names)."""

    name: str
    points: int
    e_avg: float  #: mean illuminance
    e_min: float
    e_max: float
    u0: float  #: uniformity E_min / E_avg (0 when E_avg is 0)
    ud: float  #: E_min / E_max (0 when E_max is 0)


def _ratio(a: float, b: float) -> float:
    return a / b if b > 0 else 0.0


def _number(sensor: Mapping[str, Any], key: str, fallback: float) -> float:
    value = sensor.get(key)
    return float(value) if isinstance(value, (int, float)) else fallback


def metrics_of(sensor: Mapping[str, Any]) -> SensorMetrics:
    """The metrics of one result sensor set: its own numbers where it has them, else computed
    from ``illuminance`` (the running previews carry the same members, but that is cheap to
    be robust about)."""
    values = [float(v) for v in sensor.get("illuminance", [])]
    e_avg = _number(sensor, "average", sum(values) / len(values) if values else 0.0)
    e_min = _number(sensor, "min", min(values) if values else 0.0)
    e_max = _number(sensor, "max", max(values) if values else 0.0)
    u0 = _number(sensor, "u0", _number(sensor, "uniformity", _ratio(e_min, e_avg)))
    ud = _number(sensor, "ud", _ratio(e_min, e_max))
    return SensorMetrics(str(sensor.get("name", "")), len(values), e_avg, e_min, e_max, u0, ud)


def sensor_metrics(result: Mapping[str, Any]) -> List[SensorMetrics]:
    """Every sensor set's metrics, in the result's order (empty while a job has no preview)."""
    return [metrics_of(s) for s in result.get("sensors", []) if isinstance(s, Mapping)]


def _find(sets: Sequence[Any], name: str, index_hint: Optional[int] = None) -> Optional[Any]:
    if index_hint is not None and 0 <= index_hint < len(sets):
        candidate = sets[index_hint]
        if isinstance(candidate, Mapping) and candidate.get("name") == name:
            return candidate
    return next((s for s in sets if isinstance(s, Mapping) and s.get("name") == name), None)


def sensor_rows(result: Mapping[str, Any], name: str,
                scene: Optional[Mapping[str, Any]] = None) -> Rows:
    """The illuminance (lux) of grid sensor set ``name`` as rows: ``rows[iv][iu]``, row 0 along
    the grid's ``u`` edge at its origin; ``None`` in a work plane's cells that have no point.

    A work plane's grid comes with the result; a scene ``grid`` set needs ``scene`` (the one
    submitted: :meth:`radiant_client.Job.rows` passes it). Raises ``KeyError`` for an unknown
    set and ``ValueError`` for one that is not a grid.
    """
    sets = [s for s in result.get("sensors", []) if isinstance(s, Mapping)]
    index = next((i for i, s in enumerate(sets) if s.get("name") == name), None)
    if index is None:
        raise KeyError(name)
    sensor = sets[index]
    values = [float(v) for v in sensor.get("illuminance", [])]
    grid = sensor.get("grid")
    if isinstance(grid, Mapping):
        nu, nv = int(grid["nu"]), int(grid["nv"])
        rows: Rows = [[None] * nu for _ in range(nv)]
        for value, (iu, iv) in zip(values, grid.get("cells", [])):
            rows[iv][iu] = value
        return rows
    scene_sets = scene.get("sensors", []) if isinstance(scene, Mapping) else []
    scene_set = _find(scene_sets, name, index)
    if scene_set is None or not isinstance(scene_set.get("grid"), Mapping):
        why = "not a grid" if scene is not None else "not a work plane; pass the scene for a grid"
        raise ValueError(f"sensor set {name!r}: {why}")
    nu, nv = int(scene_set["grid"]["nu"]), int(scene_set["grid"]["nv"])
    if len(values) != nu * nv:
        raise ValueError(f"sensor set {name!r} has {len(values)} values, not nu*nv = {nu * nv}")
    return [list(values[iv * nu:(iv + 1) * nu]) for iv in range(nv)]


def grid_names(result: Mapping[str, Any], scene: Optional[Mapping[str, Any]] = None) -> List[str]:
    """The names of the result's sensor sets that :func:`sensor_rows` can lay out as rows."""
    names = []
    for s in result.get("sensors", []):
        try:
            sensor_rows(result, s["name"], scene)
            names.append(s["name"])
        except (KeyError, ValueError):
            pass
    return names


def format_table(result: Mapping[str, Any], scene: Optional[Mapping[str, Any]] = None,
                 digits: int = 0) -> str:
    """A plain-text report: one line of metrics per sensor set, then each grid's rows (lux),
    the row farthest along ``v`` on top, as on a plan with ``v`` pointing up."""
    lines = [f"{'sensor set':<20} {'points':>6} {'E_avg lx':>9} {'E_min lx':>9} "
             f"{'E_max lx':>9} {'U0':>5}"]
    for m in sensor_metrics(result):
        lines.append(f"{m.name[:20]:<20} {m.points:>6} {m.e_avg:>9.1f} {m.e_min:>9.1f} "
                     f"{m.e_max:>9.1f} {m.u0:>5.2f}")
    for name in grid_names(result, scene):
        rows = sensor_rows(result, name, scene)
        cells = [[("-" if v is None else f"{v:.{digits}f}") for v in row] for row in rows]
        width = max((len(c) for row in cells for c in row), default=1)
        lines.append("")
        lines.append(f"{name} (lux; v up, u across):")
        for row in reversed(cells):
            lines.append(" ".join(c.rjust(width) for c in row))
    return "\n".join(lines)
