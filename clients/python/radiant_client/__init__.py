"""Python client of the Radiant radiosity service (radiantd): submit scenes, follow jobs, read
results and their work-plane numbers. Standard library only.

    from radiant_client import Client

    client = Client("http://127.0.0.1:8080")
    job = client.submit("proto/examples/simple-room.json")
    job.wait(progress=lambda p: print(f"{p['fraction']:.0%}"))
    print(job.table())
"""

from .client import DEFAULT_URL, Client, Job
from .errors import (BadRequestError, HTTPError, InvalidSceneError, JobFailedError,
                     NotFoundError, PayloadTooLargeError, Problem, QueueFullError,
                     RadiantConnectionError, RadiantError, RadiantTimeout, SceneError,
                     SceneFileError, ServerError, ServiceUnavailableError)
from .events import Event
from .scene_files import inline_files, load_scene
from .workplane import SensorMetrics, format_table, grid_names, sensor_metrics, sensor_rows

__version__ = "0.1.0"

__all__ = [
    "DEFAULT_URL", "Client", "Job", "Event",
    "load_scene", "inline_files",
    "SensorMetrics", "sensor_metrics", "sensor_rows", "grid_names", "format_table",
    "RadiantError", "RadiantConnectionError", "RadiantTimeout", "JobFailedError",
    "SceneError", "SceneFileError", "Problem",
    "HTTPError", "BadRequestError", "InvalidSceneError", "NotFoundError",
    "PayloadTooLargeError", "QueueFullError", "ServiceUnavailableError", "ServerError",
]
