"""The client against a real radiantd on a loopback port (started by the tests)."""

from __future__ import annotations

import csv
import http.client
import io
import json
import struct
import tempfile
import threading
import time
import unittest
from pathlib import Path

from radiant_client import (BadRequestError, Client, HTTPError, InvalidSceneError, NotFoundError, QueueFullError,
                            RadiantConnectionError, RadiantTimeout, SceneError, SceneFileError)
from radiant_client.events import decode_arrays, parse_events

from support import (FURNISHED_OFFICE, SIMPLE_ROOM, SOURCE_DIR, CuttingProxy, Daemon,
                     free_port, require_radiantd, slow_room, tiny_room, wait_for_status)


def increasing(ids):
    return all(a < b for a, b in zip(ids, ids[1:]))


class Service(unittest.TestCase):
    """One daemon for the tests that leave no job running."""

    @classmethod
    def setUpClass(cls):
        require_radiantd()
        cls.daemon = Daemon().start()
        cls.client = Client(cls.daemon.url, timeout=30)

    @classmethod
    def tearDownClass(cls):
        cls.daemon.close()

    def test_health_jobs_and_metrics(self):
        self.assertEqual(self.client.health(), {"status": "ok", "store": "writable"})
        first = self.client.submit(tiny_room())
        second = self.client.submit(tiny_room())
        second.wait(timeout=60)
        first.wait(timeout=60)
        ids = [job["id"] for job in self.client.jobs()]
        self.assertLess(ids.index(second.id), ids.index(first.id))  # newest first
        self.assertEqual(len(self.client.jobs(limit=1)), 1)
        self.assertIn("radiant_jobs{", self.client.metrics())

    def test_simple_room_with_progress_metrics_rows_and_glb(self):
        job = self.client.submit(SIMPLE_ROOM)
        seen = []
        final = job.wait(progress=seen.append, timeout=120)
        self.assertEqual(final["status"], "done")
        self.assertTrue(seen)
        fractions = [p["fraction"] for p in seen]
        self.assertEqual(fractions, sorted(fractions))
        self.assertEqual(seen[0]["id"], job.id)

        result = job.result()
        self.assertEqual(result["status"], "converged")
        [m] = job.metrics(result)
        self.assertEqual((m.name, m.points), ("workplane", 81))
        self.assertGreater(m.e_min, 0)
        self.assertLessEqual(m.e_min, m.e_avg)
        self.assertLessEqual(m.e_avg, m.e_max)
        # Each value carries 4 significant digits (each off by at most 5e-4 of itself), so the
        # ratio of the rounded min and average and the rounded u0 may differ by 1.5e-3 of it.
        self.assertAlmostEqual(m.u0, m.e_min / m.e_avg, delta=1.5e-3 * m.u0)
        rows = job.rows("workplane", result)  # a scene grid: laid out with the submitted scene
        self.assertEqual([len(r) for r in rows], [9] * 9)
        self.assertEqual(rows[0][:2], result["sensors"][0]["illuminance"][:2])
        self.assertAlmostEqual(rows[4][4], m.e_max)  # under the bulb
        self.assertIn("workplane", job.table(result))

        self.assertEqual(job.result_glb()[:4], b"glTF")
        mesh = job.result(include_mesh=True)["mesh"]
        self.assertEqual(len(mesh["triangles"]), len(mesh["triangle_radiosity"]))

    def test_files_and_compact_events_of_a_finished_job(self):
        job = self.client.submit(SIMPLE_ROOM)
        job.wait(timeout=120)
        result = job.result()
        self.assertEqual(result["units"]["illuminance"], "lx")
        rows = list(csv.reader(io.StringIO(job.sensors_csv(), newline="")))
        self.assertEqual(rows[0], ["set", "index", "x", "y", "z", "nx", "ny", "nz", "lux"])
        workplane = result["sensors"][0]
        self.assertEqual(len(rows), 1 + len(workplane["illuminance"]))
        for row, point, lux in zip(rows[1:], workplane["points"], workplane["illuminance"]):
            self.assertEqual([float(x) for x in row[2:5]], point)
            self.assertEqual(float(row[8]), lux)
        for picture in (job.plan_png(size=200), job.view_png(width=80, height=60),
                        job.view_png(eye=(0.5, 0.5, 2.0), target=(3, 3, 0), falsecolor=True,
                                     width=80, height=60)):
            self.assertEqual(picture[:8], b"\x89PNG\r\n\x1a\n")
        mesh = radiosity = None
        for event in job.events(kinds=("mesh", "radiosity")):
            if event.kind == "mesh":
                mesh = decode_arrays(event.data)
            else:
                radiosity = decode_arrays(event.data)
        self.assertIsNotNone(mesh)
        self.assertTrue(radiosity["final"])
        self.assertEqual(len(mesh["vertices"]), 3 * len(radiosity["vertex_radiosity"]))
        self.assertEqual(len(mesh["triangles"]), 3 * len(radiosity["triangle_radiosity"]))
        self.assertEqual(len(mesh["triangle_surface"]), len(radiosity["triangle_radiosity"]))
        self.assertGreater(max(radiosity["vertex_radiosity"]), 0)

    def test_furnished_office_with_its_obj_and_ies_files(self):
        # Sent as the file is, the service refuses the references: it has no scene directory.
        connection = http.client.HTTPConnection("127.0.0.1", self.daemon.port, timeout=30)
        connection.request("POST", "/v1/jobs", FURNISHED_OFFICE.read_bytes(),
                           {"Content-Type": "application/json"})
        refused = json.loads(connection.getresponse().read())["error"]
        connection.close()
        self.assertIn("/obj_file", " ".join(p["pointer"] for p in refused["problems"]))

        job = self.client.submit(FURNISHED_OFFICE, {"tolerance": 0.1})
        self.assertEqual(job.wait(timeout=300)["status"], "done")
        result = job.result()
        names = [s["name"] for s in result["surfaces"]]
        self.assertTrue(any(n.startswith("furniture") for n in names), names)
        # The work plane names an EN 12464-1 task: its surrounding band is a set of its own.
        metrics = {m.name: m for m in job.metrics(result)}
        self.assertEqual(len(metrics), 2, list(metrics))
        m = metrics["work plane"]
        self.assertGreater(m.e_avg, 100)  # the three IES downlights light it
        rows = job.rows("work plane", result)  # a work plane: its grid comes with the result
        grid = result["sensors"][0]["grid"]
        self.assertEqual((len(rows[0]), len(rows)), (grid["nu"], grid["nv"]))
        self.assertEqual(sum(v is not None for r in rows for v in r), m.points)

    def test_light_scenes_from_the_stored_solution(self):
        job = self.client.submit(FURNISHED_OFFICE.with_name("light-scenes.json"),
                                 {"tolerance": 0.1})
        with self.assertRaises(HTTPError) as running:  # the office takes a second to solve
            job.light_scene("early", {"window": 1})
        self.assertEqual(running.exception.status, 409)
        self.assertEqual(job.wait(timeout=300)["status"], "done")
        result = job.result()
        both = job.light_scene("all on", {"window": 1, "door": 1})
        self.assertEqual(both["name"], "all on")
        window = job.light_scene("window", {"window": 1})
        half = job.light_scene("window at half", {"window": 0.5})
        for full, w, h in zip(result["sensors"][0]["illuminance"],
                              window["sensors"][0]["illuminance"],
                              half["sensors"][0]["illuminance"]):
            self.assertAlmostEqual(h, 0.5 * w, delta=1e-3 * max(w, 1))  # light is linear
            self.assertLessEqual(w, full * (1 + 1e-9))
        for mine, all_on in zip(both["sensors"][0]["illuminance"],
                                result["sensors"][0]["illuminance"]):
            self.assertAlmostEqual(mine, all_on, delta=1e-3 * max(all_on, 1))
        with self.assertRaises(BadRequestError) as unknown:
            job.light_scene("typo", {"windw": 1})
        self.assertEqual(unknown.exception.pointer, "/dimming/windw")

    def test_model_and_photometric_files_of_the_test_data(self):
        good = SOURCE_DIR / "tests" / "data" / "good"
        jobs = {name: self.client.submit(good / name, {"tolerance": 0.1})
                for name in ("import-obj-file.json", "import-gltf.json", "workplane-ies.json")}
        # The same table as a .gltf with its buffer in a separate file: sent as one .glb.
        with tempfile.TemporaryDirectory() as tmp:
            glb = (good / "models" / "table.glb").read_bytes()
            json_length = struct.unpack_from("<I", glb, 12)[0]
            document = json.loads(glb[20:20 + json_length])
            binary = glb[20 + json_length + 8:][:document["buffers"][0]["byteLength"]]
            Path(tmp, "table.bin").write_bytes(binary)
            document["buffers"][0]["uri"] = "table.bin"
            Path(tmp, "table.gltf").write_text(json.dumps(document))
            scene = json.loads((good / "import-gltf.json").read_text())
            model = next(s for s in scene["surfaces"] if "gltf_file" in s)
            model["gltf_file"] = str(Path(tmp, "table.gltf"))
            jobs["table.gltf"] = self.client.submit(scene, {"tolerance": 0.1})
        for name, job in jobs.items():
            with self.subTest(name):
                self.assertEqual(job.wait(timeout=120)["status"], "done")
        surfaces = [s["name"] for s in jobs["table.gltf"].result()["surfaces"]]
        self.assertTrue(any(n.startswith("table-file") for n in surfaces), surfaces)

    def test_a_refused_scene_raises_with_the_services_pointer(self):
        scene = tiny_room()
        scene["surfaces"][1]["polygon"] = scene["surfaces"][1]["polygon"][:2]
        scene["materials"]["wall"]["reflectance"] = 1.5
        with self.assertRaises(InvalidSceneError) as caught:
            self.client.submit(scene)
        e = caught.exception
        self.assertEqual((e.status, e.code), (400, "invalid_scene"))
        pointers = [p.pointer for p in e.problems]
        self.assertIn("/surfaces/1/polygon", pointers)
        self.assertIn("/materials/wall/reflectance", pointers)
        self.assertEqual(e.pointer, e.problems[0].pointer)

    def test_every_bad_scene_of_the_test_data_is_refused_at_its_expected_pointer(self):
        bad = SOURCE_DIR / "tests" / "data" / "bad"
        expected = json.loads((bad / "expected.json").read_text())
        for name, want in expected.items():
            with self.subTest(name):
                with self.assertRaises(SceneError) as caught:
                    self.client.submit(bad / name)
                self.assertEqual(caught.exception.pointer, want["pointer"], caught.exception)
                if name == "import-obj-file-missing.json":
                    self.assertIsInstance(caught.exception, SceneFileError)  # read by the client

    def test_an_idempotency_key_returns_the_first_submissions_job(self):
        key = f"python-test-{time.time_ns()}"
        first = self.client.submit(tiny_room(), idempotency_key=key)
        again = self.client.submit(tiny_room(), idempotency_key=key)
        self.assertEqual(again.id, first.id)
        self.assertEqual(first.wait(timeout=60)["status"], "done")

    def test_unknown_job(self):
        with self.assertRaises(NotFoundError) as caught:
            self.client.job("0" * 32).status()
        self.assertEqual(caught.exception.code, "not_found")

    def test_events_resume_with_last_event_id(self):
        job = self.client.submit(slow_room(2))
        head = []
        for event in job.events():
            head.append(event)
            if len(head) == 4:
                break  # the stream is closed here
        ids = [e.id for e in head]
        self.assertTrue(increasing(ids), ids)
        rest = list(job.events(last_event_id=ids[-1], timeout=60))
        rest_ids = [e.id for e in rest]
        self.assertGreater(rest_ids[0], ids[-1])
        self.assertTrue(increasing(rest_ids), rest_ids)
        self.assertEqual(rest[-1].kind, "done")
        self.assertEqual(rest[-1].data["status"], "done")
        kinds = {e.kind for e in head + rest}
        self.assertLessEqual({"progress", "radiosity", "done"}, kinds)

    def test_a_dropped_stream_reconnects_with_last_event_id(self):
        proxy = CuttingProxy(self.daemon.port, events=2)
        try:
            job = Client(proxy.url).submit(slow_room(2))
            events = list(job.events(timeout=60))
        finally:
            proxy.close()
        ids = [e.id for e in events]
        self.assertTrue(increasing(ids), ids)
        self.assertEqual(events[-1].kind, "done")
        body = proxy.cut_stream.split(b"\r\n\r\n", 1)[1].decode()
        cut_ids = [e.id for e in parse_events(body.split("\n"))]
        self.assertGreaterEqual(len(cut_ids), 2)
        retries = [r for r in proxy.requests if r.startswith("GET ") and "/events" in r]
        self.assertEqual(len(retries), 2, retries)
        self.assertIn(f"Last-Event-ID: {cut_ids[-1]}\r\n", retries[1])
        self.assertEqual(ids[:len(cut_ids)], cut_ids)

    def test_cancel_a_running_job(self):
        job = self.client.submit(slow_room(30))
        self.assertEqual(wait_for_status(job, "running")["status"], "running")
        with self.assertRaises(RadiantTimeout):
            job.wait(timeout=0.5)
        answer = job.cancel()
        self.assertIn(answer["status"], ("running", "cancelled"))
        self.assertEqual(job.wait(timeout=30)["status"], "cancelled")
        self.assertEqual(job.result()["status"], "stopped")  # the best result so far


