// SPDX-License-Identifier: GPL-3.0-or-later
// The BurrTools puzzle file (.xmpuzzle): gzip-compressed XML, puzzle version 2, cube grid. Written
// from the format description in shared/reference/original-code-notes.md, section E, and, for the
// saved solution, from how BurrTools 0.6 reads <solution>, <assembly> and <separation> (its XML
// parsers in src/lib/solution.cpp, assembly.cpp, disassembly.cpp; no code taken from them).
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "desia/voxel_disassembly.h"
#include "desia/error.h"
#include "desia/export.h"
#include "desia/mesh.h"
#include "io/export_internals.h"

namespace desia {
namespace {

// XML text and attribute values: the five special characters as entities; control characters
// (not allowed in XML 1.0, and a name is one line) become spaces.
std::string escapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out;
}

struct Box {
  std::array<int, 3> low{0, 0, 0}, high{-1, -1, -1};  // inclusive
  int size(int axis) const { return high[axis] - low[axis] + 1; }
};

// A <voxel> shape: x*y*z characters in index order x + X*(y + Y*z), '#' filled, '_' empty, no
// whitespace (BurrTools rejects any other character in the voxel text).
std::string voxelElement(const VoxelGrid& grid, const Box& box, int partId, const std::string& name) {
  std::string out = "  <voxel x=\"" + std::to_string(box.size(0)) + "\" y=\"" + std::to_string(box.size(1)) +
                    "\" z=\"" + std::to_string(box.size(2)) + "\" name=\"" + escapeXml(name) + "\" type=\"0\">";
  for (int z = box.low[2]; z <= box.high[2]; ++z) {
    for (int y = box.low[1]; y <= box.high[1]; ++y) {
      for (int x = box.low[0]; x <= box.high[0]; ++x) {
        const int label = grid.label(x, y, z);
        out += (partId == 0 ? label > 0 : label == partId) ? '#' : '_';
      }
    }
  }
  return out + "</voxel>\n";
}

// Where each piece is while a separation runs: offsets from its assembled place, in voxels.
using Offset = std::array<int, 3>;

// BurrTools takes a piece whose offset exceeds 10000 along an axis as removed; its own
// disassembler writes 20000 times the direction of the last move.
constexpr int kRemovedDistance = 20000;

std::string numberList(const std::vector<int>& values) {
  std::string out;
  for (size_t k = 0; k < values.size(); ++k) out += (k ? " " : "") + std::to_string(values[k]);
  return out;
}

// <state>: the offsets of the separation's pieces, one <dx>, <dy>, <dz> list each, in piece order.
std::string stateElement(const std::vector<Offset>& offsets, const std::string& indent) {
  std::string out = indent + "<state>";
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<int> values;
    for (const Offset& offset : offsets) values.push_back(offset[axis]);
    const char* tag = axis == 0 ? "dx" : axis == 1 ? "dy" : "dz";
    out += std::string("<") + tag + ">" + numberList(values) + "</" + tag + ">";
  }
  return out + "</state>\n";
}

// The disassembly as BurrTools' separation tree. Each separation holds the pieces still together
// (0-based piece numbers, ascending), one state per position along the way (the first: everything
// in place), and ends when the removed piece is gone (kRemovedDistance along its last move, which
// the plan guarantees is free to infinity: the part has left the others' box). desia removes one
// part at a time and the others stay put, so the pieces left after each removal form the next
// separation, nested as its "left" branch; a single removed piece needs no branch of its own, nor
// do the last two pieces. Written as a chain of nested elements, closed at the end.
std::string separationElements(const DisassemblyPlan& plan, const Assembly& assembly, int parts) {
  std::vector<int> together;
  for (int piece = 0; piece < parts; ++piece) together.push_back(piece);
  std::string out, closing;
  std::string indent = "     ";
  for (size_t r = 0; r < plan.removals.size() && together.size() >= 2; ++r) {
    const Removal& removal = plan.removals[r];
    const int piece = assembly.parts[removal.part].id - 1;
    const size_t moving = static_cast<size_t>(std::find(together.begin(), together.end(), piece) - together.begin());
    out += indent + (r == 0 ? "<separation>" : "<separation type=\"left\">") + "\n";
    out += indent + " <pieces count=\"" + std::to_string(together.size()) + "\">" + numberList(together) + "</pieces>\n";
    std::vector<Offset> offsets(together.size(), Offset{0, 0, 0});
    out += stateElement(offsets, indent + " ");
    for (size_t m = 0; m < removal.path.size(); ++m) {
      const Move& move = removal.path[m];
      const bool last = m + 1 == removal.path.size();
      const int distance = last ? kRemovedDistance : move.steps;
      for (int axis = 0; axis < 3; ++axis) offsets[moving][axis] += distance * static_cast<int>(move.direction[axis]);
      out += stateElement(offsets, indent + " ");
    }
    closing = indent + "</separation>\n" + closing;
    together.erase(together.begin() + static_cast<std::ptrdiff_t>(moving));
    indent += " ";
  }
  return out + closing;
}

