// SPDX-License-Identifier: GPL-3.0-or-later
// Exports of frame structures: part meshes (STL, OBJ), FrameInterlock's .fpuz, the cut list (CSV),
// and the surfaces a viewer draws.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "desia/error.h"
#include "desia/formats.h"
#include "desia/frame.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "io/export_internals.h"

namespace desia {
namespace {

std::string cellsText(const JointLabels& labels, int beam) {
  std::string text;
  for (int v = 0; v < kJointVoxelCount; ++v) {
    if (labels[v] != beam) continue;
    if (!text.empty()) text += ";";
    text += std::to_string(v % 3) + " " + std::to_string(v / 3 % 3) + " " + std::to_string(v / 9);
  }
  return text;
}

// The bare joint cubes of a frame without designed joints.
TriangleMesh cubesMesh(const FrameLayout& layout) {
  TriangleMesh mesh;
  for (size_t j = 0; j < layout.frame.joints.size(); ++j) {
    VoxelGrid grid(1, 1, 1);
    grid.setLabelAt(0, 1);
    const TriangleMesh cube = partSurfaceMesh(grid, 1, layout.frame.jointSize);
    const Vec3& p = layout.frame.joints[j].position;
    const int first = static_cast<int>(mesh.vertices.size());
    const double half = layout.frame.jointSize / 2;
    for (const auto& v : cube.vertices)
      mesh.vertices.push_back({v[0] + p[0] - half, v[1] + p[1] - half, v[2] + p[2] - half});
    for (const auto& t : cube.triangles) mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  }
  return mesh;
}

// Does the beam's body have a box at a slant (a curved beam's path)? Axis-aligned bodies are
// exact unions of boxes already (beamPartMesh).
bool slantedBody(const FrameLayout& layout, int beam) {
  for (const OrientedBox& box : beamBodyBoxes(layout, beam)) {
    for (const Vec3& axis : box.axes) {
      int along = 0;
      for (double c : axis) {
        if (std::abs(std::abs(c) - 1) < tolerance::kDirection) ++along;
        else if (std::abs(c) >= tolerance::kDirection) return true;
      }
      if (along != 1) return true;
    }
  }
  return false;
}

std::vector<TriangleMesh> bodyBoxMeshes(const FrameLayout& layout, int beam) {
  std::vector<TriangleMesh> meshes;
  for (const OrientedBox& box : beamBodyBoxes(layout, beam)) meshes.push_back(orientedBoxMesh(box));
  return meshes;
}

// A curved beam's body as a maker cuts it: the union of its body boxes less its joint cubes (3D
// union, solidBooleanMesh), so that it shares no volume with the joint pieces; where that union
// fails its check, the boxes as they are (beamBodyPieceMesh).
TriangleMesh curvedBodyPiece(const FrameLayout& layout, int beam) {
  std::vector<TriangleMesh> cubes;
  for (int joint : layout.frame.beams[beam].joints) {
    OrientedBox cube;
    cube.centre = layout.frame.joints[joint].position;
    cube.halfExtents = {layout.frame.jointSize / 2, layout.frame.jointSize / 2, layout.frame.jointSize / 2};
    cubes.push_back(orientedBoxMesh(cube));
  }
  std::optional<TriangleMesh> body = solidBooleanMesh(bodyBoxMeshes(layout, beam), cubes);
  return body ? std::move(*body) : beamBodyPieceMesh(layout, beam);
}

TriangleMesh bodyPieceMesh(const FrameLayout& layout, int beam) {
  return slantedBody(layout, beam) ? curvedBodyPiece(layout, beam) : beamBodyPieceMesh(layout, beam);
}

// A beam as one solid: a curved beam's body piece and joint pieces unioned in 3D (the body boxes
// alone for a frame without joints yet); an axis-aligned one as beamPartMesh makes it. Where the
// 3D union fails its check, beamPartMesh's closed shells.
TriangleMesh partMesh(const FrameLayout& layout, const std::vector<JointLabels>& labels, int beam) {
  std::vector<JointLabels> none(layout.frame.joints.size());
  for (JointLabels& unowned : none) unowned.fill(-1);
  const std::vector<JointLabels>& owned = labels.empty() ? none : labels;
  if (!slantedBody(layout, beam)) return beamPartMesh(layout, owned, beam);
  std::vector<TriangleMesh> pieces;
  if (labels.empty()) {
    pieces = bodyBoxMeshes(layout, beam);
  } else {
    pieces.push_back(curvedBodyPiece(layout, beam));
    for (int joint : layout.frame.beams[beam].joints) {
      TriangleMesh piece = beamJointPieceMesh(layout, labels, beam, joint);
      if (!piece.triangles.empty()) pieces.push_back(std::move(piece));
    }
  }
  std::optional<TriangleMesh> solid = solidBooleanMesh(pieces);
  return solid ? std::move(*solid) : beamPartMesh(layout, owned, beam);
}

std::vector<NamedMesh> partMeshes(const FrameDocument& document, int part, const std::string& source) {
  const FrameLayout& layout = document.layout;
  std::vector<NamedMesh> meshes;
  for (int beam : document.order) {
    const int id = layout.frame.beams[beam].id;
    if (part != 0 && part != id) continue;
    meshes.push_back({id, partMesh(layout, document.labels, beam), ""});
  }
  if (meshes.empty())
    throwBadInput(source, "part " + std::to_string(part) + " is not a beam of this frame (0 = all parts)");
  if (document.labels.empty() && part == 0) meshes.push_back({0, cubesMesh(layout), ""});
  return meshes;
}

// What a maker cuts and glues: each beam's body (a stick cut to length) and, on their own, the
// joint pieces glued to its ends (the voxels it owns in each joint cube), in removal order.
std::vector<NamedMesh> pieceMeshes(const FrameDocument& document, const std::string& source) {
  if (document.labels.empty()) throwBadInput(source, "this frame has no designed joints yet: run desia design frame first");
  const FrameLayout& layout = document.layout;
  std::vector<NamedMesh> meshes;
  for (int beam : document.order) {
    const int id = layout.frame.beams[beam].id;
    // The stick cut to length: it ends where the joint pieces begin (beamBodyPieceMesh).
    meshes.push_back({id, bodyPieceMesh(layout, beam), "beam" + std::to_string(id)});
    for (int joint : layout.frame.beams[beam].joints) {
      TriangleMesh piece = beamJointPieceMesh(layout, document.labels, beam, joint);
      if (piece.triangles.empty()) continue;
      meshes.push_back({id, std::move(piece),
                        "beam" + std::to_string(id) + "_joint" + std::to_string(layout.frame.joints[joint].id)});
    }
  }
  return meshes;
}

// The joint pieces alone, each moved onto the plane z = 0 at its own place of a square grid (one
// voxel apart), to print in one go; the beam bodies are sticks and stay out.
std::vector<NamedMesh> jointPiecesOnAPlate(std::vector<NamedMesh> pieces, double voxelSize) {
  std::vector<NamedMesh> joints;
  for (NamedMesh& piece : pieces) {
    if (piece.name.find("_joint") != std::string::npos) joints.push_back(std::move(piece));
  }
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(joints.size())))));
  const double pitch = 4 * voxelSize;
  for (size_t k = 0; k < joints.size(); ++k) {
    auto& vertices = joints[k].mesh.vertices;
    std::array<double, 3> lowest{vertices[0][0], vertices[0][1], vertices[0][2]};
    for (const auto& v : vertices) {
      for (int axis = 0; axis < 3; ++axis) lowest[axis] = std::min(lowest[axis], static_cast<double>(v[axis]));
    }
    const double x = pitch * static_cast<double>(static_cast<int>(k) % columns);
    const double y = pitch * static_cast<double>(static_cast<int>(k) / columns);
    for (auto& v : vertices) {
      v[0] = v[0] - lowest[0] + x;
      v[1] = v[1] - lowest[1] + y;
      v[2] = v[2] - lowest[2];
    }
  }
  return joints;
}

