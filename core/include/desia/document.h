// SPDX-License-Identifier: GPL-3.0-or-later
// The assembly document every command reads (docs/json-schema.md) and its check.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "desia/analysis.h"
#include "desia/frame.h"
#include "desia/model.h"
#include "desia/plate.h"
#include "desia/voxel.h"

namespace desia {

// The JSON assembly document (schema in docs/json-schema.md): one format for voxel, plate and
// frame assemblies, or bare contact graphs, optionally carrying analysis results.

enum class AssemblyKind { Voxel, Plate, Frame, Contacts };
const char* assemblyKindName(AssemblyKind kind);

// One joint of a plate design result (`joints`): which part moves along `direction` into which.
struct PlateResultJoint {
  int mover = 0;     // part id
  int other = 0;     // part id
  std::string type;  // a joint type's name (jointTypeName), as the result was written
  Vec3 direction{};  // unit vector
};

// A plate design result's plan (docs/json-schema.md "Plate results"), read by part id with the
// document: `removal` names every part once, the key first; the last part stays.
struct PlateResultPlan {
  std::string jointGeometry;      // "cut", "milled" (jointed plates) or "planned" (nothing cut)
  std::vector<int> removalOrder;  // part ids in the order they leave
  std::vector<Vec3> directions;   // unit vectors: removalOrder[k] leaves along directions[k]
  double clearance = 0;           // mm of play in `fabricationPlates`
  std::vector<PlateResultJoint> joints;
};

// A frame, and when it is a design result its joint voxels and removal plan.
struct FrameDocument {
  std::string name;
  FrameLayout layout;
  std::vector<JointLabels> labels;  // empty for a frame without joints designed
  std::vector<int> order;           // beams (internal indices) in removal order; with labels: by id
  std::vector<Vec3> directions;     // removal direction of order[k]; empty when not given
};

struct AssemblyDocument {
  AssemblyKind kind = AssemblyKind::Voxel;
  std::string name;
  VoxelGrid voxels;          // kind == Voxel
  // kind == Voxel: the voxel edge lengths a .puz file gives (x, y, z), the default size of exports.
  std::optional<std::array<double, 3>> voxelSize;
  Assembly assembly;         // parts and contacts (derived from the grid for voxel documents)
  std::optional<FrameDocument> frame;  // kind == Frame given by its geometry (a frame or a designed one)
  std::vector<Plate> plates;          // kind == Plate, read from geometry (then contacts are computed)
  std::vector<Plate> fabricationPlates;  // a design result with a clearance: the plates as they are cut
  // Parts (internal indices) that are cut points of the parts-graph: plates (plates in contact), or
  // a frame's beams (beams sharing a joint). The check report's `cutPoints`.
  std::vector<int> plateCutPoints;
  // kind == Plate with contactsFromGeometry: the plates' contacts as computed when they were read
  // (the designer and the cut sheets take them from here rather than computing them again).
  std::vector<PlateContact> plateContacts;
  PlateOptions plateOptions;          // the contact tolerance the plates were read with
  bool contactsFromGeometry = false;  // the contacts were computed from `plates` (a design, not a plan)
  std::optional<PlateResultPlan> plateResult;  // kind == Plate with `removal`: a design result
};

// Reads .puz or JSON text (detected from the content). `source` names the input in messages.
AssemblyDocument parseAssemblyText(const std::string& text, const std::string& source = "<input>");
// The same, letting the text go as soon as it is parsed (less memory for large documents).
AssemblyDocument parseAssemblyText(std::string&& text, const std::string& source = "<input>");
AssemblyDocument parseJsonDocument(const std::string& text, const std::string& source = "<input>");
AssemblyDocument documentFromVoxels(VoxelGrid grid, std::string name = "");
// A plate design: the plates validated, their contacts computed (they must all be connected), and
// the parts-graph's cut points found. Throws BadInput naming `source` and the plate.
AssemblyDocument documentFromPlates(std::vector<Plate> plates, const PlateOptions& options, const std::string& source,
                                    std::string name = "");

// Serializes a document (without results). `indent` < 0 gives one line.
std::string documentToJson(const AssemblyDocument& document, int indent = 2);

// `desia check` of a document of any kind: the contact check (analysis.h) with the kind's
// disassembly planner, and the report as text or JSON.

// checkContacts on the document's contacts; voxel documents plan their disassembly on the voxels.
CheckReport checkAssembly(const AssemblyDocument& document, const CheckOptions& options = {});

// The report as the JSON object printed by `desia check --json` (fields documented in docs/json-schema.md).
std::string checkReportToJson(const AssemblyDocument& document, const CheckReport& report,
                              int indent = 2);
// Human-readable report for the terminal.
std::string checkReportToText(const AssemblyDocument& document, const CheckReport& report);

// `desia check` for every kind: the interlocking tests on the document's contacts (checkAssembly,
// which knows only parts and contacts), and, for a plate or frame design result, its removal plan
// replayed on the real shapes by the kind's own geometry (paper Section 4.1 (iii)).

// checkAssembly, plus for results that carry a removal plan:
// - plate results (read by part id, whatever the file's order): the verification the designer
//   ran before writing the result (verifyJointedPlates for cut and milled joints, verifyPlannedPlates
//   for a plan with nothing cut), the verdict reported on the contacts it judged, and the
//   fabrication plates compared with the verified ones (fabricationPlatesFailure);
// - frames with designed joints: each beam, body and joint voxels, swept along its axis misses
//   every beam still in place.
// The plan is read with the document (PlateResultPlan); a malformed plan is BadInput there.
CheckReport checkDocument(const AssemblyDocument& document, const CheckOptions& options = {});

// True when the report passes on the contacts and, where it ran, on the shapes.
bool checkPassed(const CheckReport& report);

}  // namespace desia
