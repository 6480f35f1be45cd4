// SPDX-License-Identifier: GPL-3.0-or-later
#include "plate/joints/halved.h"

#include "analysis/vec3.h"
#include "plate/joints/joint_geometry.h"
#include "plate/plate_shape.h"

namespace desia {
namespace {

class SlotJointCut final : public JointCut {
 public:
  explicit SlotJointCut(const SlotCut& slot) : slot_(slot) {}
  void addTo(const std::vector<Plate>&, const JointCutOptions&, PlateCuts& cuts) const override {
    cuts.removed[slot_.plate].push_back(slot_.rectangle);
  }

 private:
  SlotCut slot_;
};

}  // namespace

std::vector<SlotCut> halvedSlots(const std::vector<Plate>& plates, const PlateContact& crossing, int mover,
                                 const Vec3& d, double clearance) {
  const int other = crossing.a == mover ? crossing.b : crossing.a;
  const Vec3& line = crossing.edgeDirection;
  const double sign = dot(d, line) > 0 ? 1 : -1;
  const double middle = (crossing.crossingFrom + crossing.crossingTo) / 2;
  // Far enough past the crossing's ends to run out of the outline there (it ends with the crossing).
  const double out = crossing.crossingTo - crossing.crossingFrom + kMortiseMargin;
  auto slot = [&](int plate, int across, double towards) {
    const Vec3 axis = plateThicknessAxis(plates[across]);
    const double width = plateThickness(plates[across]);
    // From the middle of the crossing out past its end `towards` (+1: +line), across the other
    // plate's thickness (its first face is on crossingPoint's plane) plus the clearance.
    const double start = middle, end = towards > 0 ? crossing.crossingTo + out : crossing.crossingFrom - out;
    auto at = [&](double t, double w) { return plus(crossing.crossingPoint, plus(scaled(line, t), scaled(axis, w))); };
    return SlotCut{plate,
                   {at(start, -clearance / 2), at(end, -clearance / 2), at(end, width + clearance / 2),
                    at(start, width + clearance / 2)}};
  };
  // The mover's slot opens behind it (it slides off the other plate forwards); the other's ahead.
  return {slot(mover, other, -sign), slot(other, mover, sign)};
}

CutFootprint slotFootprint(const SlotCut& slot) { return {slot.plate, 3, slot.rectangle}; }

std::shared_ptr<const JointCut> jointCut(const SlotCut& slot) { return std::make_shared<SlotJointCut>(slot); }

}  // namespace desia