std::vector<uint8_t> bytesOf(const std::string& text) { return std::vector<uint8_t>(text.begin(), text.end()); }

}  // namespace

std::string frameCutListCsv(const FrameDocument& document) {
  const FrameLayout& layout = document.layout;
  const Frame& frame = layout.frame;
  std::string out =
      "part,input beam,joint a,face a,joint b,face b,body length,section,voxels at a,cells at a,voxels at b,cells at "
      "b,removal\n";
  for (size_t k = 0; k < document.order.size(); ++k) {
    const int beam = document.order[k];
    const FrameBeam& b = frame.beams[beam];
    out += std::to_string(b.id) + "," + std::to_string(b.inputId ? b.inputId : b.id);
    for (int end = 0; end < 2; ++end)
      out += "," + std::to_string(frame.joints[b.joints[end]].id) + "," + cubeFaceName(layout.endFace[beam][end]);
    out += "," + formatNumber(beamBodyLength(layout, beam)) + "," + formatNumber(frame.beamSection);
    for (int end = 0; end < 2; ++end) {
      if (document.labels.empty()) {
        out += ",,";
        continue;
      }
      const JointLabels& labels = document.labels[b.joints[end]];
      int count = 0;
      for (int label : labels) count += label == beam ? 1 : 0;
      out += "," + std::to_string(count) + "," + cellsText(labels, beam);
    }
    std::string removal = k + 1 == document.order.size() ? "stays" : "";
    if (k < document.directions.size()) {
      for (int face = 0; face < 6; ++face) {
        if (cubeFaceNormal(face) == document.directions[k]) removal = cubeFaceName(face);
      }
    }
    out += "," + removal + "\n";
  }
  return out;
}

