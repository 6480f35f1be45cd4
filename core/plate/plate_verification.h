// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces of a plate plan's verification that the designer also uses at every node: the two
// interlocking tests and the removal order on a model, and the sweep of each plate past the
// plates still in place. The whole verification (verifyJointedPlates, verifyPlannedPlates) is in
// desia/plate.h.
#pragma once

#include <string>
#include <vector>

#include "desia/model.h"
#include "desia/plate.h"

namespace desia {

// Why a complete plan fails, or "" when it passes: both interlocking tests with the key (part 0)
// as the only movable part (the DBG test is only necessary on non-orthogonal joints, so the LP
// test has the last word), and every part free to leave the ones after it along its direction
// (part k leaves k-th along directions[k]).
std::string planFailure(const Assembly& model, const std::vector<Vec3>& directions);

// The first plate that, swept along its direction, runs into a plate still in place, as a
// sentence, or "" (plates[order[k]] leaves k-th along directions[k]). `skip(a, b)` (positions in
// `order`) names pairs not to sweep (crossing plates whose slots are not cut). `hitPosition`,
// when given, gets the position in `order` of the plate run into (-1 when none is).
std::string sweepFailure(const std::vector<Plate>& plates, const std::vector<int>& order,
                         const std::vector<Vec3>& directions, double tolerance, int* hitPosition = nullptr,
                         const std::vector<std::pair<int, int>>& skip = {});

}  // namespace desia
