// SPDX-License-Identifier: GPL-3.0-or-later
// Frame structures (paper Section 5.3): beams joined by 3x3x3 voxel joints, and their designer.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "desia/model.h"
#include "desia/search.h"

namespace desia {

// Frame structures (paper Section 5.3): beams joined at joints, every joint an axis-aligned cube of
// 3x3x3 voxels. Every beam end enters the face of its joint cube whose normal is closest to the
// beam's end tangent, at that face's centre voxel, so a joint holds at most six beams. A part is
// one beam with the voxels it owns in the joint cubes at its two ends; parts touch only where
// voxels of different parts share a face, so every contact normal is an axis (the DBG test is
// exact, paper Section 3.2).

constexpr int kJointVoxelsPerSide = 3;
constexpr int kJointVoxelCount = 27;
constexpr int kMaxJointValence = 6;
// Beams and joints a frame may have (checked while reading, before anything is allocated).
constexpr int kMaxFrameBeams = 20000;
constexpr int kMaxFrameJoints = 20000;
constexpr int kMaxBeamPathPoints = 10000;

// Faces of a joint cube, numbered as in FrameInterlock's .fpuz files: 0 +x, 1 -x, 2 +y, 3 -y,
// 4 +z, 5 -z. Face f has axis f / 2 and points along + for even f.
const char* cubeFaceName(int face);  // "+x", "-x", ...
Vec3 cubeFaceNormal(int face);
// The face's centre voxel (where a beam enters), as an index x + 3y + 9z of the cube's voxels.
int faceCentreVoxel(int face);

struct FrameJoint {
  int id = 0;  // the id the user sees (1-based in files)
  Vec3 position{0, 0, 0};
};

struct FrameBeam {
  int id = 0;                       // the id the user sees
  int inputId = 0;                  // the beam's id in the design it came from (result documents), else = id
  std::array<int, 2> joints{0, 0};  // internal joint indices of its two ends
  std::vector<Vec3> path;           // interior points of a curved beam (polyline), none for a straight beam
};

struct Frame {
  std::vector<FrameJoint> joints;
  std::vector<FrameBeam> beams;
  double jointSize = 0;    // edge length of a joint cube; 0 = the default from the geometry
  double beamSection = 0;  // side of the beams' square section; 0 = the voxel size (jointSize / 3)
};

// A validated frame with what follows from its geometry.
struct FrameLayout {
  Frame frame;                                 // sizes resolved (never 0)
  double voxelSize = 0;                        // jointSize / 3
  std::vector<std::array<int, 2>> endFace;     // per beam, the face it enters at joints[0] and joints[1]
  std::vector<std::array<int, 6>> faceBeam;    // per joint, the beam entering each face, or -1
  std::vector<std::vector<int>> beamsAtJoint;  // per joint, its beams (sorted)
};

// The default joint cube: a fifth of the shortest beam (chord between its joints), and less than
// half the smallest distance (largest coordinate difference) between two joints, so cubes never
// overlap.
double defaultJointSize(const Frame& frame);

// Checks the frame and derives its layout. Throws BadInput naming `source`, the joint and the
// beams for: a beam whose ends are one joint or one point, two beams between the same joints (and
// along the same path), an end tangent that ties two faces, two beams through one face, valence
// above 6, joint cubes that overlap or touch, a path point inside a joint cube, a beam that
// crosses another beam or passes through a joint cube, a joint without beams, a frame that falls
// apart into groups, sizes out of range (beam section above the voxel size).
FrameLayout layoutFrame(Frame frame, const std::string& source);

// The beams (internal indices, sorted) that are cut points of the parts-graph (nodes = beams,
// adjacent when they share a joint): taking one away splits the others, and no joints can make
// such a frame interlocking (paper Section 5.2, Fig. 18, which carries over to frames).
std::vector<int> frameCutBeams(const FrameLayout& layout);

// Voxel labels of every joint cube: index x + 3y + 9z (x fastest, as in .puz and .fpuz), value =
// internal index of the beam owning the voxel, or -1 (not assigned yet, during design only).
using JointLabels = std::array<int, kJointVoxelCount>;

// Throws BadInput unless every voxel is owned by a beam at that joint, every beam owns its face
// centre voxel, and the voxels of each beam at a joint are face-connected.
void validateJointLabels(const FrameLayout& layout, const std::vector<JointLabels>& labels, const std::string& source);

// The assembly the interlocking tests read: parts = beams (part k = beam `partOrder[k]`, id and
// name from the beam), one contact per pair of parts and axis normal where their voxels share
// faces (area = the number of faces).
Assembly frameAssembly(const FrameLayout& layout, const std::vector<JointLabels>& labels,
                       const std::vector<int>& partOrder);

// An oriented box: centre, orthonormal axes, half extents along them.
struct OrientedBox {
  Vec3 centre{0, 0, 0};
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  Vec3 halfExtents{0, 0, 0};
};

// The body of a beam as boxes of its square section along its centreline: from the centre of the
// face it enters at one joint, straight out of that face for half a voxel (when it then turns),
// through its path, to the face at the other end. Each box reaches half a section further at both
// ends, so bends are covered. Coordinates in the frame's units.
std::vector<OrientedBox> beamBodyBoxes(const FrameLayout& layout, int beam);
// The centreline's length from face to face (the cut length of a straight beam).
double beamBodyLength(const FrameLayout& layout, int beam);
// The box of voxel `voxel` (x + 3y + 9z) of joint `joint`.
OrientedBox jointVoxelBox(const FrameLayout& layout, int joint, int voxel);

// Does `moving`, translated by t * direction for some t > 0 (to infinity), overlap `fixed` with
// positive depth? Touching faces do not count; sliding along them does not either. Exact for boxes
// (separating axes over the whole motion).
bool sweptBoxesCollide(const OrientedBox& moving, const Vec3& direction, const OrientedBox& fixed);

// Can beam `beam`, with its voxels, leave along `direction` (unit axis) while the beams flagged in
// `present` stay (their bodies and voxels)? Returns "" or what it hits ("beam 4", "a voxel of beam
// 7 at joint 3").
std::string frameSweepObstacle(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam,
                               const Vec3& direction, const std::vector<bool>& present);

// The closed mesh (in the frame's units) of one beam: when its body boxes are axis-aligned (every
// frame on a grid), the exact union of its body boxes and its joint voxels, one solid whose every
// edge is in exactly two triangles (surfaceOfBoxUnion); a beam with slanted boxes (a curved path)
// is one closed shell per body box and voxel group, overlapping where they meet (the exports
// union them in 3D: solidBooleanMesh in desia/plate.h, core/io/frame/frame_export.cpp).
TriangleMesh beamPartMesh(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam);
// An oriented box as a closed mesh of 12 triangles, wound outward.
TriangleMesh orientedBoxMesh(const OrientedBox& box);
// The body of a beam as a maker cuts it (pieces-obj): for axis-aligned bodies the body boxes cut
// back to the faces of the beam's joint cubes (a straight beam: the stick of beamBodyLength), one
// solid that shares no volume with the joint pieces; a curved beam's slanted boxes as they are.
TriangleMesh beamBodyPieceMesh(const FrameLayout& layout, int beam);
// The joint piece glued to a beam's end at `joint`: the voxels it owns there (face voxel
// included), one closed shell; empty when it owns none there.
TriangleMesh beamJointPieceMesh(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam,
                                int joint);

// Designing the voxel joints of an interlocking frame structure (paper Section 5.3): the key beam,
// the order in which the other beams are taken out, the axis each one leaves along, and which beam
// owns each voxel of each joint cube. Same shape as the plate planner (plate.h).

struct FrameDesignOptions {
  uint64_t seed = 1;
  int candidates = 2;            // children kept per node (the paper's m; FrameInterlock keeps 2)
  DesignLimits limits{60, 1'000'000, {}, false};  // time, nodes, progress and cancellation
};

struct FrameDesignResult {
  DesignStatus status = DesignStatus::NotFound;
  std::string message;              // one sentence for the user
  std::vector<int> order;           // beam indices: the key first, the last beam last
  std::vector<Vec3> directions;     // axis direction order[k] leaves along (none for the last beam)
  std::vector<JointLabels> labels;  // per joint, the owning beam of each voxel (internal indices)
  Assembly assembly;                // parts = beams in `order` (part 1 = key), voxel contacts
  DesignProgress progress;
};

// One step of a frame design: the beam taken (an index), the axis direction it leaves along, and
// the free voxels it takes at its two joints (frame.beams[beam].joints[0] and [1]; voxel indices
// 0..26, x fastest) besides the face voxels it owns from the start.
struct FrameDesignStep {
  int beam = 0;
  Vec3 direction{0, 0, 0};
  std::array<std::vector<int>, 2> voxels;
};

// Step-by-step design (as the voxel and plate sessions, paper Algorithm 1 by hand): the beams
// taken so far, the ranked children of the current node (the designer's, options.candidates per
// node, more for the key), choose one, go back. A choice that completes the design is accepted
// only if it verifies (frameDesignFailure). Deterministic for a seed and a sequence of calls.
class FrameDesignSession {
 public:
  // Throws BadInput for a frame no joints can make interlocking (a cut-point beam, named; fewer
  // than 3 beams).
  FrameDesignSession(FrameLayout layout, const FrameDesignOptions& options);
  ~FrameDesignSession();
  FrameDesignSession(const FrameDesignSession&) = delete;
  FrameDesignSession& operator=(const FrameDesignSession&) = delete;

