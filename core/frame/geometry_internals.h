// SPDX-License-Identifier: GPL-3.0-or-later
// What the frame's geometry files share: axis-aligned bounds of the oriented boxes frames are made
// of (beam bodies, joint voxels; the cheap first test before an exact one, for the frame's
// validation and its designer's sweeps) and the names of beams and joints in messages.
#pragma once

#include <string>

#include "analysis/vec3.h"
#include "desia/frame.h"

namespace desia::frame_geometry {

struct Aabb {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
};

Aabb boxBounds(const OrientedBox& box);
void include(Aabb& bounds, const Aabb& more);
bool boundsOverlap(const Aabb& a, const Aabb& b);
// `bounds` swept along an axis direction to infinity.
Aabb sweptBounds(Aabb bounds, const Vec3& direction);
Aabb cubeBounds(const FrameLayout& layout, int joint);
OrientedBox boxFromBounds(const Aabb& bounds);
// A segment's box: its axis, the section's sides on axes where possible, half a section longer at
// both ends.
OrientedBox segmentBox(const Vec3& a, const Vec3& b, double section);

// "beam 7", "joint 3": by their ids in the input.
std::string beamName(const Frame& frame, int beam);
std::string jointName(const Frame& frame, int joint);

}  // namespace desia::frame_geometry
