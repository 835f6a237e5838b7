# SPDX-License-Identifier: BSD-3-Clause
# Where `cmake --install` and the .deb files put each part, relative to the prefix; included
# before app/, whose installed command line finds the models from its own location.
include(GNUInstallDirs)
set(EDGETRACK_INSTALL_PORTS_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/edgetrack/ports)
set(EDGETRACK_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/edgetrack)
set(EDGETRACK_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/edgetrack)
file(RELATIVE_PATH EDGETRACK_INSTALL_DATADIR_FROM_BINDIR /${CMAKE_INSTALL_BINDIR} /${EDGETRACK_INSTALL_DATADIR})
# `edgetrack compare` runs its ViSP child and `edgetrack` loads its host extras plugin from here, relative to its own executable, in the
# build tree as installed.
set(EDGETRACK_INSTALL_LIBEXECDIR ${CMAKE_INSTALL_LIBEXECDIR}/edgetrack)
file(RELATIVE_PATH EDGETRACK_INSTALL_LIBEXECDIR_FROM_BINDIR /${CMAKE_INSTALL_BINDIR} /${EDGETRACK_INSTALL_LIBEXECDIR})
file(RELATIVE_PATH EDGETRACK_INSTALL_LIBDIR_FROM_BINDIR /${CMAKE_INSTALL_BINDIR} /${CMAKE_INSTALL_LIBDIR})
file(RELATIVE_PATH EDGETRACK_INSTALL_LIBDIR_FROM_LIBEXECDIR /${EDGETRACK_INSTALL_LIBEXECDIR} /${CMAKE_INSTALL_LIBDIR})
