#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The Python side of the binding's cost, as cpp_track_loop does it in C++: reads the frames
FIRST..LAST as numpy arrays, creates an edgetrack.Tracker, tracks the first TRACKED of them and
prints the mean time of one track() call in microseconds. Run with TRACKED = 0 it does all but
the tracking (results.sh counts instructions of both runs).
usage: bench.py MODEL CONFIG INIT PATTERN FIRST LAST TRACKED"""
import sys
import time

import numpy as np

import edgetrack


def read_pgm(path):
    """An 8-bit binary PGM without comments, as ViSP's sequences are."""
    with open(path, "rb") as f:
        header = []
        while len(header) < 4:
            header += f.readline().split()
        width, height = int(header[1]), int(header[2])
        return np.frombuffer(f.read(width * height), np.uint8).reshape(height, width)


def main():
    model_path, config_path, init_path, pattern, first, last, tracked = sys.argv[1:8]
    model, config = edgetrack.load_model(model_path), edgetrack.read_config(config_path)
    initial = edgetrack.read_pose(init_path)
    frames = [read_pgm(pattern % k) for k in range(int(first), int(last) + 1)]
    tracked = int(tracked)
    if tracked > len(frames):
        sys.exit("bench.py: only %d frames" % len(frames))
    tracker = edgetrack.Tracker(model, config, initial)
    ns = 0
    for frame in frames[:tracked]:
        begin = time.perf_counter_ns()
        tracker.track(frame)
        ns += time.perf_counter_ns() - begin
    if tracked:
        print("%.3f" % (ns / 1e3 / tracked))


if __name__ == "__main__":
    main()
