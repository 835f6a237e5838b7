# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the scripts that read ViSP's example images (Debian's visp-images-data): where they
# are, as CMake's EDGETRACK_VISP_IMAGES says (its tests pass it in the environment) or, for a
# script run by hand, where Debian installs them.
visp_images=${EDGETRACK_VISP_IMAGES:-/usr/share/visp-images-data/ViSP-images}
