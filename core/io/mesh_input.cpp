// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh assemblies read from OBJ and STL files, and their check reports.
#include "desia/formats.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "desia/analysis.h"
#include "desia/error.h"
#include "desia/mesh.h"
#include "three_mf.h"

namespace desia {
namespace {

std::string lowered(std::string text) {
  for (char& c : text) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  return text;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && lowered(text.substr(text.size() - suffix.size())) == suffix;
}

bool isBinaryStl(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
  const uint64_t count = p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<uint64_t>(p[3]) << 24);
  return 84 + 50 * count == bytes.size();
}

// The triangles of one group, with their own vertices (numbered in order of first use).
TriangleMesh subMesh(const TriangleMesh& mesh, const std::vector<size_t>& triangles) {
  TriangleMesh part;
  std::vector<int> renumbered(mesh.vertices.size(), -1);
  for (size_t t : triangles) {
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][static_cast<size_t>(k)];
      if (renumbered[static_cast<size_t>(v)] < 0) {
        renumbered[static_cast<size_t>(v)] = static_cast<int>(part.vertices.size());
        part.vertices.push_back(mesh.vertices[static_cast<size_t>(v)]);
      }
      corners[static_cast<size_t>(k)] = renumbered[static_cast<size_t>(v)];
    }
    part.triangles.push_back(corners);
  }
  return part;
}

void addObjParts(const MeshFile& file, std::vector<MeshPart>* parts) {
  const TriangleMesh mesh = parseObj(file.bytes, file.source);
  if (mesh.triangles.empty()) throwBadInput(file.source, "the OBJ file has no faces");
  if (mesh.groupNames.empty()) {
    parts->push_back({0, meshShapeName(file.source), file.source, mesh});
    return;
  }
  std::vector<std::vector<size_t>> byGroup(mesh.groupNames.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) byGroup[static_cast<size_t>(mesh.triangleGroup[t])].push_back(t);
  for (size_t g = 0; g < byGroup.size(); ++g) {
    if (byGroup[g].empty()) continue;  // a group record without faces (a material or an empty object)
    parts->push_back({0, mesh.groupNames[g], file.source, subMesh(mesh, byGroup[g])});
  }
}

// ASCII STL: each `solid ... endsolid` is a part; the text before each is kept as blank lines so
// that the reader's messages name the file's own line numbers.
void addAsciiStlParts(const MeshFile& file, std::vector<MeshPart>* parts) {
  size_t start = 0, lineStart = 0;
  int linesBefore = 0, line = 0;
  while (lineStart < file.bytes.size()) {
    size_t lineEnd = file.bytes.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = file.bytes.size();
    ++line;
    std::istringstream words(file.bytes.substr(lineStart, lineEnd - lineStart));
    std::string first;
    words >> first;
    lineStart = lineEnd + 1;
    if (lowered(first) != "endsolid") continue;
    const std::string text = std::string(static_cast<size_t>(linesBefore), '\n') +
                             file.bytes.substr(start, std::min(lineStart, file.bytes.size()) - start);
    std::istringstream head(file.bytes.substr(start, 256));
    std::string keyword, name;
    head >> keyword;
    std::getline(head, name);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t\r") + 1);
    parts->push_back({0, name.empty() ? meshShapeName(file.source) : name, file.source, parseStl(text, file.source)});
    start = std::min(lineStart, file.bytes.size());
    linesBefore = line;
  }
  const std::string rest = file.bytes.substr(start);
  if (rest.find_first_not_of(" \t\r\n") != std::string::npos || parts->empty()) {
    // Text after the last endsolid, or none at all: the reader names what is wrong.
    parts->push_back({0, meshShapeName(file.source), file.source,
                      parseStl(std::string(static_cast<size_t>(linesBefore), '\n') + rest, file.source)});
  }
}

