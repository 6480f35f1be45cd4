// SPDX-License-Identifier: GPL-3.0-or-later
// A mesh assembly built and checked: parts validated, contacts computed, the check of every kind
// with the plan that sweeps the real shapes.
#include <cmath>
#include <memory>

#include "desia/error.h"
#include "desia/tolerances.h"
#include "mesh/mesh_geometry.h"

namespace desia {

MeshAssembly buildMeshAssembly(std::vector<MeshPart> parts, const MeshAssemblyOptions& options) {
  if (parts.empty()) throw Error(ErrorCode::BadInput, "a mesh assembly needs at least one part");
  mesh::Box all;
  for (const MeshPart& part : parts) {
    for (const Vec3& v : part.mesh.vertices) all.add(v);
  }
  MeshAssembly meshes;
  meshes.diagonal = norm(minus(all.hi, all.lo));
  if (!std::isfinite(meshes.diagonal) || meshes.diagonal <= 0) {
    throw Error(ErrorCode::BadInput, parts.front().source + ": the parts have no extent (diagonal " +
                                         std::to_string(meshes.diagonal) + " mm)");
  }
  if (!(options.contactTolerance >= 0) || !std::isfinite(options.contactTolerance)) {
    throw Error(ErrorCode::BadInput, "contact tolerance " + std::to_string(options.contactTolerance) +
                                         " mm: expected a finite length >= 0 (0 = scaled to the model)");
  }
  meshes.tolerance =
      options.contactTolerance > 0 ? options.contactTolerance : tolerance::kMeshContactShare * meshes.diagonal;
  const double emptyArea = tolerance::kMeshEmptyAreaShare * meshes.diagonal * meshes.diagonal;
  for (MeshPart& part : parts) mesh::requireClosedOrientedPart(part, emptyArea * meshes.tolerance);
  auto geometry = std::make_shared<const std::vector<mesh::PartGeometry>>(mesh::partGeometries(parts));
  mesh::requireNoOverlaps(parts, *geometry, meshes.tolerance);
  meshes.assembly.contacts = mesh::meshContacts(parts, *geometry, meshes.tolerance, emptyArea, &meshes.faceCount,
                                                 &meshes.curvedContacts);
  meshes.geometry = std::move(geometry);
  for (const MeshPart& part : parts) meshes.assembly.parts.push_back({part.id, part.name});
  meshes.parts = std::move(parts);
  return meshes;
}

CheckReport checkMeshAssembly(const MeshAssembly& meshes, const CheckOptions& options) {
  const std::vector<mesh::PartGeometry>& geometry = mesh::geometryOf(meshes);
  std::string latticeNote;
  CheckReport report = checkContacts(meshes.assembly, options,
                                     [&](const Assembly&) { return mesh::planWithGeometry(meshes, geometry, &latticeNote); });
  ShapeRemovalCheck check;
  check.checked = "contacts from the meshes' planar faces (tolerance " + std::to_string(meshes.tolerance) +
                  " mm); each step of the plan swept past the parts in place, triangle against triangle";
  if (!latticeNote.empty()) check.checked += "; " + latticeNote;
  if (report.disassembly && !report.disassembly->complete) {
    check.failure = report.disassembly->searchLimitReached
                        ? "the plan stopped short (" + report.disassembly->limit + "): the parts left are not proven stuck"
                        : "no translation separates the parts left: the plan is stuck";
  }
  report.shapeRemoval = check;
  return report;
}

}  // namespace desia
