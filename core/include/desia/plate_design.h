// SPDX-License-Identifier: GPL-3.0-or-later
// Designing the joints of an interlocking plate structure (paper Section 5.2): the key, the order
// in which the other plates are taken out, the direction each one leaves in, the joint each pair
// of touching plates gets, and the joints cut into the plates (core/plate/joints/). A result is
// verified on the jointed plates themselves: their contacts computed from the geometry, both
// interlocking tests, and each plate swept out along its direction past the plates still in place.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "desia/assembly.h"
#include "desia/design_search.h"
#include "desia/plate.h"

namespace desia {

// A share of a length: numerator / denominator of it. Kept as two numbers so that a third is the
// length divided by 3, to the last bit.
struct LengthShare {
  double numerator = 1, denominator = 1;
  double of(double length) const { return numerator * length / denominator; }
};

// A sliding dovetail (JointType::Dovetail, paper Fig. 2, right).
struct DovetailSizes {
  double slope = 1.0 / 6;        // how far each flank leans in, mm per mm of depth (1 in 6)
  LengthShare depth{1, 3};       // the housing's depth, of the housing plate's thickness (housings
                                 // from both faces leave the rest between them)
  LengthShare width{2, 3};       // the tongue's width at the housing's floor, of the tongue plate's thickness
  double narrowestNeck = 2;      // mm: the tongue's least width at the face; narrower, no dovetail
  double stop = 10;              // mm: the housing stops at least this far (and at least the housing
                                 // plate's thickness) before the contact's closed end
};

// A tenon across a mitre (JointType::MitreTenon, paper Fig. 16a).
struct MitreTenonSizes {
  LengthShare width{1, 3};       // along the shared edge, of the mitre's length
  LengthShare height{1, 4};      // its root across the edge, of the mitre's height
  double lowestRoot = 1;         // mm: a lower root gets no tenon
  double shallowestPocket = 2;   // mm: a pocket the plate cannot hold this deep gets no tenon
};

// A tongue sliding in a groove along a mitre (JointType::MitreSlide, paper Fig. 16b).
struct MitreSlideSizes {
  double slope = 1.0 / 6;        // how far the groove's flanks lean out, mm per mm of depth (1 in 6)
  LengthShare height{1, 4};      // the tongue's root across the edge, of the mitre's height
  double lowestRoot = 1;         // mm: a lower root gets no slide
  double shallowestGroove = 2;   // mm: a groove the plate cannot hold this deep gets no slide
  double stop = 10;              // mm: the groove stops at least this far (and at least the slide
                                 // plate's thickness) before the mitre's end ahead
  double shortestGroove = 10;    // mm: a shorter groove (with wood all round it) gets no slide
};

// A stub tenon on a lap (JointType::FaceTenon).
struct FaceTenonSizes {
  LengthShare margin{1, 3};      // the lap left on each side of the block, of the lap's length and width
  LengthShare depth{1, 3};       // the blind mortise's depth, of the mortise plate's thickness
};

// A tenon running on square past a shallow mitre into a pocket in the other plate's edge
// (JointType::StepTenon): plates meeting edge to edge with their planes 30..80 degrees apart.
struct StepTenonSizes {
  LengthShare width{1, 3};       // along the shared edge, of the mitre's length
  LengthShare reach{1, 2};       // how far it runs past the mitre's foot on the tenon plate's face,
                                 // of the way to the other plate's far face (where the slabs part)
  LengthShare height{3, 4};      // the tenons' height at the pocket's wall, of the wall's
  LengthShare gap{1, 4};         // between the two tenons at the wall, of the pair's width
  double flare = 0.25;           // mm each tenon's ends run outwards along the edge per mm towards
                                 // the mitre (a dovetail seen along the tenon plate's axis)
  double leastDegrees = 40;      // the angles between the plates' planes it joins (40..50: sides at
  double mostDegrees = 50;       // 130..140 degrees, the icosahedron's 138.2). Flatter and steeper
                                 // mitres are left to the mitre tenons and slides (the lizard's
                                 // 31..38 degree mitres with step tenons: a plan that fails the
                                 // final check, issue 26)
};

// The sizes of the joints cut or milled into the plates. The defaults are the sizes every design
// has had; each family reads its own and the shared ones.
struct JointCutOptions {
  // Through and open mortise-and-tenon joints (JointType::MortiseTenon, paper Fig. 2, left).
  double tenonWidth = 0;     // mm along the edge; 0 = as wide as the gaps between them and at the ends
                             // (the edge's length / (2 count + 1): a third, or a fifth for two tenons)
  int tenonCount = 0;        // tenons per joint; 0 = one, or two from `twoTenonsFrom`
  double twoTenonsFrom = 8;  // with tenonCount 0: edges at least this many tenon-plate thicknesses
                             // long get two tenons
  // Every family.
  double clearance = 0;      // mm of play between a joint's pieces (the mortises, slots and housings
                             // grow by it, or the tongues and milled tenons shrink)
  double woodMargin = 1;     // mm of wood left at least round a mortise, pocket, groove or housing,
                             // and how far a cut runs on past an edge it opens through
  double shortestJoint = 3;  // mm: a shorter contact, tenon or block gets no joint
  DovetailSizes dovetail;
  MitreTenonSizes mitreTenon;
  MitreSlideSizes mitreSlide;
  FaceTenonSizes faceTenon;
  StepTenonSizes stepTenon;
};

enum class JointType {
  MortiseTenon,  // tenons on one plate's edge, mortises through the other (planned: the edge
                 // within 45..135 degrees of the direction)
  Halved,        // the edge runs along the direction: slots where two plates cross (paper Fig. 2)
  Dovetail,      // milled: a sliding dovetail along the edge, out through the housing's open end
  MitreTenon,    // milled: plates meeting edge to edge at an angle, a tenon across the mitre into a
                 // pocket that fits it (paper Fig. 16a); the plate leaves straight out of the pocket
  MitreSlide,    // milled: plates meeting edge to edge at an angle, a dovetail tongue on one
                 // running in a stopped groove in the other along the edge (paper Fig. 16b)
  FaceTenon,     // milled: plates lying face to face (a lap), a stub tenon on one in a blind
                 // mortise in the other; the plate leaves straight off the lap
  StepTenon,     // milled: plates meeting edge to edge at a shallow angle, the tenon plate running
                 // on square past the mitre into a pocket in the other's edge; it leaves along its
                 // axis or in its plane away from the edge
  Empty,         // the plates only touch
};
// "mortise-tenon", "halved", "dovetail", "mitre-tenon", "mitre-slide", "face-tenon",
// "empty"
const char* jointTypeName(JointType type);

// What a design makes of its joints.
enum class JointRealization {
  // Joints cut into the plates (through and open mortise-and-tenon joints, halved joints), each
  // pair's joint chosen among those the geometry allows, the result verified on the jointed plates.
  Cut,
  // As Cut, and where no such joint lets a plate out, sliding dovetails milled along square edges
  // (a CNC router with a dovetail bit; the tongue and housing are not 2D cuts): the plate leaves
  // along the edge. What furniture whose boards end flush (BOOKSHELF) needs. And on plates that
  // meet edge to edge at an angle (mitres: the CABINET's ridge, polyhedral sculptures), tenons
  // across the mitre into pockets (paper Fig. 16a). Exports: STL and OBJ (cut sheets hold 2D cuts
  // only).
  Milled,
  // The paper's graph design stage alone (Section 5.2): halved, mortise-and-tenon or empty by the
  // angle between the shared edge and the direction, each joint modelled by the faces every such
  // joint has; verified on that model. Nothing to cut yet: halved joints need plates that cross,
  // and the non-orthogonal variants (Fig. 16) and dovetails are not made.
  Planned,
  // Chosen for the user (the CLI's and the package's default): Cut if a plan exists, else Milled,
  // else Planned; the result says which and why (PlateDesignResult::realization and message).
  // Step by step, Auto steps with Cut joints (the first it tries; choose Milled or Planned to step
  // a design that needs them).
  Auto,
};

// A joint between two touching plates (internal indices): it lets `mover` leave `other` along
// `direction` only (relative motion), the removal direction planned when `mover` was taken.
struct PlateJoint {
  int mover = 0, other = 0;
  Vec3 direction{0, 0, 0};
  JointType type = JointType::Empty;
  int contact = -1;  // the contact the tenons, slots or dovetail are cut in, an index into the contacts
};

struct PlateDesignOptions {
  uint64_t seed = 1;
  int candidates = 30;  // children kept per node (the paper's m)
  DesignLimits limits{60, 1'000'000, {}, false};  // time, nodes, progress and cancellation
  JointRealization realization = JointRealization::Cut;
  JointCutOptions joints;  // tenon sizes and the clearance cut into the result
  PlateOptions geometry;   // the contact tolerance for the jointed plates' contacts
};

struct PlateDesignResult {
  DesignStatus status = DesignStatus::NotFound;
  std::string message;           // one sentence for the user
  std::vector<int> order;        // plate indices: the key first, the last plate last
  std::vector<Vec3> directions;  // removal direction of order[k] (none for the last plate)
  std::vector<PlateJoint> joints;
  JointRealization realization = JointRealization::Cut;
  // The plates with their joints cut (input order, no clearance): what was verified (Cut only).
  std::vector<Plate> jointedPlates;
  // The same with the clearance cut into the mortises: what to make (equal to jointedPlates without one).
  std::vector<Plate> fabricationPlates;
  double clearance = 0;  // mm of play cut into the fabrication plates' mortises
  // The contacts of the jointed plates, computed from their geometry (Planned: the joints' model
  // contacts); part k = order[k].
  Assembly jointAssembly;
  DesignProgress progress;
};

// One step of a plate design: the plate taken (an index) and the direction it leaves along, with
// the joints it gets with the plates still in place.
struct PlateDesignStep {
  int plate = 0;
  Vec3 direction{0, 0, 0};
  std::vector<PlateJoint> joints;
};

// Step-by-step design (as the voxel session, paper Algorithm 1 by hand): the plates taken so far,
// the ranked children of the current node, choose one, go back. A node whose choice completes the
// plan is accepted only if the plan verifies (on its jointed plates when cut).
class PlateDesignSession {
 public:
  // Throws BadInput for a structure no joints can make interlocking (a cut point, named; fewer
  // than 3 plates).
  PlateDesignSession(std::vector<Plate> plates, std::vector<PlateContact> contacts, const PlateDesignOptions& options);
  ~PlateDesignSession();
  PlateDesignSession(const PlateDesignSession&) = delete;
  PlateDesignSession& operator=(const PlateDesignSession&) = delete;