class QueueFull(unittest.TestCase):
    def test_429_carries_retry_after_and_queue_wait_retries(self):
        with Daemon("--queue-limit", "1") as daemon:
            client = Client(daemon.url)
            slow = client.submit(slow_room(30))
            wait_for_status(slow, "running")
            queued = client.submit(tiny_room())
            with self.assertRaises(QueueFullError) as caught:
                client.submit(tiny_room())
            self.assertEqual((caught.exception.status, caught.exception.code),
                             (429, "queue_full"))
            self.assertEqual(caught.exception.retry_after, 5.0)
            # Once the slow job is cancelled the queue drains, and a waiting submission goes in.
            threading.Timer(0.5, slow.cancel).start()
            started = time.monotonic()
            late = client.submit(tiny_room(), queue_wait=60)
            self.assertGreaterEqual(time.monotonic() - started, 4)  # it honoured Retry-After
            self.assertEqual(late.wait(timeout=60)["status"], "done")
            self.assertEqual(queued.wait(timeout=60)["status"], "done")


class Token(unittest.TestCase):
    def test_a_service_with_a_token_file_needs_the_token(self):
        require_radiantd()
        with tempfile.TemporaryDirectory() as tmp:
            token_file = Path(tmp) / "token"
            token_file.write_text("py-s3cret\n")
            with Daemon("--token-file", str(token_file)) as daemon:
                self.assertEqual(Client(daemon.url).health(), {"status": "ok", "store": "writable"})
                with self.assertRaises(HTTPError) as caught:
                    Client(daemon.url).submit(tiny_room())
                self.assertEqual((caught.exception.status, caught.exception.code),
                                 (401, "unauthorized"))
                job = Client(daemon.url, token="py-s3cret").submit(tiny_room())
                self.assertEqual(job.wait(timeout=60)["status"], "done")


class Connection(unittest.TestCase):
    def test_no_service_raises_a_connection_error(self):
        client = Client(f"http://127.0.0.1:{free_port()}", timeout=5)
        with self.assertRaises(RadiantConnectionError):
            client.health()
        with self.assertRaises(ConnectionError):  # it is a builtin ConnectionError too
            client.submit(tiny_room())

    def test_the_stream_survives_a_daemon_restart(self):
        require_radiantd()
        daemon = Daemon(port=free_port()).start()
        try:
            job = Client(daemon.url).submit(slow_room(3))
            ids = []
            for event in job.events(timeout=120):
                ids.append(event.id)
                if len(ids) == 2:
                    daemon.kill()  # as a crash: the job store keeps the running job
                    daemon.start()  # on the same port and data; the job runs again
            self.assertEqual(event.kind, "done")
            self.assertTrue(increasing(ids), ids)
            # The job's second run numbers its events a million above the first's.
            self.assertGreater(ids[-1], 1_000_000)
            self.assertEqual(job.status()["status"], "done")
        finally:
            daemon.close()


if __name__ == "__main__":
    unittest.main()
