# SPDX-License-Identifier: BSD-3-Clause
# The bare-metal tree is built for size (-Os, toolchains/cortex-m3.cmake: flash is the budget);
# these sources, where a frame spends its instructions, are built for speed. fixed64's arithmetic
# is inline in its header, and at -Os each +, * and / of the frame loop becomes a call. Chosen from
# the per-function counts of the tracked frames (toolchains/qemu/count-insns.sh --profile), by the
# object each function was linked from. -O2 with inlining limits near -O3's: plain -O2 leaves
# fixed64's * and / as calls; -O3 inlines as much but its loop transformations cost more flash.
# Sources with fewer of the frame's instructions (the control points, the Edge-ID raster, the
# rotations, the tracker's own loop) are left for size: their flash outweighs their instructions.
set(EDGETRACK_MCU_HOT_OPTIONS -O2 --param=max-inline-insns-single=200 --param=max-inline-insns-auto=40
    CACHE STRING "Compile options of the bare-metal sources built for speed")
set(edgetrack_hot_tracker pose_solver moving_edges pose_uncertainty edge_id_buffer contrast_memory edge_support)
list(TRANSFORM edgetrack_hot_tracker REPLACE "(.+)" "${PROJECT_SOURCE_DIR}/tracker/src/\\1.cpp")
set_source_files_properties(${edgetrack_hot_tracker} DIRECTORY ${PROJECT_SOURCE_DIR}/tracker
                            PROPERTIES COMPILE_OPTIONS "${EDGETRACK_MCU_HOT_OPTIONS}")
# The pose's Levenberg-Marquardt (MINPACK, and through vnl for the command line), instantiated on `real`.
set_source_files_properties(${PROJECT_SOURCE_DIR}/ports/netlib/instances/minpack+real-.cxx
                            DIRECTORY ${PROJECT_SOURCE_DIR}/ports/netlib
                            PROPERTIES COMPILE_OPTIONS "${EDGETRACK_MCU_HOT_OPTIONS}")
set_source_files_properties(${PROJECT_SOURCE_DIR}/ports/vnl/instances/algo/vnl_levenberg_marquardt+real-.cxx
                            DIRECTORY ${PROJECT_SOURCE_DIR}/ports/vnl
                            PROPERTIES COMPILE_OPTIONS "${EDGETRACK_MCU_HOT_OPTIONS}")
