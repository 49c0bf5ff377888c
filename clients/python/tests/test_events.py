"""The event-stream parser and the error documents, without a service."""

from __future__ import annotations

import base64
import struct
import unittest

from radiant_client import (Event, InvalidSceneError, NotFoundError, QueueFullError,
                            RadiantError, SceneError, ServerError)
from radiant_client.errors import error_from_response
from radiant_client.events import EventParser, decode_arrays, parse_events


class Events(unittest.TestCase):
    def test_fields_comments_and_multi_line_data(self):
        text = ("event: progress\nid: 2\ndata: {\"fraction\": 0.5}\n\n"
                ": keep-alive\n\n"
                "event: note\ndata:first\ndata: second\n\n"
                "id: 7\n\n"
                "data: [1,\ndata: 2]\n\n")
        self.assertEqual(list(parse_events(text.split("\n"))), [
            Event("progress", 2, {"fraction": 0.5}),
            Event("note", None, "first\nsecond"),
            Event("message", None, [1, 2]),
        ])

    def test_last_event_id_counts_only_whole_events(self):
        parser = EventParser()
        for line in ["event: progress", "id: 4", "data: {}", ""]:
            parser.feed(line)
        self.assertEqual(parser.last_event_id, 4)
        for line in ["event: radiosity", "id: 5", "data: {\"cut"]:
            self.assertIsNone(parser.feed(line))
        self.assertEqual(parser.last_event_id, 4)  # event 5 never completed

    def test_data_of_unwanted_kinds_is_left_as_text(self):
        parser = EventParser(lambda kind: kind != "radiosity")
        for line in ["event: radiosity", "id: 1", "data: {\"a\": 1}"]:
            parser.feed(line)
        self.assertEqual(parser.feed(""), Event("radiosity", 1, "{\"a\": 1}"))


class EventArrays(unittest.TestCase):
    def test_base64_little_endian_arrays_decode_to_float32_and_int32(self):
        data = {"id": "j", "encoding": "base64-le", "version": 3,
                "vertex_radiosity": base64.b64encode(struct.pack("<3f", 1.5, 0.0, 250.25)).decode(),
                "triangles": base64.b64encode(struct.pack("<3i", 0, 1, 2)).decode()}
        out = decode_arrays(data)
        self.assertEqual(list(out["vertex_radiosity"]), [1.5, 0.0, 250.25])
        self.assertEqual(list(out["triangles"]), [0, 1, 2])
        self.assertEqual(out["version"], 3)

    def test_other_encodings_and_broken_arrays_are_refused(self):
        with self.assertRaises(ValueError):
            decode_arrays({"encoding": "json", "vertices": []})
        with self.assertRaises(ValueError):
            decode_arrays({"encoding": "base64-le", "vertices": base64.b64encode(b"12345").decode()})


class ErrorDocuments(unittest.TestCase):
    def test_a_refused_scene_carries_every_problem(self):
        body = ('{"error":{"code":"invalid_scene","message":"m1","pointer":"/a",'
                '"problems":[{"pointer":"/a","message":"m1"},{"pointer":"/b/0","message":"m2"}]}}')
        e = error_from_response(400, body, None)
        self.assertIsInstance(e, InvalidSceneError)
        self.assertIsInstance(e, SceneError)
        self.assertEqual((e.status, e.code, e.pointer, e.message),
                         (400, "invalid_scene", "/a", "m1"))
        self.assertEqual([str(p) for p in e.problems], ["/a: m1", "/b/0: m2"])
        self.assertIn("/b/0: m2", str(e))

    def test_statuses(self):
        full = error_from_response(
            429, '{"error":{"code":"queue_full","message":"full","pointer":""}}', "5")
        self.assertIsInstance(full, QueueFullError)
        self.assertEqual(full.retry_after, 5.0)
        self.assertIsInstance(error_from_response(404, '{"error":{"code":"not_found"}}', None),
                              NotFoundError)
        odd = error_from_response(502, "<html>bad gateway</html>", None)
        self.assertIsInstance(odd, ServerError)
        self.assertIsInstance(odd, RadiantError)
        self.assertEqual(odd.message, "<html>bad gateway</html>")


if __name__ == "__main__":
    unittest.main()