  const std::vector<PlateDesignStep>& steps() const;  // the key first
  int targetPlates() const;
  bool complete() const;  // every plate placed and the plan verified
  // The verified result once complete (status Success), else NotFound saying how far it got.
  const PlateDesignResult& result() const;

  int childCount();                          // ranked children of the current node (generated on first call)
  PlateDesignStep childPreview(int n);       // the n-th child (0 = best ranked), without moving
  // Moves to the n-th child. Throws BadInput when n is out of range, or when that child completes
  // a plan that fails verification (the child is dropped from the list; the message says why).
  void chooseChild(int n);
  bool next();  // moves to the best child that works; false when none does (then go back)
  bool back();  // moves to the parent; false at the root
  // "Finish automatically from here": designPlateJoints's restarted search run below the current
  // node, so the plates taken so far stay, first in the order with their directions; restarts
  // re-seed below this node. A success is verified like any design. The session does not move.
  // Deterministic: the same path and seed give the same result; from the root it is
  // designPlateJoints with the session's options and these limits.
  PlateDesignResult finish(const DesignLimits& limits);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// "cut", "milled", "planned" or "auto"; BadInput naming the value else.
JointRealization parseJointRealization(const std::string& name);
const char* jointRealizationName(JointRealization realization);

// Designs the joints of a connected plate structure whose parts-graph has no cut point (otherwise:
// status CutPoint, naming it). A success has been verified on the jointed plates: their contacts,
// computed from the geometry, are interlocking with the key as the only movable part by both the
// DBG and the LP test, and each plate, swept along its direction, misses every plate after it.
PlateDesignResult designPlateJoints(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                                    const PlateDesignOptions& options = {});

// What a plan's verification found: "" or why it fails, and what it judged.
struct PlateRemovalVerification {
  std::string failure;
  int hitPosition = -1;          // when a plate ran into another: that one's place in the order
  Assembly assembly;             // the contacts judged, part k = the k-th to leave (normals squared)
  std::vector<Vec3> directions;  // the ways out judged (squared to the contacts)
};

// One verification for the designer (before it reports a plan) and `desia check` (of a file)
// alike. Jointed plates (a cut or milled result), in removal order, plates[0] the key: their
// contacts computed from the geometry, normals and ways out squared to each other (plan_squaring.h),
// interlocking with the key as the only movable part by both the DBG and the LP test, each plate
// free along directions[k] of the plates after it, and each plate, swept along its direction,
// missing every plate after it. The result depends on the plates and their removal order, not on
// how the document lists them.
PlateRemovalVerification verifyJointedPlates(const std::vector<Plate>& plates, const std::vector<Vec3>& directions,
                                             const PlateOptions& geometry = {});

// A planned result (nothing cut): the same tests on the joint model's contacts (`model`, part k =
// plates[k] = the k-th to leave), and the plates as they are swept along their directions, pairs
// that cross excepted (their slots are not cut).
PlateRemovalVerification verifyPlannedPlates(const Assembly& model, const std::vector<Plate>& plates,
                                             const std::vector<Vec3>& directions, const PlateOptions& geometry = {});

// Why a result's `fabricationPlates` (what the cut files and meshes make) are not its verified
// `plates` with play cut into their joints, or "": plates matched by id, each fabrication plate's
// faces in its plate's planes, its solid within its plate's (only wood removed) and its plate's
// within `clearance` of it; attached solids the same in number, each within the clearance of its
// own.
std::string fabricationPlatesFailure(const std::vector<Plate>& plates, const std::vector<Plate>& fabrication,
                                     double clearance, const PlateOptions& geometry = {});

}  // namespace desia
