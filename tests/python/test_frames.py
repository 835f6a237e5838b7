# SPDX-License-Identifier: BSD-3-Clause
"""Every layout, packed, with padded rows and as a crop of a larger buffer, tracked from numpy
gives bit for bit the poses the C++ API gives on the same bytes (track_raw_frames); and the
layouts built from the same grey values give the same poses as one another."""
import os
import subprocess
import unittest

import numpy as np

import edgetrack
from frames import CONFIG, INIT, MODEL, OUTPUT, cube_frame

FRAMES = 4
HELPER = os.environ.get("EDGETRACK_TRACK_RAW_FRAMES")
L = edgetrack.Layout


def layout_pixels(grey, layout, seed):
    """`grey` (H x W) in `layout`: colour channels all equal to it, RGB565 from its top bits,
    YUV with noise chroma; alpha is noise too (the tracker must not read it)."""
    h, w = grey.shape
    noise = np.random.default_rng(seed)
    if layout == L.GREY8:
        return grey.copy()
    if layout in (L.RGB24, L.BGR24):
        return np.repeat(grey[:, :, None], 3, axis=2)
    if layout in (L.RGBA32, L.BGRA32):
        alpha = noise.integers(0, 256, (h, w, 1), dtype=np.uint8)
        return np.concatenate([np.repeat(grey[:, :, None], 3, axis=2), alpha], axis=2)
    if layout == L.RGB565:
        g = grey.astype(np.uint16)
        return ((g >> 3) << 11) | ((g >> 2) << 5) | (g >> 3)
    if layout in (L.NV21, L.NV12, L.I420):
        return np.concatenate([grey, noise.integers(0, 256, (h // 2, w), dtype=np.uint8)])
    raise AssertionError(layout)


def placed(pixels, pad_bytes, offset_rows, offset_bytes):
    """`pixels` inside a larger uint8 buffer: each row `pad_bytes` longer, starting `offset_rows`
    rows and `offset_bytes` bytes in; returns the strided view and the bytes from its start."""
    rows = pixels.shape[0]
    row = pixels[0].nbytes
    stride = row + pad_bytes
    buffer = np.full((rows + offset_rows) * stride + offset_bytes, 0xA5, np.uint8)
    start = offset_rows * stride + offset_bytes
    view = np.lib.stride_tricks.as_strided(buffer[start:].view(pixels.dtype), shape=pixels.shape,
                                           strides=(stride,) + pixels.strides[1:], writeable=True)
    view[...] = pixels
    return view, buffer[start:], stride


CASES = [(layout, pad, rows, off) for layout in (L.GREY8, L.RGB24, L.BGR24, L.RGBA32, L.BGRA32, L.RGB565, L.NV21, L.NV12, L.I420)
         for pad, rows, off in ((0, 0, 0), (6, 0, 0), (34, 3, 16))]


class LayoutsAndStrides(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.model = edgetrack.load_model(MODEL)
        cls.config = edgetrack.read_config(CONFIG)
        cls.initial = edgetrack.read_pose(INIT)
        cls.greys = [cube_frame(k) for k in range(FRAMES)]

    def track(self, views, layout):
        tracker = edgetrack.Tracker(self.model, self.config, self.initial)
        return [tracker.track(v, layout=layout) for v in views]

    def test_each_layout_and_stride_equals_the_cpp_api(self):
        self.assertTrue(HELPER, "EDGETRACK_TRACK_RAW_FRAMES names the C++ helper")
        by_layout = {}
        for layout, pad, rows, off in CASES:
            with self.subTest(layout=layout.name, pad=pad, offset=(rows, off)):
                views, files = [], []
                for k, grey in enumerate(self.greys):
                    view, raw, stride = placed(layout_pixels(grey, layout, k), pad, rows, off)
                    self.assertEqual(view.strides[0], stride)
                    self.assertTrue(pad == 0 or not view.flags.c_contiguous)
                    path = os.path.join(OUTPUT, "frame_%s_%d_%d.raw" % (layout.name, pad, k))
                    raw.tofile(path)
                    views.append(view)
                    files.append(path)
                results = self.track(views, layout)
                h, w = self.greys[0].shape
                helper = subprocess.run([HELPER, MODEL, CONFIG, INIT, edgetrack_layout_name(layout), str(w), str(h),
                                         str(stride)] + files, capture_output=True, text=True)
                self.assertEqual(helper.returncode, 0, helper.stderr)
                expected = helper.stdout.split("\n")[:-1]
                got = [" ".join(float.hex(float(x)) for x in r.camera_from_model[:3].ravel()) + " " + r.status_name
                       for r in results]
                self.assertEqual(len(expected), FRAMES)
                for g, e in zip(got, expected):
                    self.assertEqual(g.split(), [normalise_hex(x) for x in e.split()])
                self.assertTrue(all(r.points_matched > 50 for r in results), "the frames are tracked, not vacuous")
                by_layout.setdefault(layout, []).append([r.camera_from_model.tobytes() for r in results])
        grey_poses = by_layout[L.GREY8][0]
        for layout, runs in by_layout.items():
            for run in runs:
                self.assertEqual(run, by_layout[layout][0], "%s: the same poses at every stride" % layout.name)
            if layout != L.RGB565:
                self.assertEqual(runs[0], grey_poses, "%s: the same poses as grey8 from the same grey" % layout.name)


def edgetrack_layout_name(layout):
    return {"GREY8": "grey8"}.get(layout.name, layout.name)


def normalise_hex(text):
    """C's %a and Python's float.hex spell a few numbers apart (0x0p+0 against 0x0.0p+0)."""
    try:
        return float.hex(float.fromhex(text))
    except ValueError:
        return text


if __name__ == "__main__":
    unittest.main()
