// SPDX-License-Identifier: GPL-3.0-or-later
// The BurrTools puzzle file (.xmpuzzle): gzip-compressed XML, puzzle version 2, cube grid. Written
// from the format description in shared/reference/original-code-notes.md, section E, and, for the
// saved solution, from how BurrTools 0.6 reads <solution>, <assembly> and <separation> (its XML
// parsers in src/lib/solution.cpp, assembly.cpp, disassembly.cpp; no code taken from them).
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "desia/error.h"
#include "desia/export.h"
#include "desia/formats.h"
#include "desia/voxel.h"
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
std::string voxelCharacters(const VoxelGrid& grid, const Box& box, int partId) {
  std::string out;
  for (int z = box.low[2]; z <= box.high[2]; ++z) {
    for (int y = box.low[1]; y <= box.high[1]; ++y) {
      for (int x = box.low[0]; x <= box.high[0]; ++x) {
        const int label = grid.label(x, y, z);
        out += (partId == 0 ? label > 0 : label == partId) ? '#' : '_';
      }
    }
  }
  return out;
}

std::string voxelElement(const VoxelGrid& grid, const Box& box, int partId, const std::string& name) {
  return "  <voxel x=\"" + std::to_string(box.size(0)) + "\" y=\"" + std::to_string(box.size(1)) + "\" z=\"" +
         std::to_string(box.size(2)) + "\" name=\"" + escapeXml(name) + "\" type=\"0\">" +
         voxelCharacters(grid, box, partId) + "</voxel>\n";
}

// BurrTools' pieces: parts whose cropped voxels are equal (the same shape, translated) are copies
// of one shape with a count, so that its solver does not count their permutations as different
// assemblies (AlPackino's 12 pieces of 3 shapes: 1 assembly, not 13,824). Shapes come in the order
// of their first part; a shape's pieces are consecutive, in part order.
struct PieceLayout {
  std::vector<std::vector<int>> partsOfShape;  // shape s (1..S) at s - 1: its part ids, ascending
  std::vector<int> pieceOfPart;                // part id (1..K) at id: its 0-based piece number
  std::vector<int> partOfPiece;                // piece number: its part id
};

PieceLayout pieceLayout(const VoxelGrid& grid, const std::vector<Box>& boxes, int parts) {
  PieceLayout layout;
  std::map<std::string, size_t> shapeOf;  // size and voxels -> shape index
  for (int part = 1; part <= parts; ++part) {
    const Box& box = boxes[static_cast<size_t>(part)];
    const std::string key = std::to_string(box.size(0)) + " " + std::to_string(box.size(1)) + " " +
                            std::to_string(box.size(2)) + " " + voxelCharacters(grid, box, part);
    const auto [at, added] = shapeOf.emplace(key, layout.partsOfShape.size());
    if (added) layout.partsOfShape.emplace_back();
    layout.partsOfShape[at->second].push_back(part);
  }
  layout.pieceOfPart.assign(static_cast<size_t>(parts) + 1, -1);
  for (const std::vector<int>& shape : layout.partsOfShape) {
    for (int part : shape) {
      layout.pieceOfPart[static_cast<size_t>(part)] = static_cast<int>(layout.partOfPiece.size());
      layout.partOfPiece.push_back(part);
    }
  }
  return layout;
}

// Where each piece is while a separation runs: its position in the result shape, in voxels (the
// <assembly> placement, then moved).
using Offset = std::array<int, 3>;

// BurrTools takes a piece whose position exceeds 10000 along an axis as removed; its own
// disassembler writes about 30000 along the direction of the last move.
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

// One separation of BurrTools' tree: the pieces together (0-based piece numbers, ascending), one
// state per position along the way, the last with the removed pieces beyond 10000; then the
// separations of the two sides, where a side keeps two pieces or more.
struct SeparationNode {
  std::vector<int> pieces;
  std::vector<std::vector<Offset>> states;
  int left = -1, removed = -1;
};

