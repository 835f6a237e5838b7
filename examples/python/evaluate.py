#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tracks a sequence made by `edgetrack synth` and compares the poses with its truth:

    evaluate.py MODEL SEQUENCE_DIR [--plot FILE.png]

SEQUENCE_DIR holds what `edgetrack synth --out SEQUENCE_DIR` writes (frames/frame%04d.ppm,
truth.csv, first.pos, camera.xml). Prints each frame's translation error (mm) and rotation error
(degrees) and their summary; --plot draws both against the frame number with matplotlib (when
installed)."""
import argparse
import csv
import os
import sys

import numpy as np

import edgetrack
from track_sequence import read_frame


def rotation_error_deg(estimate, truth):
    r = estimate[:3, :3] @ truth[:3, :3].T
    return np.degrees(np.arccos(np.clip((np.trace(r) - 1) / 2, -1.0, 1.0)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model")
    parser.add_argument("sequence")
    parser.add_argument("--plot", help="write the errors' plot (needs matplotlib)")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        plt = None
    if args.plot and plt is None:
        raise SystemExit("evaluate: --plot needs matplotlib (python3-matplotlib)")
    seq = args.sequence
    try:
        tracker = edgetrack.Tracker(edgetrack.load_model(args.model), edgetrack.read_config(os.path.join(seq, "camera.xml")),
                                    edgetrack.read_pose(os.path.join(seq, "first.pos")))
    except edgetrack.Error as error:
        raise SystemExit("evaluate: %s" % error)
    with open(os.path.join(seq, "truth.csv")) as f:
        truth = [row for row in csv.DictReader(f)]
    frames, t_err, r_err, statuses = [], [], [], []
    for row in truth:
        index = int(row["frame"])
        frame, layout = read_frame(os.path.join(seq, "frames", "frame%04d.ppm" % index))
        result = tracker.track(frame, layout=layout)
        true_pose = edgetrack.pose_from_theta_u([float(row[k]) for k in ("tx", "ty", "tz")],
                                                [float(row[k]) for k in ("tux", "tuy", "tuz")])
        frames.append(index)
        t_err.append(1000 * np.linalg.norm(result.translation - true_pose[:3, 3]))
        r_err.append(rotation_error_deg(result.camera_from_model, true_pose))
        statuses.append(result.status_name)
        print("frame %d: %.3f mm, %.3f deg, %s" % (index, t_err[-1], r_err[-1], statuses[-1]))
    t_err, r_err = np.array(t_err), np.array(r_err)
    print("%d frames, %d tracked: translation error mean %.3f mm, max %.3f mm; rotation error mean %.3f deg, max %.3f deg"
          % (len(frames), statuses.count("tracked"), t_err.mean(), t_err.max(), r_err.mean(), r_err.max()))
    if args.plot:
        figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
        top.plot(frames, t_err)
        top.set_ylabel("translation error (mm)")
        bottom.plot(frames, r_err)
        bottom.set_ylabel("rotation error (deg)")
        bottom.set_xlabel("frame")
        figure.savefig(args.plot)
        print("wrote %s" % args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
