# SPDX-License-Identifier: BSD-3-Clause
"""edgetrack: markerless edge-based 3D tracking of a wireframe model, frames read in place
from numpy arrays (docs/PYTHON.md)."""
from ._edgetrack import *  # noqa: F401,F403
from ._edgetrack import Error, real  # noqa: F401
from . import _edgetrack

__all__ = [name for name in dir(_edgetrack) if not name.startswith("_")]
