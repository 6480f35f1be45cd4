// SPDX-License-Identifier: GPL-3.0-or-later
// All of desia's public API: include this one header (or the few a program needs).
#pragma once

#include "desia/analysis.h"
#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/mesh.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "desia/search.h"
#include "desia/tolerances.h"
#include "desia/version.h"
#include "desia/voxel.h"
