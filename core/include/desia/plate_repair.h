// SPDX-License-Identifier: GPL-3.0-or-later
// Repairing a plate structure whose parts-graph has a cut point (paper Section 5.2, Fig. 18): no
// joints can make it interlocking, but an added part that joins the groups the cut point holds
// together can (the paper's CHAIR gets one bar).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "desia/plate.h"

namespace desia {

struct PlateRepair {
  std::vector<Plate> plates;  // the input's plates, then the added bars (ids after the largest)
  std::vector<int> added;     // indices of the added bars in `plates`
  std::string message;        // what was added, for the user
};

// Proposes bars that remove every cut point: for the groups a cut point separates, a bar lying
// flat against a face of a plate in one group and a face of a plate in another that share one
// plane (a leg's outer face and the edge of a back, say), outside both, spanning from one to the
// other across the width they share, as thick as the thinner plate, clear of every other plate.
// The smallest such bar is taken first; repeated until no cut point is left. Nothing when the
// structure has no cut point or no such bar exists.
std::optional<PlateRepair> proposeCutPointRepair(const std::vector<Plate>& plates, const PlateOptions& options = {});

}  // namespace desia
