// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_stlfwd.h: the standard containers, for code that used it to name them.
#pragma once

#ifdef vcl_stlfwd_h_
#error "edgetrack's drop-in vcl_stlfwd.h and VXL's cannot be mixed in one translation unit (see docs/INSTALL.md)"
#endif

#include <deque>
#include <list>
#include <map>
#include <queue>
#include <set>
#include <stack>
#include <string>
#include <vector>

#include "vcl_compiler.h"
