// SPDX-License-Identifier: GPL-3.0-or-later
// Plate structures (paper Section 5.2): plates and their contacts, the joint planner and designer,
// mitred plates from faces, and the repair of cut points.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "desia/model.h"
#include "desia/search.h"
#include "desia/tolerances.h"

namespace desia {

// Plate structures (paper Section 5.2): flat boards of constant thickness, each given by its two
// parallel faces. Their contacts (which plates touch, where, with which normal) are computed from
// the geometry: a face of one plate lying on a face of another with opposite outward normals and
// an overlap of positive area. That covers a plate's edge face against another plate's face (butt,
// T and L joints) and two plates meeting edge to edge along a shared, possibly mitred, face.

// One closed loop of a face: vertices in order, no closing repeat.
using Loop = std::vector<Vec3>;

struct Plate {
  int id = 0;
  std::string name;
  // The two faces: loop k of `bottom` matches loop k of `top` vertex for vertex; loop 0 is the
  // outline, the others are holes. The plate is the solid between them.
  std::vector<Loop> bottom;
  std::vector<Loop> top;
  // Solids milled as part of this plate where its faces alone cannot hold a joint (a sliding
  // dovetail's tongue on its edge; the floor and overhanging lips of its housing): each a prism
  // of its own, described like a plate (its two end faces), without attachments of its own. The
  // plate is the union of its prism and these; they touch it but are not in contact with it.
  std::vector<Plate> attached;
};

// Newell's normal of a loop: right-handed about the vertex order, its length twice the loop's
// area (robust for non-convex loops).
Vec3 loopNormal(const Loop& loop);

// The unit vector across the plate, from its first face towards its second.
Vec3 plateThicknessAxis(const Plate& plate);

// The outward unit normals of the side faces along loop `loopIndex` (side k joins vertices k, k+1).
std::vector<Vec3> plateSideNormals(const Plate& plate, size_t loopIndex);

// The plate as closed triangle meshes (outward, counter-clockwise seen from outside), in mm: its
// prism and each attached solid a closed shell of its own (they touch). What the swept-collision
// tests run on.
TriangleMesh plateMesh(const Plate& plate);

// The plate as one solid for export and drawing, in mm: its attached solids unioned with it (the
// faces where they touch gone, coplanar faces merged), every edge in exactly two triangles in
// opposite directions, no T-junction, no zero-area triangle, no pinched vertex. Checked as it is
// built (edges and volume); where the check fails, the union triangulated plainly (rows of
// collinear mortises: it may keep zero-area triangles), then both from the 3D union's boundary
// (unionBoundaryPolygons: solids meeting on slanted planes), else the touching shells of
// plateMesh (no example or golden-corpus plate; docs/export.md).
TriangleMesh plateSolidMesh(const Plate& plate);

// The union of closed solids less the union of `removed` (booleanBoundaryPolygons) as one closed
// mesh, by the plates' merge of coplanar faces (Clipper per plane, no T-junction): every edge in
// two opposite triangles and the volume of the boundary's polygons, checked; nullopt where the
// check fails. For exports of solids that overlap (a curved frame beam's body boxes and joint
// voxels).
std::optional<TriangleMesh> solidBooleanMesh(const std::vector<TriangleMesh>& solids,
                                             const std::vector<TriangleMesh>& removed = {});

struct PlateOptions {
  // Two faces closer than this (mm) lie on one another; also the planarity tolerance of a face.
  double contactTolerance = tolerance::kContactMm;
};

// A planar contact between two plates (internal indices into the plate list).
struct PlateContact {
  int a = 0, b = 0;
  Vec3 normal{0, 0, 0};         // unit, pointing from plate a into plate b (the outward normal of a's face)
  double area = 0;              // mm^2 of the overlap
  Vec3 edgeDirection{0, 0, 0};  // the shared edge line's direction: where the plates' mid-planes meet
  std::vector<Vec3> region;     // the overlap polygon (largest piece), in 3D
  // Two plates that cross (an X, to be joined by slots: a halved joint, paper Fig. 2) are in the
  // parts-graph with a crossing instead of a face contact: no normal, `edgeDirection` the crossing
  // line, `area` the crossing's area seen across it. See computePlateContacts.
  bool crossing = false;
  Vec3 crossingPoint{0, 0, 0};              // on the crossing line and on both plates' first faces
  double crossingFrom = 0, crossingTo = 0;  // the crossing's extent along the line, from crossingPoint
  // Where a slot may open (the plate's outline ends at the crossing on that side): [0] towards
  // -edgeDirection, [1] towards +edgeDirection; for plate a and plate b.
  std::array<bool, 2> aOpens{false, false}, bOpens{false, false};
  // How far each plate's material where the other's slab passes through it (both faces' traces)
  // reaches past the crossing's ends where it only tapers there (mm; its outline crosses the slab
  // at a slant, as a rib's end bevelled to sit level does: nowhere past the end has it material
  // across the whole trace), [0] and [1] as for aOpens; infinite where it runs on across the
  // whole trace (a square overshoot, where a slot would cut an empty notch) or is not known. A
  // slot run on past the end cuts such a taper away (halvedSlotsOpen).
  static constexpr double kNoTaper = std::numeric_limits<double>::infinity();
  std::array<double, 2> aOverhang{kNoTaper, kNoTaper}, bOverhang{kNoTaper, kNoTaper};
};

// Checks every plate (planar faces, positive thickness, parallel matching faces, loops that do not
// cross themselves) and throws BadInput naming the plate and the problem.
void validatePlates(const std::vector<Plate>& plates, const PlateOptions& options, const std::string& source);

// Plates snapped to their design, once, on reading (readers call it after validatePlates): a design
// turned by any rotation or written to 6 decimals (as CAD tools write) has faces meant to be
// parallel 1e-9 to 1e-7 rad apart and faces meant to be square as far off square. Every normal the
// designer and `desia check` derive (contact normals, ways out, joint faces) inherits that noise,
// and the blocking tests decide d·n > tolerance::kDirection (README "Verdicts on computed
// normals"): the noise multiplies the base directions (the MITRED BOX, turned and rounded: 72
// instead of 7) and lets faces block what slides along them. Snapped, every plane of the design is
// exact to rounding (tolerance::kSquaredCosine) and the same design gives the same verdict in any
// turn.
//
// The plates with every face plane (both faces and every side, of the plates and of their attached
// solids) snapped: normals within an angle (below) of parallel made one normal, pairs as close to
// square made square (snappedDirections), each plane through the mean of its vertices, and every
// vertex recomputed as the crossing of its face's plane and its two sides' planes (on their shared
// line where the sides are within tolerance::kStraightSideSine of parallel). A plate whose
// vertices would move further than tolerance::kLargestVertexSnapMm (or the contact tolerance, if
// smaller) is kept as given: a shape no plane fits, which validatePlates judges.
// Drawn: a design from a file or a modelling tool (directions within
// tolerance::kDrawnDirectionRad snapped: a CAD file in metres to 6 decimals). Computed: plates
// desia made or wrote at full precision (the designer's jointed plates, a result's plates; within
// tolerance::kComputedDirectionRad, as finer cuts are real). normal_classes.h.
enum class PlateOrigin { Drawn, Computed };
std::vector<Plate> regularizedPlates(const std::vector<Plate>& plates, const PlateOptions& options, PlateOrigin origin);

// All contacts between the plates, in a fixed order (by plate pair, then faces), and the crossings
// of plates that pass through each other at any angle (each plate's material fills the other's
// thickness over the crossing). Throws BadInput naming both plates when such plates
// overlap only in part (neither a contact nor a crossing explains it).
std::vector<PlateContact> computePlateContacts(const std::vector<Plate>& plates, const PlateOptions& options);

// Throws BadInput when some plate touches nothing or the plates fall into separate groups.
void requireConnectedPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts,
                            const std::string& source);

