// SPDX-License-Identifier: GPL-3.0-or-later
// Which of a planned result's joints no made joint family can make (issue 26): when 'auto' falls
// back to the paper's plan (paper Section 5.2, nothing cut), the user is told which plates and
// edges lack a joint that can be cut or milled, and how they meet there.
#pragma once

#include <string>
#include <vector>

#include "desia/plate.h"

namespace desia {

// The planned joints (mover leaving along its direction) for which no cut or milled family has a
// joint on the pair's contacts, each as "plate 3 (side) and plate 5 (roof): edge to edge, their
// planes 41.8 degrees apart, plate 3 leaving at 90.0 degrees to their edge and 48.2 degrees to the
// contact's normal (the plan's mortise-tenon)", in the joints' order.
std::vector<std::string> jointsNothingMakes(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                            const std::vector<PlateJoint>& planned, const JointCutOptions& options);

// One sentence for the user: how many of the planned joints lack a made joint, the first
// `shown` of them named, or "" when every one has one.
std::string jointsNothingMakesSentence(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                       const std::vector<PlateJoint>& planned, const JointCutOptions& options,
                                       size_t shown = 6);

}  // namespace desia
