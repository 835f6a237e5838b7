# SPDX-License-Identifier: BSD-3-Clause
"""Models, configurations, calibrations and poses from Python: files and text give the same
objects; refusals raise edgetrack.Error with the command line's line."""
import os
import subprocess
import unittest

import numpy as np

import edgetrack
from frames import CONFIG, INIT, MBT, MODEL, OUTPUT, TOLERANCE


def write(name, text):
    path = os.path.join(OUTPUT, name)
    with open(path, "w") as f:
        f.write(text)
    return path


class Inputs(unittest.TestCase):
    def test_model_from_file_and_text(self):
        model = edgetrack.load_model(MODEL)
        self.assertEqual((model.vertex_count, model.edge_count), (8, 12))
        with open(MODEL) as f:
            text = f.read()
        same = edgetrack.load_model_text(text, "cube.cao")
        self.assertTrue(np.array_equal(model.vertices, same.vertices))
        self.assertTrue(np.array_equal(model.edges, same.edges))
        obj = edgetrack.load_model_text("v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nf 1 2 3 4\n", "square.obj")
        self.assertEqual(obj.vertex_count, 4)

    def test_load_lines_in_text(self):
        write("py_part.cao", "V1\n4\n0 0 0\n0.1 0 0\n0.1 0.1 0\n0 0.1 0\n0\n0\n1\n4 0 1 2 3\n")
        includer = 'V1\nload("py_part.cao")\n0\n0\n0\n0\n'
        self.assertEqual(edgetrack.load_model_text(includer, "scene.cao", base_dir=OUTPUT).vertex_count, 4)
        with self.assertRaisesRegex(edgetrack.Error, r'^scene\.cao:2: load\("py_part\.cao"\) in a model given as text '
                                                     r'needs a base directory'):
            edgetrack.load_model_text(includer, "scene.cao")

    def test_config_from_file_and_text(self):
        config = edgetrack.read_config(CONFIG)
        with open(CONFIG) as f:
            same = edgetrack.read_config_text(f.read(), "cube.xml")
        for field in ("px", "py", "u0", "v0"):
            self.assertEqual(getattr(config.camera, field), getattr(same.camera, field))
        self.assertEqual(config.params.range, same.params.range)
        self.assertNotEqual(config.params.range, edgetrack.Params().range, "the file's range is applied")
        notes = config.apply_text("<conf><ecm><range><tracking>9</tracking></range></ecm></conf>")
        self.assertEqual(config.params.range, 9)
        self.assertFalse(notes["camera_block"])
        with self.assertRaisesRegex(edgetrack.Error, r"^bad\.xml:1: .*range"):
            config.apply_text("<conf><ecm><range><tracking>-3</tracking></range></ecm></conf>", "bad.xml")
        self.assertEqual(config.params.range, 9, "a refused file changes nothing")

    def test_camera_file(self):
        path = write("camera.xml", """<?xml version="1.0"?>
<root><camera><name>Camera</name><image_width>640</image_width><image_height>480</image_height>
<model><type>perspectiveProjWithoutDistortion</type><px>600</px><py>610</py><u0>320</u0><v0>240</v0></model>
</camera></root>
""")
        camera = edgetrack.read_camera_file(path)
        self.assertEqual((camera.px, camera.py, camera.u0, camera.v0, camera.width, camera.height),
                         (600, 610, 320, 240, 640, 480))
        self.assertFalse(camera.distorted)
        config = edgetrack.Config()
        config.camera = camera
        self.assertEqual(config.camera.py, 610)

    def test_pose_files(self):
        pose = edgetrack.read_pose(INIT)
        self.assertEqual(pose.shape, (4, 4))
        self.assertEqual(pose.dtype, np.float64)
        np.testing.assert_allclose(pose[:3, :3] @ pose[:3, :3].T, np.eye(3), atol=TOLERANCE)
        with open(INIT) as f:
            numbers = [float(x) for x in f.read().split()]
        np.testing.assert_allclose(pose[:3, 3], numbers[:3], atol=TOLERANCE)
        t, tu = edgetrack.theta_u_of(pose)
        np.testing.assert_allclose(tu, numbers[3:], atol=TOLERANCE)
        np.testing.assert_allclose(edgetrack.pose_from_theta_u(t, tu), pose, atol=TOLERANCE)
        # The file's matrix made in double from the .pos values (Rodrigues), as a user's file is: a
        # pose printed from a fixed-point `real` is a rotation only to the real's step.
        theta = np.linalg.norm(numbers[3:])
        k = np.array(numbers[3:]) / theta
        cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        exact = np.eye(4)
        exact[:3, :3] = np.eye(3) + np.sin(theta) * cross + (1 - np.cos(theta)) * cross @ cross
        exact[:3, 3] = numbers[:3]
        matrix = write("pose.txt", "\n".join(" ".join("%.17g" % x for x in row) for row in exact) + "\n")
        np.testing.assert_allclose(edgetrack.read_pose(matrix), pose, atol=TOLERANCE)

    def test_errors_are_the_command_lines(self):
        missing = os.path.join(OUTPUT, "no_such_model.cao")
        with self.assertRaises(edgetrack.Error) as raised:
            edgetrack.load_model(missing)
        message = str(raised.exception)
        self.assertIsInstance(raised.exception, ValueError)
        self.assertEqual(len(message.splitlines()), 1)
        cli = os.environ.get("EDGETRACK_CLI")
        if cli:
            run = subprocess.run([cli, "track", "--model", missing, "--camera", CONFIG, "--init-pose", INIT, "--images",
                                  os.path.join(MBT, "cube", "image%04d.pgm"), "--last", "1"],
                                 capture_output=True, text=True)
            self.assertNotEqual(run.returncode, 0)
            self.assertIn(message, run.stderr)
        bad = write("bad_pose.pos", "0 0 0.5\n0 0 nan\n")
        with self.assertRaisesRegex(edgetrack.Error, r"bad_pose\.pos:2: "):
            edgetrack.read_pose(bad)
        with self.assertRaisesRegex(edgetrack.Error, "no_camera.xml"):
            edgetrack.read_camera_file(os.path.join(OUTPUT, "no_camera.xml"))


if __name__ == "__main__":
    unittest.main()