// Names for the JSON report: file, object and solid names are whatever bytes the files hold, and
// JSON text must be UTF-8, so an invalid sequence becomes U+FFFD (found by the mesh_assembly fuzz
// harness: the writer threw on such a name).
std::string validUtf8(const std::string& text) {
  return nlohmann::json::parse(nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))
      .get<std::string>();
}

}  // namespace

LengthUnit parseLengthUnit(const std::string& name) {
  if (name == "mm") return LengthUnit::Millimetre;
  if (name == "m") return LengthUnit::Metre;
  if (name == "inch" || name == "in") return LengthUnit::Inch;
  throw Error(ErrorCode::BadInput, "unknown unit '" + name + "': expected mm, m or inch");
}

double millimetresPer(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Metre: return 1000.0;
    case LengthUnit::Inch: return 25.4;
    case LengthUnit::Millimetre: break;
  }
  return 1.0;
}

bool isMeshAssemblyPath(const std::string& path) {
  return endsWith(path, ".obj") || endsWith(path, ".stl") || endsWith(path, ".3mf");
}

std::vector<MeshPart> readMeshParts(const std::vector<MeshFile>& files, LengthUnit unit) {
  std::vector<MeshPart> parts;
  for (const MeshFile& file : files) {
    if (file.bytes.find_first_not_of(" \t\r\n") == std::string::npos) throwBadInput(file.source, "the file is empty");
    const size_t before = parts.size();
    if (endsWith(file.source, ".3mf")) {
      // In millimetres already: a 3MF model says its unit itself.
      for (MeshPart& part : readThreeMfParts(file.bytes, file.source)) parts.push_back(std::move(part));
    } else if (isBinaryStl(file.bytes)) {
      parts.push_back({0, meshShapeName(file.source), file.source, parseStl(file.bytes, file.source)});
    } else if (endsWith(file.source, ".stl") || lowered(file.bytes.substr(0, 5)) == "solid") {
      addAsciiStlParts(file, &parts);
    } else {
      addObjParts(file, &parts);
    }
    if (parts.size() - before > 1 || parts.back().name.empty()) {
      for (size_t k = before; k < parts.size(); ++k) {
        if (parts[k].name.empty()) parts[k].name = meshShapeName(file.source) + "#" + std::to_string(k - before + 1);
      }
    }
  }
  const double scale = millimetresPer(unit);
  for (size_t k = 0; k < parts.size(); ++k) {
    parts[k].id = static_cast<int>(k + 1);
    if (endsWith(parts[k].source, ".3mf")) continue;
    for (auto& v : parts[k].mesh.vertices) v = {v[0] * scale, v[1] * scale, v[2] * scale};
  }
  return parts;
}

MeshCheck checkMeshFiles(const std::vector<MeshFile>& files, LengthUnit unit, const MeshAssemblyOptions& meshOptions,
                         const CheckOptions& options) {
  MeshCheck check{buildMeshAssembly(readMeshParts(files, unit), meshOptions), {}};
  check.report = checkMeshAssembly(check.meshes, options);
  return check;
}

