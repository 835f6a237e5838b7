# SPDX-License-Identifier: BSD-3-Clause
"""What the Python tests share: where the data and tools are, and ViSP's mbt/cube frames."""
import os

import numpy as np

import edgetrack

VISP = os.environ.get("EDGETRACK_VISP_IMAGES", "/usr/share/visp-images-data/ViSP-images")
MBT = os.path.join(VISP, "mbt")
MODEL, CONFIG, INIT = (os.path.join(MBT, name) for name in ("cube.cao", "cube.xml", "cube.0.pos"))
SOURCE = os.environ.get("EDGETRACK_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
OUTPUT = os.environ.get("EDGETRACK_TEST_OUTPUT", "/tmp/edgetrack-python-tests")
os.makedirs(OUTPUT, exist_ok=True)
# How near two computations of one pose come in this build's real (S47.16's step is 2^-16).
TOLERANCE = {"double": 1e-12, "float": 1e-5, "s40_23": 1e-5, "s47_16": 1e-4}[edgetrack.real]


def read_pgm(path):
    """An 8-bit binary PGM (P5) as an H x W uint8 array."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    assert fields[0] == b"P5" and int(fields[3]) == 255, path
    width, height = int(fields[1]), int(fields[2])
    return np.frombuffer(data, np.uint8, width * height, pos + 1).reshape(height, width)


def cube_frame(index):
    return read_pgm(os.path.join(MBT, "cube", "image%04d.pgm" % index))
