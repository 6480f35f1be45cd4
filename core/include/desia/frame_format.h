// SPDX-License-Identifier: GPL-3.0-or-later
// Frame files: the JSON document (kind "frame", docs/json-schema.md), OBJ (every `l` segment and
// every face edge a beam, shared edges once; every vertex a joint) and FrameInterlock's .fpuz; the
// result document of a design; exports (meshes, .fpuz, a cut list).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "desia/document.h"
#include "desia/export.h"
#include "desia/frame.h"
#include "desia/frame_design.h"

namespace desia {

// A frame, and when it is a design result its joint voxels and removal plan.
struct FrameDocument {
  std::string name;
  FrameLayout layout;
  std::vector<JointLabels> labels;  // empty for a frame without joints designed
  std::vector<int> order;           // beams (internal indices) in removal order; with labels: by id
  std::vector<Vec3> directions;     // removal direction of order[k]; empty when not given
};

// Reads a frame from JSON, OBJ or .fpuz text (by the extension of `source`: ".obj", ".fpuz",
// otherwise JSON). `jointSize` > 0 overrides the file's joint size (and the default). Validated
// (layoutFrame, validateJointLabels); throws BadInput naming `source`.
FrameDocument parseFrameText(const std::string& text, const std::string& source, double jointSize = 0);

// The result document of a successful design (kind "frame"): beams renumbered in removal order
// (part 1 = the key; each keeps `inputId`), `jointVoxels` (per joint its 27 part ids, x fastest),
// `removal` (part and direction, in order). Same result, same bytes.
std::string frameResultToJson(const FrameLayout& layout, const FrameDesignResult& result, const std::string& name = "",
                              int indent = 2);
// A frame document as JSON (with its joints and removal when it has them).
std::string frameDocumentToJson(const FrameDocument& document, int indent = 2);

// The assembly document `desia check` reads: parts = beams (ids), contacts = the voxel faces
// between different parts (axis normals); the frame kept as its geometry sections.
AssemblyDocument assemblyDocumentFromFrame(const FrameDocument& document);
// The frame of a frame assembly document (read again from its geometry sections).
FrameDocument frameFromAssemblyDocument(const AssemblyDocument& document, const std::string& source = "<input>");

// FrameInterlock's text format (original-code-notes.md section C): straight beams only; voxel
// values = part id (removal order), all voxels owned.
std::string formatFpuz(const FrameDocument& document);

// The cut list: one row per beam (part, input beam, joints, faces, body length, section, voxels at
// each end with their cells, removal direction).
std::string frameCutListCsv(const FrameDocument& document);

// A designed frame whose beams are straight along the axes and whose joint cubes sit on one grid
// of the joint voxel size, as a voxel assembly (core/frame/frame_voxels.cpp): each beam a rod of
// voxels through the centre voxels of the faces it enters, plus its voxels in its two joint
// cubes; voxel label = part id (beam id of the result document, 1 = the key). Throws BadInput
// naming the first beam (by id) that is off the grid (curved, not along an axis, or a joint not a
// whole number of voxels from the first joint), or for a frame without designed joints.
VoxelGrid frameVoxelGrid(const FrameDocument& document, const std::string& source = "<input>");
// The same as a voxel assembly document (the name kept): .puz, voxel JSON, .xmpuzzle, desia check.
AssemblyDocument frameVoxelDocument(const FrameDocument& document, const std::string& source = "<input>");

// "stl", "stl-ascii", "obj" (one closed mesh per part: its body boxes and voxel groups, each a
// closed shell), "fpuz", "csv", and the voxel assembly of frameVoxelDocument as "puz",
// "voxel-json" or "xmpuzzle". `part` 0 = all parts (meshes only). Throws BadInput for an unknown
// format, an unknown part, a frame without designed joints (fpuz, csv need them; meshes draw the
// beams and bare cubes), curved beams in .fpuz.
std::vector<uint8_t> exportFrame(const FrameDocument& document, const std::string& format, int part = 0,
                                 const std::string& source = "<input>");

// Every part's surface, ready to draw (flat normals), parts in id order; without designed joints,
// the beams and then the bare joint cubes (part id 0).
std::vector<PartSurface> framePartSurfaces(const FrameDocument& document);

}  // namespace desia
