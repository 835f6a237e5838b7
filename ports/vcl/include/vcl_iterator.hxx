// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_iterator.hxx: the standard <iterator>; nothing left to instantiate.
#pragma once

#include "vcl_iterator.h"