std::vector<PartSurface> meshPartSurfaces(const std::vector<MeshFile>& files, LengthUnit unit) {
  std::vector<PartSurface> surfaces;
  for (const MeshPart& part : readMeshParts(files, unit)) {
    PartSurface surface;
    surface.partId = part.id;
    for (const std::array<int, 3>& triangle : part.mesh.triangles) {
      const Vec3& a = part.mesh.vertices[static_cast<size_t>(triangle[0])];
      const Vec3& b = part.mesh.vertices[static_cast<size_t>(triangle[1])];
      const Vec3& c = part.mesh.vertices[static_cast<size_t>(triangle[2])];
      Vec3 normal = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                     (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                     (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
      const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      for (double& x : normal) x = length > 0 ? x / length : 0;  // a sliver draws unlit rather than NaN
      for (const Vec3* corner : {&a, &b, &c}) {
        for (size_t k = 0; k < 3; ++k) {
          surface.positions.push_back(static_cast<float>((*corner)[k]));
          surface.normals.push_back(static_cast<float>(normal[k]));
        }
      }
    }
    surfaces.push_back(std::move(surface));
  }
  return surfaces;
}

AssemblyDocument meshReportDocument(const MeshAssembly& meshes) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Contacts;
  document.name = validUtf8(meshShapeName(meshes.parts.front().source));
  document.assembly = meshes.assembly;
  return document;
}

std::string meshCheckReportToJson(const MeshAssembly& meshes, const CheckReport& report, int indent) {
  nlohmann::json root = nlohmann::json::parse(checkReportToJson(meshReportDocument(meshes), report, -1));
  root["kind"] = "mesh";
  size_t triangles = 0;
  for (const MeshPart& part : meshes.parts) triangles += part.mesh.triangles.size();
  root["mesh"] = {{"tolerance", meshes.tolerance},
                  {"diagonal", meshes.diagonal},
                  {"planarFaces", meshes.faceCount},
                  {"contacts", meshes.assembly.contacts.size()},
                  {"triangles", triangles}};
  // The parts' own names (OBJ objects or groups, STL solids or files), in the order of partIds.
  nlohmann::json names = nlohmann::json::array();
  for (const MeshPart& part : meshes.parts) names.push_back(validUtf8(part.name));
  root["mesh"]["partNames"] = names;
  // Curved contact regions, approximated by their planar facets (docs/meshes.md).
  nlohmann::json curved = nlohmann::json::array();
  for (const CurvedContact& region : meshes.curvedContacts) {
    curved.push_back({{"parts", {meshes.parts[static_cast<size_t>(region.a)].id, meshes.parts[static_cast<size_t>(region.b)].id}},
                      {"facets", region.facets},
                      {"area", region.area}});
  }
  root["mesh"]["curvedContacts"] = curved;
  for (const char* section : {"disassembly", "disassemblyFailure"}) {
    if (!report.disassembly || !root.contains(section) || !root[section].is_object() || !root[section].contains("steps")) {
      continue;
    }
    auto& steps = root[section]["steps"];
    for (size_t k = 0; k < steps.size() && k < report.disassembly->moves.size(); ++k) {
      const GroupMove& move = report.disassembly->moves[k];
      const Vec3& d = move.direction;
      steps[k]["dir"] = directionLabel(d);
      steps[k]["vector"] = {d[0], d[1], d[2]};
      // A finite move's length in mm, and the move itself in mm (the voxel kind's are whole cells).
      const double length = move.out ? 1.0 : move.length;
      steps[k]["move"] = {d[0] * length, d[1] * length, d[2] * length};
      if (!move.out) steps[k]["length"] = move.length;
    }
  }
  return root.dump(indent);
}

std::string meshCheckReportToText(const MeshAssembly& meshes, const CheckReport& report) {
  size_t triangles = 0;
  for (const MeshPart& part : meshes.parts) triangles += part.mesh.triangles.size();
  std::ostringstream out;
  out << "meshes: " << meshes.parts.size() << " parts, " << triangles << " triangles, " << meshes.faceCount
      << " planar faces, " << meshes.assembly.contacts.size() << " contacts (tolerance " << meshes.tolerance << " mm)\n";
  if (!meshes.curvedContacts.empty()) {
    out << "curved contacts, approximated by their planar facets:";
    for (const CurvedContact& region : meshes.curvedContacts) {
      out << (&region == &meshes.curvedContacts.front() ? " " : "; ") << "parts "
          << meshes.parts[static_cast<size_t>(region.a)].id << " and " << meshes.parts[static_cast<size_t>(region.b)].id
          << " (" << region.facets << " facets, " << region.area << " mm²)";
    }
    out << "\n";
  }
  std::string text = checkReportToText(meshReportDocument(meshes), report);
  const std::string contactsKind = " (contacts)\n";  // the first line names the parts' kind
  const size_t kind = text.find(contactsKind);
  if (kind != std::string::npos && kind < text.find('\n')) text.replace(kind, contactsKind.size(), " (mesh)\n");
  return out.str() + text;
}

}  // namespace desia