// <solution>: the assembly (per piece its offset in the result shape and transformation 0, i.e.
// as drawn in the file; a piece's voxel (x, y, z) goes to (x, y, z) + offset), then, when the plan
// removed every part, its separation tree. Without a complete plan the assembly alone is written.
std::string solutionElement(const AssemblyDocument& document, const std::vector<Box>& boxes, int parts) {
  std::string placements;
  for (int part = 1; part <= parts; ++part) {
    const Box& box = boxes[part];
    placements += (part > 1 ? " " : "") + std::to_string(box.low[0]) + " " + std::to_string(box.low[1]) + " " +
                  std::to_string(box.low[2]) + " 0";
  }
  std::string out = "   <solutions>\n    <solution>\n     <assembly>" + placements + "</assembly>\n";
  if (parts >= 2) {
    const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
    if (plan.complete) out += separationElements(plan, document.assembly, parts);
  }
  return out + "    </solution>\n   </solutions>\n";
}

}  // namespace

// Layout (the one BurrTools writes): shape 0 is the result, the assembled puzzle in the full grid;
// shapes 1..K are parts 1..K, each cropped to its bounding box. BurrTools places the pieces itself
// when it solves (it tries every position and rotation), so a piece's position in the file carries
// no meaning for it; cropping keeps the file near the size of the grid instead of K times it (the
// gzip stream is stored, not compressed). The crop offsets are listed in the comment, and they are
// the placements of the problem's one saved solution: desia's assembly, with its disassembly plan
// as the separation tree, so BurrTools shows the disassembly at once, whatever the size (its own
// solver may take longer than anyone waits for 80 parts). One problem uses every piece once, with
// shape 0 as result and state 3 (BurrTools' "partial": solutions known, not all counted), so its
// solver can still be started to find every assembly.
std::string xmpuzzleXml(const AssemblyDocument& document, const std::string& source) {
  requireExportableVoxels(document, source);
  const VoxelGrid& grid = document.voxels;
  const int parts = grid.maxLabel();
  std::vector<Box> boxes(static_cast<size_t>(parts) + 1);
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    const int label = grid.labelAt(i);
    if (label == 0) continue;
    const Int3 c = grid.coordinates(i);
    Box& box = boxes[label];
    const std::array<int, 3> p{c.x, c.y, c.z};
    const bool first = box.high[0] < box.low[0];
    for (int axis = 0; axis < 3; ++axis) {
      box.low[axis] = first ? p[axis] : std::min(box.low[axis], p[axis]);
      box.high[axis] = first ? p[axis] : std::max(box.high[axis], p[axis]);
    }
  }
  Box whole;
  whole.high = {grid.nx() - 1, grid.ny() - 1, grid.nz() - 1};
  // One character per voxel of the grid and of every box: refuse before building a huge string.
  int64_t voxelCharacters = grid.voxelCount();
  for (int part = 1; part <= parts; ++part) {
    if (boxes[part].high[0] < boxes[part].low[0])
      throwBadInput(source, "part " + std::to_string(part) + " has no voxels");
    voxelCharacters += int64_t{boxes[part].size(0)} * boxes[part].size(1) * boxes[part].size(2);
  }
  if (voxelCharacters > kMaxExportBytes) throwExportTooLarge(source, "xmpuzzle file", voxelCharacters);

  // A .puz has no name of its own: the file's stem names the result shape, as BurrTools users
  // would name it.
  const std::string stem = meshShapeName(source);
  const std::string title = !document.name.empty() ? document.name : !stem.empty() ? stem : "assembly";
  std::string xml = "<?xml version=\"1.0\"?>\n<puzzle version=\"2\">\n <gridType type=\"0\"/>\n <colors/>\n <shapes>\n";
  xml += voxelElement(grid, whole, 0, title);
  std::string offsets;
  for (int part = 1; part <= parts; ++part) {
    const int index = document.assembly.indexOfId(part);
    const std::string partName = index >= 0 && !document.assembly.parts[index].name.empty()
                                     ? document.assembly.parts[index].name
                                     : "part " + std::to_string(part);
    xml += voxelElement(grid, boxes[part], part, partName);
    offsets += "part " + std::to_string(part) + ": " + std::to_string(boxes[part].low[0]) + " " +
               std::to_string(boxes[part].low[1]) + " " + std::to_string(boxes[part].low[2]) + "\n";
  }
  xml += " </shapes>\n <problems>\n  <problem name=\"desia\" state=\"3\">\n   <shapes>\n";
  for (int part = 1; part <= parts; ++part) xml += "    <shape id=\"" + std::to_string(part) + "\" count=\"1\"/>\n";
  xml += "   </shapes>\n   <result id=\"0\"/>\n   <bitmap/>\n" + solutionElement(document, boxes, parts) +
         "  </problem>\n </problems>\n";
  xml += " <comment>" +
         escapeXml("Exported by desia from " + title + ". Shape 0 is the assembled puzzle (grid " +
                   std::to_string(grid.nx()) + " x " + std::to_string(grid.ny()) + " x " + std::to_string(grid.nz()) +
                   "); shapes 1 to " + std::to_string(parts) + " are parts 1 to " + std::to_string(parts) +
                   ", each cropped to its bounding box. The saved solution is desia's assembly and its "
                   "disassembly plan. Offsets of the boxes in the grid (x y z):") +
         "\n" + offsets + "</comment>\n</puzzle>\n";
  if (static_cast<int64_t>(xml.size()) > kMaxExportBytes) {
    throwExportTooLarge(source, "xmpuzzle file", static_cast<int64_t>(xml.size()));
  }
  return xml;
}

std::vector<uint8_t> xmpuzzleFile(const AssemblyDocument& document, const std::string& source) {
  return gzipStored(xmpuzzleXml(document, source));
}

}  // namespace desia