// The plan's moves replayed into the tree: each move belongs to the sub-assembly holding its
// parts; a move out closes that sub-assembly's separation and opens one per side of two pieces
// or more, starting where its pieces were. `position`: each piece's placement.
std::vector<SeparationNode> separationTree(const DisassemblyPlan& plan, const Assembly& assembly,
                                           const PieceLayout& layout, std::vector<Offset> position) {
  const int pieces = static_cast<int>(position.size());
  std::vector<SeparationNode> tree(1);
  for (int piece = 0; piece < pieces; ++piece) tree[0].pieces.push_back(piece);
  std::vector<int> nodeOf(static_cast<size_t>(pieces), 0);
  auto stateOf = [&](const SeparationNode& node) {
    std::vector<Offset> state;
    for (int piece : node.pieces) state.push_back(position[static_cast<size_t>(piece)]);
    return state;
  };
  auto shift = [&](const std::vector<int>& moving, const GroupMove& move, int distance) {
    for (int piece : moving) {
      for (int axis = 0; axis < 3; ++axis) {
        position[static_cast<size_t>(piece)][axis] += distance * static_cast<int>(move.direction[axis]);
      }
    }
  };
  tree[0].states.push_back(stateOf(tree[0]));
  for (const GroupMove& move : plan.moves) {
    std::vector<int> moving;
    for (int part : move.parts) moving.push_back(layout.pieceOfPart[static_cast<size_t>(assembly.parts[part].id)]);
    std::sort(moving.begin(), moving.end());
    const int node = nodeOf[static_cast<size_t>(moving[0])];
    const int distance = move.out ? kRemovedDistance : move.steps;
    shift(moving, move, distance);
    tree[static_cast<size_t>(node)].states.push_back(stateOf(tree[static_cast<size_t>(node)]));
    if (!move.out) continue;
    shift(moving, move, -distance);  // each side goes on from where its pieces were
    SeparationNode sides[2];         // [0] left, [1] removed
    for (int piece : tree[static_cast<size_t>(node)].pieces) {
      sides[std::binary_search(moving.begin(), moving.end(), piece) ? 1 : 0].pieces.push_back(piece);
    }
    for (int s = 0; s < 2; ++s) {
      const bool alone = sides[s].pieces.size() < 2;
      const int child = alone ? -1 : static_cast<int>(tree.size());
      for (int piece : sides[s].pieces) nodeOf[static_cast<size_t>(piece)] = child;
      if (alone) continue;
      sides[s].states.push_back(stateOf(sides[s]));
      (s == 0 ? tree[static_cast<size_t>(node)].left : tree[static_cast<size_t>(node)].removed) = child;
      tree.push_back(std::move(sides[s]));
    }
  }
  return tree;
}

// The tree as nested <separation> elements (the sides as type "left" and "removed"), written
// with an explicit stack.
std::string separationElements(const std::vector<SeparationNode>& tree) {
  struct Open {
    int node;
    const char* type;
    int depth;
    bool contentWritten;
  };
  std::string out;
  std::vector<Open> stack{{0, nullptr, 0, false}};
  while (!stack.empty()) {
    Open& top = stack.back();
    const SeparationNode& node = tree[static_cast<size_t>(top.node)];
    const std::string indent(static_cast<size_t>(5 + top.depth), ' ');
    if (top.contentWritten) {
      out += indent + "</separation>\n";
      stack.pop_back();
      continue;
    }
    out += indent + (top.type ? std::string("<separation type=\"") + top.type + "\">" : std::string("<separation>")) + "\n";
    out += indent + " <pieces count=\"" + std::to_string(node.pieces.size()) + "\">" + numberList(node.pieces) + "</pieces>\n";
    for (const auto& state : node.states) out += stateElement(state, indent + " ");
    top.contentWritten = true;
    const int depth = top.depth + 1;
    if (node.removed >= 0) stack.push_back({node.removed, "removed", depth, false});
    if (node.left >= 0) stack.push_back({node.left, "left", depth, false});
  }
  return out;
}

