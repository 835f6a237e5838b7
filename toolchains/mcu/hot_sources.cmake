# SPDX-License-Identifier: BSD-3-Clause
# The bare-metal tree is built for size (-Os, toolchains/cortex-m3.cmake: flash is the budget). At
# -Os GCC calls fixed64's +, * and comparisons instead of inlining them, and a frame is far over the
# issue's 2.0 M instructions; these sources, where a frame spends its instructions, are built for
# size too but with FIXEDPOINT_FORCE_INLINE, which forces that arithmetic (and geometry.h's small
# vector operations) inline (real/fixed64.h). Chosen from the per-function counts of the tracked
# frames (toolchains/qemu/count-insns.sh --profile), by the object each function was linked from,
# and from the calls to fixed64's operators each object makes. -O2 (with inlining limits near
# -O3's) took about twice their flash for a few per cent fewer instructions.
set(EDGETRACK_MCU_FRAME_OPTIONS -Os -DFIXEDPOINT_FORCE_INLINE
    CACHE STRING "Compile options of the bare-metal sources where a frame spends its instructions")
# raster.cpp (the triangles' and lines' set-up; their per-pixel walks are raster.h's, inlined where
# they plot) is not: listed, it took 2.7 KB more flash for 6.5 K fewer instructions a frame.
# Nor is excluded_pull.cpp, the drift check's gate (once a frame, its sums over the matches
# fixed64's dot_product): kept apart from pose_uncertainty.cpp, it took 2.8 KB less for 2.8 K more
# instructions a frame with the check on.
set(edgetrack_hot_tracker moving_edges pose_uncertainty edge_id_buffer contrast_memory edge_support thin_lines)
list(TRANSFORM edgetrack_hot_tracker REPLACE "(.+)" "${PROJECT_SOURCE_DIR}/tracker/src/\\1.cpp")
set_source_files_properties(${edgetrack_hot_tracker} DIRECTORY ${PROJECT_SOURCE_DIR}/tracker
                            PROPERTIES COMPILE_OPTIONS "${EDGETRACK_MCU_FRAME_OPTIONS}")
# The pose's loops over the matches: built for speed, -O2 with the arithmetic forced inline as above
# (-O2's inlining limits raised near -O3's instead took 8.3 KB more for 2 K fewer instructions a
# frame). Built as the sources above, it was 16 KB smaller and the tracker firmware's frames just
# over 2.0 M instructions (2002243 a frame, the 20 generated frames).
set(EDGETRACK_MCU_FAST_OPTIONS -O2 -DFIXEDPOINT_FORCE_INLINE
    CACHE STRING "Compile options of the bare-metal sources built for speed")
# Link-time optimisation of libtracker in the tracker firmwares (docs/MCU.md, "Flash"): the
# tracker firmware 286.8 KB without it, 255.4 KB with it, the pose solver then built as the frames'
# other sources (-O2 took 5.5 KB more for 6.9 K fewer instructions a frame: over the 256 KB). One
# partition: 0.5 KB less than GCC's default partitions.
option(EDGETRACK_MCU_LTO "Link-time optimisation of libtracker in the tracker firmwares" ON)
if(EDGETRACK_MCU_LTO)
  # The tracker's unit tests too, so that they run the link-time code the firmwares ship.
  set_property(TARGET tracker tracker_firmware tracker_firmware_cube_xml tracker_test_all
               PROPERTY INTERPROCEDURAL_OPTIMIZATION ON)
  set_property(TARGET tracker_firmware tracker_firmware_cube_xml APPEND PROPERTY LINK_OPTIONS -flto-partition=none)
  # GCC 12.2's link-time modref analysis: with it, edge_model.cpp at -Os put circles and cylinder
  # outlines in the wrong place (tracker_test_contours: no circle points sampled); without it, or
  # without link-time constant propagation (-fno-ipa-cp), or at -O2, right. It follows what the link
  # inlines around edge_model's sin and cos (on_circle), not their code, which has no type punning
  # or aliasing to get wrong: some trees pass with it on, so it stays off until GCC's fault is reduced.
  target_compile_options(tracker PRIVATE -fno-ipa-modref -ffat-lto-objects)
  # The other images (the command line, the tests) link libtracker's machine code, as without
  # link-time optimisation: optimised at the link, the command line's frames called fixed64's
  # conversion from double (soft float) where its constants were folded before.
  target_link_options(tracker INTERFACE $<$<NOT:$<BOOL:$<TARGET_PROPERTY:INTERPROCEDURAL_OPTIMIZATION>>>:-fno-lto>)
  set(edgetrack_pose_solver_options ${EDGETRACK_MCU_FRAME_OPTIONS})
else()
  set(edgetrack_pose_solver_options ${EDGETRACK_MCU_FAST_OPTIONS})
endif()
set_source_files_properties(${PROJECT_SOURCE_DIR}/tracker/src/pose_solver.cpp DIRECTORY ${PROJECT_SOURCE_DIR}/tracker
                            PROPERTIES COMPILE_OPTIONS "${edgetrack_pose_solver_options}")
# The pose's Levenberg-Marquardt (MINPACK, and through vnl for the command line), instantiated on `real`.
set_source_files_properties(${PROJECT_SOURCE_DIR}/ports/netlib/instances/minpack+real-.cxx
                            DIRECTORY ${PROJECT_SOURCE_DIR}/ports/netlib
                            PROPERTIES COMPILE_OPTIONS "${EDGETRACK_MCU_FRAME_OPTIONS}")
set_source_files_properties(${PROJECT_SOURCE_DIR}/ports/vnl/instances/algo/vnl_levenberg_marquardt+real-.cxx
                            DIRECTORY ${PROJECT_SOURCE_DIR}/ports/vnl
                            PROPERTIES COMPILE_OPTIONS "${EDGETRACK_MCU_FRAME_OPTIONS}")
