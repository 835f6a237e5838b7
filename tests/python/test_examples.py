# SPDX-License-Identifier: BSD-3-Clause
"""examples/python/evaluate.py as written: a sequence from `edgetrack synth` tracked from
Python and compared with its truth (track_sequence.py is run by test_tracking.py)."""
import os
import subprocess
import sys
import unittest

from frames import OUTPUT, SOURCE


class Examples(unittest.TestCase):
    def test_evaluate_a_generated_sequence(self):
        cli = os.environ.get("EDGETRACK_CLI")
        self.assertTrue(cli, "EDGETRACK_CLI names the edgetrack executable")
        seq = os.path.join(OUTPUT, "synth_seq")
        model = os.path.join(SOURCE, "data", "models", "cube60.cao")
        subprocess.run([cli, "synth", "--out", seq, "--model", model, "--frames", "12", "--supersample", "1"],
                       check=True, capture_output=True)
        run = subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "python", "evaluate.py"), model, seq],
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        lines = run.stdout.splitlines()
        self.assertEqual(len(lines), 13)
        summary = lines[-1].replace(",", "").split()
        self.assertEqual(summary[:2], ["12", "frames"])
        self.assertGreaterEqual(int(summary[2]), 10, lines[-1])
        mean_mm, mean_deg = float(summary[7]), float(summary[15])
        self.assertLess(mean_mm, 5.0, lines[-1])
        self.assertLess(mean_deg, 2.0, lines[-1])
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            refused = subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "python", "evaluate.py"), model,
                                      seq, "--plot", os.path.join(OUTPUT, "errors.png")], capture_output=True, text=True)
            self.assertNotEqual(refused.returncode, 0)
            self.assertIn("needs matplotlib", refused.stderr)


if __name__ == "__main__":
    unittest.main()