// <solution>: the assembly (per piece its offset in the result shape and transformation 0, i.e.
// as drawn in the file; a piece's voxel (x, y, z) goes to (x, y, z) + offset), then, when the plan
// removed every part, its separation tree. Without a complete plan the assembly alone is written.
std::string solutionElement(const AssemblyDocument& document, const std::vector<Box>& boxes, const PieceLayout& layout,
                            int parts) {
  std::string placements;
  for (int piece = 0; piece < parts; ++piece) {
    const Box& box = boxes[static_cast<size_t>(layout.partOfPiece[static_cast<size_t>(piece)])];
    placements += (piece > 0 ? " " : "") + std::to_string(box.low[0]) + " " + std::to_string(box.low[1]) + " " +
                  std::to_string(box.low[2]) + " 0";
  }
  std::string out = "   <solutions>\n    <solution>\n     <assembly>" + placements + "</assembly>\n";
  if (parts >= 2) {
    const DisassemblyPlan plan = planVoxelDisassembly(document.voxels, document.assembly);
    std::vector<Offset> placements;
    for (int piece = 0; piece < parts; ++piece) {
      placements.push_back(boxes[static_cast<size_t>(layout.partOfPiece[static_cast<size_t>(piece)])].low);
    }
    if (plan.complete) out += separationElements(separationTree(plan, document.assembly, layout, placements));
  }
  return out + "    </solution>\n   </solutions>\n";
}

}  // namespace

// Layout (the one BurrTools writes): shape 0 is the result, the assembled puzzle in the full grid;
// shapes 1..S are the parts, each cropped to its bounding box, equal parts as one shape with a
// count (PieceLayout). BurrTools places the pieces itself
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
  const PieceLayout layout = pieceLayout(grid, boxes, parts);
  auto partName = [&](int part) {
    const int index = document.assembly.indexOfId(part);
    return index >= 0 && !document.assembly.parts[index].name.empty() ? document.assembly.parts[index].name
                                                                       : "part " + std::to_string(part);
  };
  for (const std::vector<int>& shape : layout.partsOfShape) {
    std::string name = shape.size() == 1 ? partName(shape[0]) : "parts";
    for (size_t k = 0; shape.size() > 1 && k < shape.size(); ++k) name += (k ? ", " : " ") + std::to_string(shape[k]);
    xml += voxelElement(grid, boxes[static_cast<size_t>(shape[0])], shape[0], name);
  }
  std::string offsets;
  for (int part = 1; part <= parts; ++part) {
    offsets += "part " + std::to_string(part) + ": " + std::to_string(boxes[part].low[0]) + " " +
               std::to_string(boxes[part].low[1]) + " " + std::to_string(boxes[part].low[2]) + "\n";
  }
  // The counts say one assembly and one solution are saved: without them BurrTools lists none.
  xml += " </shapes>\n <problems>\n  <problem name=\"desia\" state=\"3\" assemblies=\"1\" solutions=\"1\" time=\"0\">\n   <shapes>\n";
  for (size_t shape = 0; shape < layout.partsOfShape.size(); ++shape) {
    xml += "    <shape id=\"" + std::to_string(shape + 1) + "\" count=\"" + std::to_string(layout.partsOfShape[shape].size()) +
           "\"/>\n";
  }
  xml += "   </shapes>\n   <result id=\"0\"/>\n   <bitmap/>\n" + solutionElement(document, boxes, layout, parts) +
         "  </problem>\n </problems>\n";
  xml += " <comment>" +
         escapeXml("Exported by desia from " + title + ". Shape 0 is the assembled puzzle (grid " +
                   std::to_string(grid.nx()) + " x " + std::to_string(grid.ny()) + " x " + std::to_string(grid.nz()) +
                   "); the other shapes are the parts, each cropped to its bounding box, parts of the same "
                   "shape as one shape with its count (pieces in the order of the shapes). The saved "
                   "solution is desia's assembly and its disassembly plan. Offsets of the parts' boxes in "
                   "the grid (x y z):") +
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
