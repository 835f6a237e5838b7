#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tracks a model through numbered frames and prints the pose and status of each, as
`edgetrack track` does:

    track_sequence.py MODEL CAMERA.xml INIT.pos 'FRAMES%04d.pgm' FIRST LAST [--poses OUT.csv] [--overlay DIR]

PGM (grey) and PPM (colour) frames are read with numpy, or with OpenCV's Python module when it
is installed; --poses writes the CSV columns of `edgetrack track --poses`; --overlay draws the
control points on each frame with OpenCV (when installed)."""
import argparse
import os
import sys

import numpy as np

import edgetrack

try:
    import cv2
except ImportError:
    cv2 = None


def read_netpbm(path):
    """A binary 8-bit PGM (H x W) or PPM (H x W x 3, RGB) as a numpy array."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while pos < len(data) and data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while end < len(data) and not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    kind, width, height, top = fields[0], int(fields[1]), int(fields[2]), int(fields[3])
    if kind not in (b"P5", b"P6") or top != 255:
        raise SystemExit("%s: not an 8-bit binary PGM or PPM" % path)
    channels = 3 if kind == b"P6" else 1
    size = width * height * channels
    if len(data) < pos + 1 + size:
        raise SystemExit("%s: the file ends before its %dx%d pixels" % (path, width, height))
    pixels = np.frombuffer(data, np.uint8, size, pos + 1)
    return pixels.reshape((height, width, 3) if channels == 3 else (height, width))


def read_frame(path):
    """The frame and its layout: grey, or colour (OpenCV reads BGR, numpy RGB)."""
    if cv2 is not None:
        frame = cv2.imread(path, cv2.IMREAD_UNCHANGED)
        if frame is None:
            raise SystemExit("%s: cannot read the image" % path)
        return frame, (edgetrack.Layout.GREY8 if frame.ndim == 2 else edgetrack.Layout.BGR24)
    frame = read_netpbm(path)
    return frame, (edgetrack.Layout.GREY8 if frame.ndim == 2 else edgetrack.Layout.RGB24)


def draw_overlay(frame, layout, result, path):
    image = frame.copy() if layout == edgetrack.Layout.BGR24 else cv2.cvtColor(frame, cv2.COLOR_GRAY2BGR)
    for x, y in result.sampled_points:
        cv2.circle(image, (int(round(x)), int(round(y))), 2, (255, 128, 0), -1)
    for (x, y), outlier in zip(result.matched_points, result.outliers):
        cv2.circle(image, (int(round(x)), int(round(y))), 2, (0, 0, 255) if outlier else (0, 255, 0), -1)
    cv2.imwrite(path, image)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model")
    parser.add_argument("camera")
    parser.add_argument("init")
    parser.add_argument("frames", help="printf pattern of the frame files, as 'seq/frame%%04d.pgm'")
    parser.add_argument("first", type=int)
    parser.add_argument("last", type=int)
    parser.add_argument("--poses", help="write the poses CSV of `edgetrack track --poses`")
    parser.add_argument("--overlay", help="write each frame with its control points drawn (needs OpenCV)")
    args = parser.parse_args()
    if args.overlay and cv2 is None:
        raise SystemExit("track_sequence: --overlay needs OpenCV's Python module (python3-opencv)")
    try:
        tracker = edgetrack.Tracker(edgetrack.load_model(args.model), edgetrack.read_config(args.camera),
                                    edgetrack.read_pose(args.init))
    except edgetrack.Error as error:
        raise SystemExit("track_sequence: %s" % error)
    poses = open(args.poses, "w") if args.poses else None
    if poses:
        poses.write("frame,tx,ty,tz,tux,tuy,tuz,points,ms,status,edge_angle_deg\n")
    if args.overlay:
        os.makedirs(args.overlay, exist_ok=True)
    for index in range(args.first, args.last + 1):
        frame, layout = read_frame(args.frames % index)
        try:
            result = tracker.track(frame, layout=layout)
        except edgetrack.Error as error:
            raise SystemExit("track_sequence: frame %d: %s" % (index, error))
        t, tu = result.translation, result.theta_u
        print("frame %d: t = %s m, theta-u = %s rad, %s (%s), %d points, %.3f ms" % (
            index, np.array2string(t, precision=5), np.array2string(tu, precision=5), result.status_name,
            result.reason_name, result.points_matched, result.ms))
        if poses:
            poses.write("%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.3f,%s,%.2f\n" % (
                (index,) + tuple(t) + tuple(tu) + (result.points_matched, result.ms, result.status_name,
                                                   result.measures.gradient_angle_deg)))
        if args.overlay:
            draw_overlay(frame, layout, result, os.path.join(args.overlay, "frame%04d.png" % index))
    if poses:
        poses.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
