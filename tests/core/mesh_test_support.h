// SPDX-License-Identifier: GPL-3.0-or-later
// What the mesh assembly tests share: other kinds exported by desia's own exporters and read back
// as meshes, turned and scaled, and an independent check of a plan (parts moved in small steps,
// overlap tested by the winding numbers of points sampled inside them: nothing of the sweep).
#pragma once

#include <array>
#include <random>
#include <string>
#include <vector>

#include "desia/analysis.h"
#include "desia/document.h"
#include "desia/formats.h"
#include "desia/mesh.h"

namespace desia::testing {

AssemblyDocument readDocument(const std::string& path);

// The first file of exporting `document` in `format` (part 0 = all parts).
std::string exported(const AssemblyDocument& document, const char* format, int part = 0);

CheckOptions bothTests();

MeshAssembly meshesOf(const std::vector<MeshFile>& files, LengthUnit unit = LengthUnit::Millimetre);

// The OBJ text with every vertex turned by `rotation` and divided by `unitInMm` (so that reading it
// in that unit gives back millimetres).
std::string transformedObj(const std::string& obj, const std::array<Vec3, 3>& rotation, double unitInMm);

// A uniformly random rotation (a random unit quaternion) from a seeded generator.
std::array<Vec3, 3> randomRotation(std::mt19937& random);

// Generalized winding number of a closed mesh around p (solid angles of its triangles, Van
// Oosterom and Strackee): about 1 inside, 0 outside.
double windingNumber(const TriangleMesh& mesh, const Vec3& p);

// "" when the plan's single-part removals, replayed in small steps, never put a sample point of a
// moving part inside a part still in place (or one of theirs inside it); else what collided.
std::string replayFailure(const MeshAssembly& meshes, const DisassemblyPlan& plan);

// The same for a plan's moves of several parts (`moves`): each move's parts stepped along it
// against the parts of their sub-assembly that stay, from where the moves before left them (a move
// out until their boxes clear the rest, then a sub-assembly of their own); and in the end every
// sub-assembly is one part when the plan is complete.
std::string replayMovesFailure(const MeshAssembly& meshes, const DisassemblyPlan& plan);

}  // namespace desia::testing