  const std::vector<FrameDesignStep>& steps() const;  // the key first
  int targetBeams() const;
  bool complete() const;  // every beam placed and the design verified
  // The verified result once complete (status Success), else NotFound saying how far it got.
  const FrameDesignResult& result() const;

  int childCount();                     // ranked children of the current node (generated on first call)
  FrameDesignStep childPreview(int n);  // the n-th child (0 = best ranked), without moving
  // Moves to the n-th child. Throws BadInput when n is out of range, or when that child completes
  // a design that fails verification (the child is dropped from the list; the message says why).
  void chooseChild(int n);
  bool next();  // moves to the best child that works; false when none does (then go back)
  bool back();  // moves to the parent; false at the root
  // "Finish automatically from here": designFrame's restarted search run below the current node,
  // so the beams taken so far stay, first in the order with their directions and voxels; restarts
  // re-seed below this node. A success is verified like any design. The session does not move.
  // Deterministic: the same path and seed give the same result.
  FrameDesignResult finish(const DesignLimits& limits);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Designs the joints of a frame whose parts-graph has no cut point (otherwise: status CutPoint,
// naming the beam). Deterministic for a seed. A success has been verified (frameDesignFailure).
FrameDesignResult designFrame(const FrameLayout& layout, const FrameDesignOptions& options = {});

// Why a complete design fails, or "" when it passes: the assembly of the joint voxels is
// interlocking by the DBG test with order[0] as the only movable part, and each beam, with its
// body and voxels, leaves the beams after it along its direction without hitting any of their
// bodies or voxels (swept), in order.
std::string frameDesignFailure(const FrameLayout& layout, const std::vector<JointLabels>& labels,
                               const std::vector<int>& order, const std::vector<Vec3>& directions);

}  // namespace desia