// Plates from a modelling tool's mesh: every OBJ object or group (`o` / `g`), or every connected
// piece of a mesh without them (STL), is a closed slab whose two largest parallel faces facing
// away from each other are the plate's faces; ids 1, 2, ... in file order, names from the groups.
// Throws BadInput naming the plate when a piece is not such a slab.
std::vector<Plate> platesFromMesh(const TriangleMesh& mesh, const PlateOptions& options, const std::string& source);

// The parts and contacts of the structure (part ids = plate ids), as the interlocking tests read them.
Assembly assemblyFromPlates(const std::vector<Plate>& plates, const std::vector<PlateContact>& contacts);

// The plates whose removal disconnects the parts-graph (its cut points). A structure with a cut
// point cannot be interlocking whatever the joints (paper Section 5.2, Fig. 18).
std::vector<int> plateCutPoints(int plateCount, const std::vector<PlateContact>& contacts);

// Designing the joints of an interlocking plate structure (paper Section 5.2): the key, the order
// in which the other plates are taken out, the direction each one leaves in, the joint each pair
// of touching plates gets, and the joints cut into the plates (core/plate/joints/). A result is
// verified on the jointed plates themselves: their contacts computed from the geometry, both
// interlocking tests, and each plate swept out along its direction past the plates still in place.

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
                                 // mitres are left to the mitre tenons and slides: wider ranges
                                 // slow the search (the lizard with 30..80: no plan in 85 s)
};

