# SPDX-License-Identifier: BSD-3-Clause
"""Tracking from Python: ViSP's mbt/cube gives `edgetrack track`'s poses CSV (through
examples/python/track_sequence.py as written); the result carries its measures and points;
reset, set_params, detection and one tracker per thread behave as the C++ API's."""
import csv
import os
import subprocess
import sys
import threading
import unittest

import numpy as np

import edgetrack
from frames import CONFIG, INIT, MBT, MODEL, OUTPUT, SOURCE, TOLERANCE, cube_frame

LAST = 80  # frames 0..LAST of mbt/cube
PATTERN = os.path.join(MBT, "cube", "image%04d.pgm")


def rows_without_time(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return [row[:8] + row[9:] for row in rows]  # all but ms


class Tracking(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = edgetrack.load_model(MODEL)
        cls.config = edgetrack.read_config(CONFIG)
        cls.initial = edgetrack.read_pose(INIT)

    def test_cube_equals_the_command_line(self):
        cli = os.environ.get("EDGETRACK_CLI")
        self.assertTrue(cli, "EDGETRACK_CLI names the edgetrack executable")
        expected, got = os.path.join(OUTPUT, "cli_poses.csv"), os.path.join(OUTPUT, "python_poses.csv")
        subprocess.run([cli, "track", "--model", MODEL, "--camera", CONFIG, "--init-pose", INIT, "--images", PATTERN,
                        "--first", "0", "--last", str(LAST), "--poses", expected], check=True, capture_output=True)
        script = os.path.join(SOURCE, "examples", "python", "track_sequence.py")
        run = subprocess.run([sys.executable, script, MODEL, CONFIG, INIT, PATTERN, "0", str(LAST), "--poses", got],
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(len(run.stdout.splitlines()), LAST + 1)
        self.assertIn("tracked", run.stdout)
        cli_rows, python_rows = rows_without_time(expected), rows_without_time(got)
        self.assertEqual(len(cli_rows), LAST + 2)
        self.assertEqual(python_rows, cli_rows)

    def test_result_fields(self):
        tracker = edgetrack.Tracker(self.model, self.config, self.initial)
        r = tracker.track(cube_frame(0))
        self.assertEqual(r.status, edgetrack.Status.TRACKED)
        self.assertEqual((r.status_name, r.reason, r.reason_name), ("tracked", edgetrack.Reason.NONE,
                                                                    edgetrack.reason_name(edgetrack.Reason.NONE)))
        self.assertEqual(r.camera_from_model.dtype, np.float64)
        np.testing.assert_array_equal(r.camera_from_model, tracker.pose)
        np.testing.assert_allclose(edgetrack.pose_from_theta_u(r.translation, r.theta_u), r.camera_from_model,
                                   atol=TOLERANCE)
        self.assertEqual(r.sampled_points.shape, (r.points_sampled, 2))
        self.assertEqual(r.matched_points.shape[1], 2)
        self.assertEqual(len(r.outliers), len(r.matched_points))
        self.assertEqual(r.points_matched, len(r.matched_points) - int(r.outliers.sum()))
        self.assertEqual(r.measures.visible, r.points_sampled)
        self.assertEqual(r.measures.kept, r.points_matched)
        self.assertTrue(r.pose.solved and r.measures.solved)
        self.assertEqual(sorted(r.step_ns), sorted(["visible edges detection", "image grey scaling", "ME",
                                                    "pose calculation"]))
        self.assertAlmostEqual(r.ms, sum(r.step_ns.values()) / 1e6)
        h, w = cube_frame(0).shape
        self.assertTrue(((r.sampled_points >= 0) & (r.sampled_points < [w, h])).all())

    def test_reset_starts_again(self):
        fresh = edgetrack.Tracker(self.model, self.config, self.initial).track(cube_frame(0))
        tracker = edgetrack.Tracker(self.model, self.config, self.initial)
        for k in range(10):
            tracker.track(cube_frame(k))
        tracker.reset(self.initial)
        np.testing.assert_array_equal(tracker.pose, self.initial)
        again = tracker.track(cube_frame(0))
        self.assertEqual(again.status, edgetrack.Status.TRACKED)
        np.testing.assert_allclose(again.camera_from_model, fresh.camera_from_model, atol=max(1e-6, TOLERANCE))
        behind = self.initial.copy()
        behind[2, 3] = -1
        with self.assertRaisesRegex(edgetrack.Error, "the reset pose"):
            tracker.reset(behind)
        np.testing.assert_array_equal(tracker.pose, again.camera_from_model, "a refused reset changes nothing")

    def test_set_params_between_frames(self):
        tracker = edgetrack.Tracker(self.model, self.config, self.initial)
        tracker.track(cube_frame(0))
        params = tracker.params
        params.range = 12
        tracker.set_params(params)
        self.assertEqual(tracker.params.range, 12)
        self.assertEqual(tracker.track(cube_frame(1)).measures.range >= 12, True)
        params.range = 0
        with self.assertRaisesRegex(edgetrack.Error, "range"):
            tracker.set_params(params)
        self.assertEqual(tracker.params.range, 12, "a refused setting changes nothing")

    def test_one_tracker_per_thread(self):
        frames = [cube_frame(k) for k in range(20)]

        def run(out):
            tracker = edgetrack.Tracker(self.model, self.config, self.initial)
            out.extend(tracker.track(f).camera_from_model.tobytes() for f in frames)

        alone, a, b = [], [], []
        run(alone)
        threads = [threading.Thread(target=run, args=(out,)) for out in (a, b)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(a, alone)
        self.assertEqual(b, alone)

    def test_auto_init_templates_find_the_cube_from_the_files_as_shipped(self):
        config = edgetrack.read_config(CONFIG)
        camera = config.camera
        camera.width, camera.height = 640, 480
        config.camera = camera
        templates = edgetrack.auto_init_templates(self.model, config.camera)
        self.assertGreater(len(templates), len(edgetrack.make_templates(self.model, config.camera)))
        detection = edgetrack.Detector(self.model, config, templates).detect(cube_frame(0))
        self.assertTrue(detection.found)
        self.assertGreater(detection.score, 0.5)

    def test_detection_and_auto_tracking(self):
        config = edgetrack.read_config(CONFIG)
        camera = config.camera
        camera.width, camera.height = 640, 480
        config.camera = camera
        templates = edgetrack.make_templates(self.model, config.camera, 0.4, 0.7)  # the cube is 0.51 m away
        self.assertGreater(len(templates), 0)
        detection = edgetrack.Detector(self.model, config, templates).detect(cube_frame(0))
        self.assertTrue(detection.found)
        self.assertGreater(detection.score, 0.5)
        auto = edgetrack.AutoTracker(self.model, config, templates)
        first = auto.track(cube_frame(0))
        self.assertTrue(auto.detected and auto.found)
        self.assertEqual((first.status, first.reason), (edgetrack.Status.UNCERTAIN, edgetrack.Reason.UNCONFIRMED))
        later = [auto.track(cube_frame(k)) for k in range(1, 4)]
        self.assertFalse(auto.detected)
        self.assertTrue(auto.confirmed)
        self.assertEqual(later[-1].status, edgetrack.Status.TRACKED)

    def test_detection_budget_from_the_config(self):
        config = edgetrack.read_config(CONFIG)
        camera = config.camera
        camera.width, camera.height = 640, 480
        config.camera = camera
        templates = edgetrack.make_templates(self.model, config.camera, 0.4, 0.7)
        self.assertEqual(config.detector.max_points_searched, edgetrack.DetectorParams().max_points_searched)
        self.assertGreater(config.detector.max_points_searched, 0, "a budget by default")
        default = edgetrack.Detector(self.model, config, templates)
        self.assertEqual(default.points_budget, 4 * config.detector.max_points_searched,
                         "QVGA's budget scaled to 640 x 480's four times the pixels")
        config.apply_text("<conf><edgetrack><detector><max_points_searched>1</max_points_searched>"
                          "</detector></edgetrack></conf>")
        self.assertEqual(config.detector.max_points_searched, 1, "the XML sets it")
        cut = edgetrack.Detector(self.model, config, templates).detect(cube_frame(0))
        self.assertEqual(cut.frames, 1, "a spent budget starts no second frame")
        self.assertTrue(cut.found or cut.cut_short, "not found only as cut short")
        self.assertFalse(cut.found and cut.cut_short)
        detector = config.detector
        detector.max_points_searched = 0
        config.detector = detector
        unlimited = edgetrack.Detector(self.model, config, templates)
        self.assertEqual(unlimited.points_budget, 0, "0: no limit")
        found = unlimited.detect(cube_frame(0))
        self.assertTrue(found.found)
        self.assertFalse(found.cut_short)
        self.assertGreater(found.points_searched, 4)
        detector.max_points_searched = -1
        config.detector = detector
        with self.assertRaisesRegex(edgetrack.Error, "budget"):
            edgetrack.Detector(self.model, config, templates)

if __name__ == "__main__":
    unittest.main()
