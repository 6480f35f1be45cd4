// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` of a designed frame: each beam swept along its direction in the planned order.
#include "io/frame/frame_check.h"

#include "desia/formats.h"
#include "desia/frame.h"

namespace desia {

std::optional<ShapeRemovalCheck> frameShapeRemoval(const AssemblyDocument& document) {
  const FrameDocument frame = frameFromAssemblyDocument(document);
  if (frame.labels.empty() || frame.directions.empty()) return std::nullopt;
  ShapeRemovalCheck check;
  check.checked = "each beam, its body and joint voxels, swept along its axis in the planned order";
  std::vector<bool> present(frame.layout.frame.beams.size(), true);
  for (size_t k = 0; k < frame.directions.size() && k < frame.order.size(); ++k) {
    const int beam = frame.order[k];
    const std::string obstacle = frameSweepObstacle(frame.layout, frame.labels, beam, frame.directions[k], present);
    if (!obstacle.empty()) {
      check.failure = "beam " + std::to_string(frame.layout.frame.beams[beam].id) + " cannot leave along " +
                      directionLabel(frame.directions[k]) + ": it hits " + obstacle;
      break;
    }
    present[beam] = false;
  }
  return check;
}


}  // namespace desia