// A mortise-and-tenon at an angle (JointType::SlantedTenon): a plate's side bevelled to lie on
// another's face, their planes from leastDegrees to less than square apart; its tenons are sized
// as the square tenon's (tenonWidth, tenonCount, twoTenonsFrom).
struct SlantedTenonSizes {
  double leastDegrees = 60;      // the least angle between the plates' planes it joins (IBOIS's
                                 // hexboxes: 80..88 degrees)
};

// A sliding dovetail on a bevelled side (JointType::SlantedDovetail): the side as a slanted
// tenon's, the tongue sized by DovetailSizes (width: its neck; slope: each wall's flare through
// the face plate; stop, narrowestNeck).
struct SlantedDovetailSizes {
  double leastDegrees = 60;      // the least angle between the plates' planes it joins
};

// A dovetail-shaped tab in the plane of two plates meeting edge to edge in one plane, cut through
// the sheet (JointType::InplaneDovetail, a jigsaw key).
struct InplaneDovetailSizes {
  LengthShare width{1, 3};       // the tab's root, of the shared side's length (in its middle)
  LengthShare depth{1, 2};       // how far it reaches into the socket plate, of its root's width
  double slope = 1.0 / 6;        // how far each flank leans out, mm per mm of depth (1 in 6)
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
  SlantedTenonSizes slantedTenon;
  SlantedDovetailSizes slantedDovetail;
  InplaneDovetailSizes inplaneDovetail;
};

// The joint families' dimensions above as named settings: "dovetail.slope", "stepTenon.width",
// ... each with its meaning and range, set by the CLI's --joint-size and the package's `jointSizes`.
// A share of a length (LengthShare) is set as a number: 0.25 = a quarter of it.
struct JointSizeSetting {
  std::string name;     // "family.field"
  std::string meaning;  // one line, with its unit and default
  double least, most;   // the values accepted
};

// Every setting, family by family, in the order docs/plates.md lists them.
std::vector<JointSizeSetting> jointSizeSettings();

