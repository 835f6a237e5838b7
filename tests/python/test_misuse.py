# SPDX-License-Identifier: BSD-3-Clause
"""Bad arrays, bad files and misuse raise edgetrack.Error with a clear line, never crash, and
leave the tracker as it was; one tracker called from two threads at once refuses the second call."""
import os
import threading
import unittest

import numpy as np

import edgetrack
from frames import CONFIG, INIT, MODEL, OUTPUT, cube_frame

L = edgetrack.Layout


class Misuse(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = edgetrack.load_model(MODEL)
        cls.config = edgetrack.read_config(CONFIG)
        cls.initial = edgetrack.read_pose(INIT)
        cls.grey = cube_frame(0)

    def setUp(self):
        self.tracker = edgetrack.Tracker(self.model, self.config, self.initial)
        self.tracker.track(self.grey)
        self.before = self.tracker.pose

    def refused(self, frame, words, layout=None):
        with self.assertRaises(edgetrack.Error) as raised:
            self.tracker.track(frame, layout=layout)
        message = str(raised.exception)
        self.assertEqual(len(message.splitlines()), 1, message)
        self.assertRegex(message, words)
        np.testing.assert_array_equal(self.tracker.pose, self.before, "the tracker is unchanged")

    def test_bad_arrays(self):
        h, w = self.grey.shape
        self.refused(self.grey.astype(np.float32), "float32 .*uint8")
        self.refused(self.grey.astype(np.int16), "int16")
        self.refused(self.grey.astype(np.float64), "wrong dtype", L.GREY8)
        self.refused(self.grey.astype(np.uint16), "wrong dtype", L.GREY8)
        self.refused(self.grey.astype(">u2"), "wrong dtype", L.RGB565)
        self.refused(np.zeros((h, w, 3), np.uint8), "needs its layout")
        self.refused(np.zeros((h, w, 3), np.uint8), "wrong shape", L.GREY8)
        self.refused(np.zeros((h, w, 4), np.uint8), "wrong shape", L.RGB24)
        self.refused(np.zeros((h, w), np.uint8), "wrong shape", L.BGRA32)
        self.refused(np.zeros(h * w, np.uint8), "wrong shape", L.GREY8)
        self.refused(np.zeros((1, h, w), np.uint8), "wrong shape", L.GREY8)
        self.refused(np.zeros((h * 3 // 2 + 1, w), np.uint8), "3H/2", L.NV21)
        self.refused(np.asfortranarray(self.grey), "pixels of a row are not next to one another")
        self.refused(self.grey[:, ::-1], "pixels of a row are not next to one another")
        self.refused(self.grey[::-1], "rows must go forward")
        self.refused(np.zeros((h, 2 * w), np.uint8)[:, ::2], "column stride 2 bytes, not 1")
        self.refused(np.zeros((h, w, 3), np.uint8, order="F"), "channels of a pixel", L.BGR24)
        self.refused(self.grey[:100], "640x100, the camera's images are 640x480")
        self.refused(self.grey[:, :600], "600x480")
        self.refused(np.zeros((0, 0), np.uint8), "an empty frame")
        self.refused([[1, 2], [3, 4]], "int64 .*uint8")
        self.refused(b"not a frame", "wrong dtype", L.GREY8)
        self.refused(object(), "object array .*frames are uint8 arrays")
        self.refused(np.zeros((h, w), np.uint8), "the NV21 frame is 640x320", L.NV21)
        odd = np.zeros(h * w * 2 + 1, np.uint8)[1:].view(np.uint16).reshape(h, w)
        self.refused(odd, "2-byte boundaries")
        with self.assertRaises(TypeError):  # a layout is an edgetrack.Layout
            self.tracker.track(self.grey, layout=99)

    def test_read_only_and_non_numpy_buffers_are_read(self):
        frozen = self.grey.copy()
        frozen.flags.writeable = False
        self.assertEqual(self.tracker.track(frozen).status, edgetrack.Status.TRACKED)
        self.assertEqual(self.tracker.track(memoryview(self.grey.tobytes()).cast("B", self.grey.shape)).status,
                         edgetrack.Status.TRACKED)

    def test_bad_files(self):
        directory = os.path.join(OUTPUT, "a_directory.cao")
        os.makedirs(directory, exist_ok=True)
        for call, path, words in ((edgetrack.load_model, "missing.cao", "missing.cao"),
                                  (edgetrack.load_model, INIT, "unknown model format"),
                                  (edgetrack.read_config, "missing.xml", "missing.xml"),
                                  (edgetrack.read_pose, MODEL, "cube.cao"),
                                  (edgetrack.read_camera_file, MODEL, "cube.cao"),
                                  (edgetrack.load_model, directory, "is a directory")):
            with self.subTest(call=call.__name__, path=path):
                with self.assertRaisesRegex(edgetrack.Error, words):
                    call(os.path.join(OUTPUT, path) if not os.path.isabs(path) else path)

    def test_a_failed_create_leaves_no_tracker(self):
        config = edgetrack.Config()
        config.camera = edgetrack.Camera(-1, 600, 320, 240, 640, 480)
        with self.assertRaisesRegex(edgetrack.Error, "px"):
            edgetrack.Tracker(self.model, config, self.initial)
        with self.assertRaisesRegex(edgetrack.Error, "4x4"):
            edgetrack.Tracker(self.model, self.config, np.eye(3))
        nan = self.initial.copy()
        nan[0, 3] = np.nan
        with self.assertRaises(edgetrack.Error):
            edgetrack.Tracker(self.model, self.config, nan)
        bad_row = self.initial.copy()
        bad_row[3, 0] = 1
        with self.assertRaisesRegex(edgetrack.Error, "0 0 0 1"):
            edgetrack.Tracker(self.model, self.config, bad_row)
        with self.assertRaises(TypeError):
            edgetrack.Tracker(None, self.config, self.initial)
        with self.assertRaises(TypeError):
            edgetrack.Tracker()

    def refused_while_tracking(self, call):
        """Runs `call(tracker)` in this thread while another thread tracks frames with the same
        tracker (the GIL released inside track), until one of the two threads' calls is refused
        (the worker stops after 2000 frames, seconds after a call would be refused otherwise);
        returns the refusal."""
        tracker = edgetrack.Tracker(self.model, self.config, self.initial)
        frames = [cube_frame(k) for k in range(10)]
        refusals, stop = [], threading.Event()

        def track_frames():
            for k in range(2000):
                if stop.is_set():
                    return
                frame = frames[k % len(frames)]
                try:
                    tracker.track(frame)
                except edgetrack.Error as error:  # this thread's call came second
                    refusals.append(error)
                    return

        worker = threading.Thread(target=track_frames)
        worker.start()
        try:
            while worker.is_alive() and not refusals:
                try:
                    call(tracker)
                except edgetrack.Error as error:
                    refusals.append(error)
        finally:
            stop.set()
            worker.join()
        self.assertTrue(refusals, "a second call on a tracker that is tracking in another thread is refused")
        tracker.reset(self.initial)
        self.assertEqual(tracker.track(self.grey).status, edgetrack.Status.TRACKED, "the tracker still tracks")
        return refusals[0]

    def test_one_tracker_from_two_threads_refuses_the_second_call(self):
        message = "this tracker is already tracking a frame in another thread: use one tracker per thread"
        params = self.tracker.params
        for name, call in (("track", lambda t: t.track(self.grey)), ("reset", lambda t: t.reset(self.initial)),
                           ("set_params", lambda t: t.set_params(params))):
            with self.subTest(call=name):
                self.assertEqual(str(self.refused_while_tracking(call)), message)


if __name__ == "__main__":
    unittest.main()
