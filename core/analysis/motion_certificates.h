// SPDX-License-Identifier: GPL-3.0-or-later
// Certificates of the inequality test's answers (paper Section 3.2, Eq. 2; see
// inequality_interlocking.cpp): a motion checked against every contact, "no motion" by weak
// duality, and, for programs of difference constraints (axis-aligned normals: every voxel
// assembly), both built by graph algorithms in linear time without GLPK.
#pragma once

#include <optional>
#include <vector>

#include "analysis/linear_program.h"
#include "desia/model.h"

namespace desia::inequality {

// c·x for the program's objective c.
double objectiveAt(const LinearProgramSpec& spec, const std::vector<double>& x);
// The motion certificate: x (clamped to its bounds) penetrates no row by more than kPenetration and
// reaches kMotion.
bool certifiesMotion(const LinearProgramSpec& spec, std::vector<double>* x);
// The no-motion certificate: the weak-duality bound of GLPK's row duals (either sign) stays below
// kMotion.
bool certifiesNoMotion(const LinearProgramSpec& spec, const std::vector<double>& rowDuals);

// A breadth-first tree: per node the row joining it to its parent (-1 for a root or a node not in
// the tree), and the nodes in breadth-first order.
struct FlowTree {
  std::vector<int> row;
  std::vector<int> order;
};

struct FreeGroupCandidate {
  int component = -1;
  double sign = 1.0;  // +1: a sink moving up; -1: a source moving down
};

// Edges as rows, for the breadth-first searches: the rows leaving (entering) each node.
struct RowAdjacency {
  std::vector<int> start, rows;
};

struct DifferenceGraph {
  int ground = -1;                  // the node of the fixed parts (= the column count)
  std::vector<int> rowFrom, rowTo;  // per row its edge, -1 for a row without entries
  RowAdjacency leaving, entering;
  StronglyConnectedComponents scc;
  std::vector<FreeGroupCandidate> candidates;  // sinks and sources, smallest first
  std::vector<int> componentsBySize;           // every component but the ground's, smallest first
  FlowTree towardRoot, fromRoot;               // inside each component, to and from its root
  FlowTree towardGround, fromGround;           // in the whole graph, to and from the ground
};

// The program as a graph of difference constraints, or nothing when a row is not one.
std::optional<DifferenceGraph> differenceGraph(const LinearProgramSpec& spec);
// The smallest free group of the graph whose motion reaches the objective, checked as a motion.
std::optional<std::vector<double>> graphMotion(const DifferenceGraph& graph, const LinearProgramSpec& spec);
// A flow certifying that the objective stays below kMotion, checked by the dual bound.
bool graphCertifiesNoMotion(const DifferenceGraph& graph, const LinearProgramSpec& spec);

// --- A certificate from cones: programs of one free part ---------------------------------------
//
// Row multipliers y >= 0 for a program of at most three columns (one part free, the rest fixed:
// round 1 of the test, where every part but the key is blocked), with c + Aᵀy = 0 up to rounding,
// or nothing. By Carathéodory's theorem -c lies in the cone of the rows exactly when it lies in the
// cone of at most three independent ones, so the search tries the rows' distinct directions one,
// two and three at a time. The caller checks the result with certifiesNoMotion, as GLPK's duals.
std::optional<std::vector<double>> coneNoMotionDuals(const LinearProgramSpec& spec);

}  // namespace desia::inequality