// Sets `name` to `value` in options; BadInput naming the setting and its range, or listing the
// settings for an unknown name.
void setJointSize(JointCutOptions& options, const std::string& name, double value);

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
  SlantedTenon,  // milled: a plate's bevelled side on another's face at 60..<90 degrees (by default:
                 // slantedTenon.leastDegrees), tenons along its plane through slanted mortises; it
                 // leaves along its plane, out of them
  SlantedDovetail,  // milled: a plate's bevelled side on another's face at 60..<90 degrees (as
                    // SlantedTenon), a dovetail tongue through a slot with slanted walls open at
                    // one end; it leaves along the shared edge, out through the open end
  InplaneDovetail,  // plates lying in one plane edge to edge: a dovetail-shaped tab on one in a
                    // socket through the other, cut square through the sheet (a jigsaw key); it
                    // leaves along the sheets' thickness axis, either way
  ThroughSlot,   // a plate crossing another square and ending inside the crossing both ways, seated
                 // whole in a slot through the other (open where that one ends); it leaves along
                 // the other's axis, either way
  Empty,         // the plates only touch
};
// "mortise-tenon", "halved", "dovetail", "mitre-tenon", "mitre-slide", "face-tenon",
// "step-tenon", "slanted-tenon", "slanted-dovetail", "inplane-dovetail", "through-slot",
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

// Plate sculptures from a low-poly mesh (paper Section 5.2, the LIZARD of Fig. 1): every
// planar face of a closed, consistently oriented mesh becomes a plate of one thickness, inset
// inside the mesh, with mitred edges. The plate's outer face is the mesh face; its inner face lies
// on the face's plane moved inward by the thickness; each side face lies on the plane that bisects
// the dihedral angle between the face and its neighbour across that edge, so two neighbouring
// plates meet edge to edge along one shared mitre face, which computePlateContacts finds.

struct MitredPlateOptions {
  double thickness = 0;  // mm, > 0: the plates' thickness, measured from the mesh face inward
  // mm: how far a face's vertices may lie off one plane, and the plates' contact tolerance.
  double tolerance = PlateOptions{}.contactTolerance;
  // Adjacent triangles whose normals differ by less than this are one face (a modelling tool's
  // triangulation of a polygon); more than that and they are two plates meeting at a mitre.
  double mergeAngleDegrees = 1.0;
};

struct MitredPlates {
  // One plate per mesh face, ids 1, 2, ... in the order of each face's first triangle in the file
  // (so a rotated copy of the mesh gives the same numbering). `bottom` is the mesh face itself,
  // counter-clockwise seen from outside and starting at its corner with the lowest vertex index;
  // `top` is the inner face, vertex for vertex. No names, no holes.
  std::vector<Plate> plates;
  // Per plate, per side k (the edge from corner k to corner k+1): the plate (index) across it.
  std::vector<std::vector<int>> sideNeighbours;
  // Per plate: the mesh vertices (0-based) at its corners, and the mesh triangles of its face.
  std::vector<std::vector<int>> cornerVertices;
  std::vector<std::vector<int>> faceTriangles;
  // The contacts of the plates (computePlateContacts with the tolerance), each mitre's among them.
  std::vector<PlateContact> contacts;
  int meshEdges = 0;            // edges between two faces (runs of mesh edges); each is one mitre
  bool reoriented = false;      // the mesh was inside out (consistently); its faces were turned outward
  // mm: where more than three faces meet, each plate's inner corner (its inner plane and its two
  // mitres) differs from its neighbours'; the largest such distance (0 when all corners agree).
  double largestCornerMismatch = 0;
};

// The mitred plates of `mesh`. Throws BadInput naming `source` and the face, edge, vertex or value:
// a mesh that is not closed, not manifold (an edge of more than two triangles, a vertex where the
// surface touches itself), inconsistently oriented, in several pieces, or without volume; a face
// that is not planar within the tolerance or has a hole; a thickness that is not positive, or too
// large for a face (its inner face would lose an edge or cross itself; the message gives the
// largest thickness that face allows) or for the shape (an inner corner leaves the mesh).
// TooLarge beyond 10000 faces, or when inner corners x triangles exceed 2e8 (the inside test).
MitredPlates mitredPlatesFromMesh(const TriangleMesh& mesh, const MitredPlateOptions& options, const std::string& source);

// Repairing a plate structure whose parts-graph has a cut point (paper Section 5.2, Fig. 18): no
// joints can make it interlocking, but an added part that joins the groups the cut point holds
// together can (the paper's CHAIR gets one bar).

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
