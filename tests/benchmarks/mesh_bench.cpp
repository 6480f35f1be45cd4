// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh kind's benchmark (issue 29): a grid of touching boxes, each face a k x k grid of
// squares (12 k² triangles a part; k = 9 gives 972), built (validation, overlaps, contacts) and
// checked (DBG test and a swept plan). Prints one row per size: parts, triangles, seconds. A file
// (OBJ, STL, 3MF) is read and checked as `desia check FILE` does: a row with its plan's level;
// `--dented FILE.obj` first pushes the vertex farthest along each diagonal (±1, ±1, ±1) a quarter
// mm into its part, off any lattice, as tests/core/mesh_group_search_test.cpp does.
//   desia_mesh_bench [PARTS | FILE | --dented FILE.obj ...]   (default 100 1000; parts are rounded to a grid nx × ny × nz)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "desia/formats.h"
#include "desia/mesh.h"
#include "mesh/mesh_geometry.h"
#include "mesh/mesh_group_search.h"
#include "obj_edits.h"  // tests/core: the dents the mesh tests make

namespace {

constexpr int kFaceDivisions = 9;
constexpr double kBoxMm = 10;
// --dented: how far each diagonal's farthest vertex is pushed in (a quarter of the exports' 1 mm cells).
constexpr double kDentMm = 0.25;

// One box with every face divided into k x k squares (two triangles each), outward.
desia::TriangleMesh dividedBox(const desia::Vec3& corner) {
  desia::TriangleMesh mesh;
  const int k = kFaceDivisions;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int first = static_cast<int>(mesh.vertices.size());
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= k; ++j) {
          desia::Vec3 p = corner;
          p[axis] += side * kBoxMm;
          p[u] += kBoxMm * i / k;
          p[v] += kBoxMm * j / k;
          mesh.vertices.push_back(p);
        }
      }
      for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) {
          const int a = first + i * (k + 1) + j, b = a + k + 1, c = b + 1, d = a + 1;
          // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
          if (side == 1) {
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
          } else {
            mesh.triangles.push_back({a, c, b});
            mesh.triangles.push_back({a, d, c});
          }
        }
      }
    }
  }
  return mesh;  // duplicate vertices along box edges: the validation works on indices, so weld
}

desia::TriangleMesh welded(const desia::TriangleMesh& mesh) {
  desia::TriangleMesh out;
  std::vector<int> index(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    int found = -1;
    for (size_t w = 0; w < out.vertices.size() && found < 0; ++w) {
      if (out.vertices[w] == mesh.vertices[v]) found = static_cast<int>(w);
    }
    if (found < 0) {
      found = static_cast<int>(out.vertices.size());
      out.vertices.push_back(mesh.vertices[v]);
    }
    index[v] = found;
  }
  for (const auto& t : mesh.triangles) out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return out;
}

void run(int requested) {
  const int nx = static_cast<int>(std::round(std::cbrt(requested)));
  const int ny = nx, nz = (requested + nx * ny - 1) / (nx * ny);
  const desia::TriangleMesh unit = welded(dividedBox({0, 0, 0}));
  std::vector<desia::MeshPart> parts;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx && static_cast<int>(parts.size()) < requested; ++x) {
        desia::MeshPart part;
        part.id = static_cast<int>(parts.size()) + 1;
        part.source = "grid";
        part.mesh = unit;
        for (auto& v : part.mesh.vertices) v = {v[0] + x * kBoxMm, v[1] + y * kBoxMm, v[2] + z * kBoxMm};
        parts.push_back(part);
      }
    }
  }
  const size_t triangles = parts.size() * unit.triangles.size();
  const auto start = std::chrono::steady_clock::now();
  const desia::MeshAssembly meshes = desia::buildMeshAssembly(std::move(parts));
  const auto built = std::chrono::steady_clock::now();
  const desia::CheckReport report = desia::checkMeshAssembly(meshes);
  const auto done = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("| %zu parts | %zu triangles | %zu contacts | build %.3f s | check %.3f s | total %.3f s | plan %s |\n",
              meshes.parts.size(), triangles, meshes.assembly.contacts.size(), seconds(start, built),
              seconds(built, done), seconds(start, done),
              report.disassembly && report.disassembly->complete ? "complete" : "INCOMPLETE");
}

// A mesh assembly from a file (PelikanBurr exported as OBJ: its plan needs the voxel disassembler;
// dented, the search for moves of several parts off any lattice).
void runFile(const std::string& path, bool dented) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    std::exit(2);
  }
  std::string bytes;
  char buffer[65536];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) bytes.append(buffer, n);
  std::fclose(file);
  if (dented) bytes = desia::testing::dentedObj(bytes, kDentMm);
  const auto start = std::chrono::steady_clock::now();
  const desia::MeshAssembly meshes = desia::buildMeshAssembly(desia::readMeshParts({{path, bytes}}));
  const auto built = std::chrono::steady_clock::now();
  const desia::CheckReport report = desia::checkMeshAssembly(meshes);
  const auto done = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  size_t triangles = 0;
  for (const desia::MeshPart& part : meshes.parts) triangles += part.mesh.triangles.size();
  std::string level;
  if (report.disassembly) {
    for (int moves : report.disassembly->level) level += (level.empty() ? "" : ".") + std::to_string(moves);
  }
  std::printf("| %s%s: %zu parts | %zu triangles | %zu contacts | build %.3f s | check %.3f s | total %.3f s | plan %s, level %s, %zu moves, %lld positions |\n",
              dented ? "dented " : "", path.c_str(), meshes.parts.size(), triangles, meshes.assembly.contacts.size(), seconds(start, built),
              seconds(built, done), seconds(start, done),
              report.disassembly && report.disassembly->complete ? "complete" : "INCOMPLETE", level.c_str(),
              report.disassembly ? report.disassembly->moves.size() : size_t{0},
              static_cast<long long>(report.disassembly ? report.disassembly->groupStates : 0));
  if (dented) {  // the search's own counts, against its bounds (GroupSearchLimits)
    desia::mesh::GroupSearchStats stats;
    const auto searchStart = std::chrono::steady_clock::now();
    desia::mesh::searchGroupMoves(meshes, desia::mesh::geometryOf(meshes), {}, &stats);
    std::printf("|   search alone: %.3f s, %lld sweeps of part pairs, %lld steps of work (bound %lld) |\n",
                seconds(searchStart, std::chrono::steady_clock::now()), static_cast<long long>(stats.pairSweeps),
                static_cast<long long>(stats.work), static_cast<long long>(desia::mesh::GroupSearchLimits{}.work));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--dented" && k + 1 < argc) {
      runFile(argv[++k], true);
    } else if (desia::isMeshAssemblyPath(arg)) {
      runFile(arg, false);
    } else {
      sizes.push_back(std::atoi(argv[k]));
    }
  }
  if (sizes.empty() && argc == 1) sizes = {100, 1000};
  for (int size : sizes) run(size);
  return 0;
}
