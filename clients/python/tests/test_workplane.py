"""Work-plane metrics and rows from result documents of each shape (no service needed)."""

from __future__ import annotations

import unittest

from radiant_client import format_table, grid_names, sensor_metrics, sensor_rows


def sensor(name, values, **extra):
    return {"name": name, "illuminance": values, "min": min(values), "max": max(values),
            "average": sum(values) / len(values), "uniformity": 0.0, "u0": 0.0, "ud": 0.0,
            **extra}


class Metrics(unittest.TestCase):
    def test_the_results_own_numbers(self):
        s = sensor("desk", [100.0, 300.0])
        s.update(u0=0.5, ud=1 / 3)
        [m] = sensor_metrics({"sensors": [s]})
        self.assertEqual((m.name, m.points, m.e_avg, m.e_min, m.e_max, m.u0), ("desk", 2, 200.0,
                                                                               100.0, 300.0, 0.5))

    def test_computed_when_a_member_is_missing(self):
        [m] = sensor_metrics({"sensors": [{"name": "old", "illuminance": [100, 200, 300]}]})
        self.assertEqual((m.e_avg, m.e_min, m.e_max), (200.0, 100.0, 300.0))
        self.assertAlmostEqual(m.u0, 0.5)
        self.assertAlmostEqual(m.ud, 1 / 3)
        [dark] = sensor_metrics({"sensors": [{"name": "dark", "illuminance": [0, 0]}]})
        self.assertEqual((dark.u0, dark.ud), (0.0, 0.0))

    def test_a_running_job_without_previews(self):
        self.assertEqual(sensor_metrics({"status": "running", "sensors": []}), [])


class Rows(unittest.TestCase):
    def test_a_scene_grid_is_row_major_u_fastest(self):
        scene = {"sensors": [{"name": "g", "grid": {"origin": [0, 0, 0], "u": [3, 0, 0],
                                                    "v": [0, 2, 0], "nu": 3, "nv": 2},
                              "normal": [0, 0, 1]}]}
        result = {"sensors": [sensor("g", [1.0, 2.0, 3.0, 4.0, 5.0, 6.0])]}
        self.assertEqual(sensor_rows(result, "g", scene), [[1, 2, 3], [4, 5, 6]])
        with self.assertRaises(ValueError):
            sensor_rows(result, "g")  # a scene grid needs the scene
        with self.assertRaises(KeyError):
            sensor_rows(result, "nothing", scene)
        self.assertEqual(grid_names(result, scene), ["g"])
        self.assertEqual(grid_names(result), [])

    def test_a_work_plane_leaves_the_cells_without_points_empty(self):
        grid = {"nu": 2, "nv": 2, "spacing": 1, "origin": [0, 0, 0.8], "u": [2, 0, 0],
                "v": [0, 2, 0], "points": [[0.5, 0.5, 0.8]] * 3, "cells": [[0, 0], [1, 0], [1, 1]]}
        result = {"sensors": [sensor("wp", [10.0, 20.0, 30.0], grid=grid),
                              sensor("desk", [5.0])]}
        self.assertEqual(sensor_rows(result, "wp"), [[10, 20], [None, 30]])
        with self.assertRaises(ValueError):
            sensor_rows(result, "desk", {"sensors": [{"name": "desk", "points": [[0, 0, 0]]}]})
        table = format_table(result)
        self.assertIn("wp (lux; v up, u across):", table)
        # The row farthest along v prints first, as on a plan.
        self.assertTrue(table.endswith("\n - 30\n10 20"), table)
        self.assertIn("desk", table.splitlines()[2])


if __name__ == "__main__":
    unittest.main()