std::vector<uint8_t> exportFrame(const FrameDocument& document, const std::string& format, int part,
                                 const std::string& source) {
  const Frame& frame = document.layout.frame;
  if (format == "fpuz" || format == "csv") {
    if (part != 0)
      throwBadInput(
          source, "a ." + format + " file holds the whole frame, so it cannot hold only part " + std::to_string(part));
    if (document.labels.empty())
      throwBadInput(source, "this frame has no designed joints yet: run desia design frame first");
    if (format == "csv") return bytesOf(frameCutListCsv(document));
    for (const FrameBeam& beam : frame.beams) {
      if (!beam.path.empty())
        throwBadInput(source, "beam " + std::to_string(beam.id) +
                                  " is curved, and .fpuz holds straight beams only; export stl, obj or csv");
    }
    return bytesOf(formatFpuz(document));
  }
  if (format == "puz" || format == "voxel-json" || format == "xmpuzzle") {
    // Axis-aligned frames on a common voxel grid, as the voxel puzzle they are (frame_voxels.cpp).
    if (part != 0)
      throwBadInput(source, "a voxel export holds the whole frame, so it cannot hold only part " + std::to_string(part));
    const AssemblyDocument voxels = frameVoxelDocument(document, source);
    if (format == "puz") return bytesOf(formatPuz(voxels.voxels));
    if (format == "voxel-json") return bytesOf(documentToJson(voxels) + "\n");
    return xmpuzzleFile(voxels, source);
  }
  if (format == "pieces-obj" || format == "joint-pieces-stl") {
    if (part != 0) throwBadInput(source, "a pieces export holds the whole frame, so it cannot hold only part " + std::to_string(part));
    std::vector<NamedMesh> pieces = pieceMeshes(document, source);
    const size_t jointPieces = pieces.size() - frame.beams.size();
    if (format == "pieces-obj") {
      return bytesOf(wavefrontObj(pieces, "frame pieces in place, " + std::to_string(frame.beams.size()) +
                                              " beam bodies and " + std::to_string(jointPieces) + " glued joint pieces"));
    }
    return bytesOf(binaryStl(jointPiecesOnAPlate(std::move(pieces), document.layout.voxelSize),
                             std::to_string(jointPieces) + " joint pieces to print and glue, laid out"));
  }
  if (format != "stl" && format != "stl-ascii" && format != "obj") {
    throwBadInput(source, "unknown export format '" + format +
                              "' for a frame (expected stl, stl-ascii, obj, pieces-stl, pieces-obj, fpuz, csv, puz, "
                              "voxel-json or xmpuzzle)");
  }
  const std::vector<NamedMesh> meshes = partMeshes(document, part, source);
  const std::string what = part == 0 ? std::to_string(frame.beams.size()) + " beams" : "part " + std::to_string(part);
  const std::string title = "frame export, " + what;
  if (format == "stl") return bytesOf(binaryStl(meshes, title));
  if (format == "stl-ascii") return bytesOf(asciiStl(meshes, part == 0 ? "frame" : "part" + std::to_string(part)));
  return bytesOf(wavefrontObj(meshes, title));
}

std::vector<PartSurface> framePartSurfaces(const FrameDocument& document) {
  std::vector<PartSurface> surfaces;
  for (const NamedMesh& named : partMeshes(document, 0, "<input>")) {
    PartSurface surface;
    surface.partId = named.partId;
    const TriangleMesh& mesh = named.mesh;
    for (const auto& triangle : mesh.triangles) {
      const auto& a = mesh.vertices[triangle[0]];
      const auto& b = mesh.vertices[triangle[1]];
      const auto& c = mesh.vertices[triangle[2]];
      double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                     (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                     (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (double& x : n) x = length > 0 ? x / length : 0;
      for (const auto* vertex : {&a, &b, &c}) {
        for (int k = 0; k < 3; ++k) {
          surface.positions.push_back(static_cast<float>((*vertex)[k]));
          surface.normals.push_back(static_cast<float>(n[k]));
        }
      }
    }
    surfaces.push_back(std::move(surface));
  }
  return surfaces;
}

}  // namespace desia
