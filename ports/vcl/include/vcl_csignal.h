// SPDX-License-Identifier: BSD-3-Clause
/// Mirrors VXL's vcl/vcl_csignal.h: today only the standard <csignal>, kept so that code written
/// against older VXL includes unchanged.
#pragma once

#include <csignal>

#include "vcl_compiler.h"
