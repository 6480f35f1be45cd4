// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/motion_certificates.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include "desia/tolerances.h"

namespace desia::inequality {

using tolerance::kMotion;
using tolerance::kPenetration;

double objectiveAt(const LinearProgramSpec& spec, const std::vector<double>& x) {
  double value = 0;
  for (int j = 0; j < spec.columnCount(); ++j) value += spec.objective[j] * x[j];
  return value;
}

// The motion certificate: x within the bounds, no row below -kPenetration, objective >= kMotion.
bool certifiesMotion(const LinearProgramSpec& spec, std::vector<double>* x) {
  for (int j = 0; j < spec.columnCount(); ++j) (*x)[j] = std::clamp((*x)[j], spec.columnLower[j], spec.columnUpper[j]);
  std::vector<double> rowValue(spec.rowCount(), 0.0);
  for (size_t k = 0; k < spec.entryValue.size(); ++k) rowValue[spec.entryRow[k]] += spec.entryValue[k] * (*x)[spec.entryColumn[k]];
  for (int r = 0; r < spec.rowCount(); ++r) {
    if (rowValue[r] < -kPenetration) return false;
  }
  return objectiveAt(spec, *x) >= kMotion;
}

namespace {

// Weak duality for maximize c·x, Ax >= -kPenetration, |x_j| <= 1: for any y >= 0 and any such x,
// c·x = (c + Aᵀy)·x - y·Ax <= Σ_j |c + Aᵀy|_j + kPenetration Σ y. GLPK's row duals supply y
// (their sign convention does not matter: both signs are tried, each bound is valid). The bound
// is padded by the rounding error of computing it.
double dualBound(const LinearProgramSpec& spec, const std::vector<double>& rowDuals, double sign) {
  std::vector<double> y(spec.rowCount());
  double ySum = 0;
  for (int r = 0; r < spec.rowCount(); ++r) {
    y[r] = std::max(0.0, sign * rowDuals[r]);
    if (!std::isfinite(y[r])) return HUGE_VAL;
    ySum += y[r];
  }
  std::vector<double> reduced = spec.objective;
  double magnitude = 0;
  for (double c : spec.objective) magnitude += std::abs(c);
  for (size_t k = 0; k < spec.entryValue.size(); ++k) {
    const double term = spec.entryValue[k] * y[spec.entryRow[k]];
    reduced[spec.entryColumn[k]] += term;
    magnitude += std::abs(term);
  }
  double bound = kPenetration * ySum;
  for (int j = 0; j < spec.columnCount(); ++j) {
    bound += std::abs(reduced[j]) * std::max(std::abs(spec.columnLower[j]), std::abs(spec.columnUpper[j]));
  }
  return bound + 64 * DBL_EPSILON * magnitude;
}

}  // namespace

bool certifiesNoMotion(const LinearProgramSpec& spec, const std::vector<double>& rowDuals) {
  return std::min(dualBound(spec, rowDuals, -1.0), dualBound(spec, rowDuals, 1.0)) < kMotion;
}

// --- Certificates from graphs: programs of difference constraints ------------------------------
//
// When every row of a motion program is a difference constraint, v_w - v_u >= 0 (coefficients +1
// and -1) or ±v_w >= 0 (the other side fixed), as with axis-aligned contact normals (every voxel
// assembly), the program is a network program and both of its answers have certificates that
// graph algorithms build in linear time. Read each row as an edge u -> w ("if u moves up, w must
// move at least as much"), with all fixed parts one ground node g (v = 0): u -> g for -v_u >= 0,
// g -> w for v_w >= 0. A column is one part's velocity along one axis, so the graph holds the
// blocking graphs along +x, +y and +z of the free parts, joined at the fixed ones.
// - A motion: a strongly connected component S without g and without outgoing edges (a sink) can
//   move up as a block, v = +1 on S; one without incoming edges (a source) down, v = -1 on S. These
//   are the DBG test's free groups with the fixed parts held still; the smallest one that reaches
//   the program's objective is proposed.
// - No motion: a flow y >= 0 along the edges leaving c_j net at every column j, i.e. Aᵀy = -c,
//   so that weak duality bounds the objective by kPenetration Σy (certifiesNoMotion). Inside each
//   component the flow runs to and from a root along breadth-first trees; what is left at a
//   component's root runs to or from the ground along breadth-first trees of the whole graph.
//   This finds a flow whenever every column that the objective weighs is held by the fixed parts
//   (in the ground's component), and for Eq. 2's objective whenever no contact it counts can
//   separate (its rows then lie inside components, and each component's sum is 0).
// Neither answer is trusted: the motion is checked against every row and the flow by the dual
// bound, exactly like GLPK's answers, so a program's answer (and the verdict) is the one that
// GLPK's certified route gives; when neither certificate holds, GLPK decides as before. Only the
// witness may differ from GLPK's: another valid motion, a smallest free group along one axis.

namespace {

RowAdjacency adjacencyBy(const std::vector<int>& endpoint, int nodeCount) {
  RowAdjacency adjacency;
  adjacency.start.assign(nodeCount + 1, 0);
  for (int node : endpoint) {
    if (node >= 0) ++adjacency.start[node + 1];
  }
  for (int node = 0; node < nodeCount; ++node) adjacency.start[node + 1] += adjacency.start[node];
  adjacency.rows.resize(adjacency.start[nodeCount]);
  std::vector<int> next(adjacency.start.begin(), adjacency.start.end() - 1);
  for (int r = 0; r < static_cast<int>(endpoint.size()); ++r) {
    if (endpoint[r] >= 0) adjacency.rows[next[endpoint[r]]++] = r;
  }
  return adjacency;
}

// Breadth-first from `roots` along rows of `adjacency` (the rows at a node), stepping to the
// row's `other` end when `admit(node, next)` allows it.
template <typename Admit>
FlowTree breadthFirstTree(int nodeCount, const std::vector<int>& roots, const RowAdjacency& adjacency,
                          const std::vector<int>& other, Admit&& admit) {
  FlowTree tree;
  tree.row.assign(nodeCount, -1);
  std::vector<bool> seen(nodeCount, false);
  for (int root : roots) {
    seen[root] = true;
    tree.order.push_back(root);
  }
  for (size_t head = 0; head < tree.order.size(); ++head) {
    const int node = tree.order[head];
    for (int k = adjacency.start[node]; k < adjacency.start[node + 1]; ++k) {
      const int r = adjacency.rows[k];
      const int next = other[r];
      if (seen[next] || !admit(node, next)) continue;
      seen[next] = true;
      tree.row[next] = r;
      tree.order.push_back(next);
    }
  }
  return tree;
}


// The nodes that `start`'s component reaches along the rows of `adjacency` (`other`: their far
// ends), itself included; nothing when the ground is among them or the search has spent `budget`
// (edges looked at, shared by the searches of one program).
std::optional<std::vector<int>> closureOf(const DifferenceGraph& graph, int component, const RowAdjacency& adjacency,
                                          const std::vector<int>& other, int64_t* budget) {
  *budget -= graph.ground + 1;
  if (*budget < 0) return std::nullopt;
  std::vector<int> nodes = graph.scc.components[component];
  std::vector<bool> seen(graph.ground + 1, false);
  for (int node : nodes) seen[node] = true;
  for (size_t head = 0; head < nodes.size(); ++head) {
    const int node = nodes[head];
    for (int k = adjacency.start[node]; k < adjacency.start[node + 1]; ++k) {
      if (--*budget < 0) return std::nullopt;
      const int next = other[adjacency.rows[k]];
      if (next == graph.ground) return std::nullopt;
      if (seen[next]) continue;
      seen[next] = true;
      nodes.push_back(next);
    }
  }
  return nodes;
}

// Moves `members` by `sign` when that reaches the objective and checks as a motion.
std::optional<std::vector<double>> motionOfGroup(const LinearProgramSpec& spec, const std::vector<int>& members, double sign) {
  double value = 0;
  for (int j : members) value += spec.objective[j];
  if (sign * value < kMotion) return std::nullopt;
  std::vector<double> x(spec.columnCount(), 0.0);
  for (int j : members) x[j] = sign;
  if (!certifiesMotion(spec, &x)) return std::nullopt;
  return x;
}


// Moves what `amount` holds at the tree's nodes to its roots (rows toward the roots, `parentEnd`
// their heads: each node's amount leaves it) or brings it from them (rows from the roots,
// `parentEnd` their tails: each node's amount arrives), adding it to the flow y of the rows.
// Amounts at the roots and at nodes outside the tree stay where they are.
void routeAlongTree(const FlowTree& tree, const std::vector<int>& parentEnd, std::vector<double>* amount,
                    std::vector<double>* y) {
  std::vector<double>& at = *amount;
  for (auto it = tree.order.rbegin(); it != tree.order.rend(); ++it) {
    const int node = *it;
    const int r = tree.row[node];
    if (r < 0 || at[node] == 0.0) continue;
    (*y)[r] += at[node];
    at[parentEnd[r]] += at[node];
    at[node] = 0.0;
  }
}

}  // namespace

// The graph of a program whose rows are all difference constraints within [-1, 1] bounds, or
// nothing when some row or bound is of another kind (then GLPK alone decides).
std::optional<DifferenceGraph> differenceGraph(const LinearProgramSpec& spec) {
  const int columns = spec.columnCount();
  const int rows = spec.rowCount();
  for (int j = 0; j < columns; ++j) {
    if (spec.columnLower[j] != -1.0 || spec.columnUpper[j] != 1.0) return std::nullopt;
  }
  std::vector<int> entries(rows, 0), plusColumn(rows, -1), minusColumn(rows, -1);
  for (size_t k = 0; k < spec.entryValue.size(); ++k) {
    const int r = spec.entryRow[k];
    const double value = spec.entryValue[k];
    if (value != 1.0 && value != -1.0) return std::nullopt;
    int& column = value == 1.0 ? plusColumn[r] : minusColumn[r];
    if (column >= 0) return std::nullopt;  // two entries of one sign
    column = spec.entryColumn[k];
    ++entries[r];
  }
  DifferenceGraph graph;
  graph.ground = columns;
  const int nodes = columns + 1;
  graph.rowFrom.assign(rows, -1);
  graph.rowTo.assign(rows, -1);
  DirectedGraph directed(nodes);
  for (int r = 0; r < rows; ++r) {
    if (entries[r] == 0) continue;  // 0 >= 0: no constraint
    graph.rowFrom[r] = minusColumn[r] >= 0 ? minusColumn[r] : graph.ground;
    graph.rowTo[r] = plusColumn[r] >= 0 ? plusColumn[r] : graph.ground;
    directed.addEdge(graph.rowFrom[r], graph.rowTo[r]);
  }
  graph.scc = findStronglyConnectedComponents(directed);
  const CondensationDegrees degrees = condensationDegrees(directed, graph.scc);
  const int groundComponent = graph.scc.componentOf[graph.ground];
  for (int c = 0; c < graph.scc.count(); ++c) {
    if (c == groundComponent) continue;
    if (!degrees.hasOutEdge[c]) graph.candidates.push_back({c, 1.0});
    if (!degrees.hasInEdge[c]) graph.candidates.push_back({c, -1.0});
  }
  auto smaller = [&](int a, int b) { return graph.scc.components[a].size() < graph.scc.components[b].size(); };
  std::stable_sort(graph.candidates.begin(), graph.candidates.end(),
                   [&](const auto& a, const auto& b) { return smaller(a.component, b.component); });
  for (int c = 0; c < graph.scc.count(); ++c) {
    if (c != groundComponent) graph.componentsBySize.push_back(c);
  }
  std::stable_sort(graph.componentsBySize.begin(), graph.componentsBySize.end(), smaller);

  graph.leaving = adjacencyBy(graph.rowFrom, nodes);
  graph.entering = adjacencyBy(graph.rowTo, nodes);
  const RowAdjacency& leaving = graph.leaving;
  const RowAdjacency& entering = graph.entering;
  std::vector<int> roots;
  for (int c = 0; c < graph.scc.count(); ++c) roots.push_back(c == groundComponent ? graph.ground : graph.scc.components[c][0]);
  auto sameComponent = [&](int a, int b) { return graph.scc.componentOf[a] == graph.scc.componentOf[b]; };
  auto anyNode = [](int, int) { return true; };
  // Toward a root: walk backwards along the rows entering a node, to their tails.
  graph.towardRoot = breadthFirstTree(nodes, roots, entering, graph.rowFrom, sameComponent);
  graph.fromRoot = breadthFirstTree(nodes, roots, leaving, graph.rowTo, sameComponent);
  graph.towardGround = breadthFirstTree(nodes, {graph.ground}, entering, graph.rowFrom, anyNode);
  graph.fromGround = breadthFirstTree(nodes, {graph.ground}, leaving, graph.rowTo, anyNode);
  return graph;
}

// The smallest free group of the graph whose motion reaches the objective, checked as a motion.
// Failing that, a component with all it carries along: all it reaches moving up, or all that
// reaches it moving down, when the ground is not among them (the watched parts may be free only
// together with an unwatched one: the key, in round 2). Those searches stop after a few passes
// over the edges; GLPK decides what they leave open.
std::optional<std::vector<double>> graphMotion(const DifferenceGraph& graph, const LinearProgramSpec& spec) {
  for (const FreeGroupCandidate& candidate : graph.candidates) {
    if (auto x = motionOfGroup(spec, graph.scc.components[candidate.component], candidate.sign)) return x;
  }
  int64_t budget = 4 * (static_cast<int64_t>(graph.rowFrom.size()) + graph.ground + 1);
  for (int component : graph.componentsBySize) {
    if (auto up = closureOf(graph, component, graph.leaving, graph.rowTo, &budget)) {
      if (auto x = motionOfGroup(spec, *up, 1.0)) return x;
    }
    if (auto down = closureOf(graph, component, graph.entering, graph.rowFrom, &budget)) {
      if (auto x = motionOfGroup(spec, *down, -1.0)) return x;
    }
    if (budget < 0) break;
  }
  return std::nullopt;
}

// A flow certifying that the objective stays below kMotion, checked by the dual bound.
bool graphCertifiesNoMotion(const DifferenceGraph& graph, const LinearProgramSpec& spec) {
  const int nodes = graph.ground + 1;
  std::vector<double> y(spec.rowCount(), 0.0);
  // Inside each component: supplies (c_j > 0) to its root, demands (c_j < 0) from it.
  std::vector<double> supply(nodes, 0.0), demand(nodes, 0.0);
  for (int j = 0; j < graph.ground; ++j) {
    supply[j] = std::max(0.0, spec.objective[j]);
    demand[j] = std::max(0.0, -spec.objective[j]);
  }
  routeAlongTree(graph.towardRoot, graph.rowTo, &supply, &y);
  routeAlongTree(graph.fromRoot, graph.rowFrom, &demand, &y);
  // What each root (other than the ground) has left: to or from the ground.
  std::vector<double> up(nodes, 0.0), down(nodes, 0.0);
  for (int node = 0; node < graph.ground; ++node) {
    const double net = supply[node] - demand[node];
    if (net > 0) up[node] = net;
    if (net < 0) down[node] = -net;
  }
  routeAlongTree(graph.towardGround, graph.rowTo, &up, &y);
  routeAlongTree(graph.fromGround, graph.rowFrom, &down, &y);
  for (int node = 0; node < graph.ground; ++node) {
    if (up[node] != 0.0 || down[node] != 0.0) return false;  // no path to or from the ground
  }
  return dualBound(spec, y, 1.0) < kMotion;
}

}  // namespace desia::inequality

// --- A certificate from cones ------------------------------------------------------------------

namespace desia::inequality {
namespace {

using Row3 = std::array<double, 3>;

double dot3(const Row3& a, const Row3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Row3 cross3(const Row3& a, const Row3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length3(const Row3& a) { return std::sqrt(dot3(a, a)); }

// Beyond this many distinct row directions GLPK decides (the search below tries every triple).
constexpr size_t kMaxConeDirections = 32;
using tolerance::kConeSingular;

// The rows as dense 3-vectors, one per distinct direction (the first row of each), in row order.
struct ConeRows {
  std::vector<Row3> vectors;
  std::vector<int> rows;
};

std::optional<ConeRows> distinctDirections(const LinearProgramSpec& spec) {
  std::vector<Row3> dense(spec.rowCount(), Row3{0, 0, 0});
  for (size_t k = 0; k < spec.entryValue.size(); ++k) dense[spec.entryRow[k]][spec.entryColumn[k]] += spec.entryValue[k];
  ConeRows cone;
  std::vector<Row3> units;
  for (int r = 0; r < spec.rowCount(); ++r) {
    const double length = length3(dense[r]);
    if (length == 0.0) continue;
    const Row3 unit{dense[r][0] / length, dense[r][1] / length, dense[r][2] / length};
    bool seen = false;
    for (const Row3& other : units) {
      seen = seen || (std::abs(unit[0] - other[0]) < kConeSingular && std::abs(unit[1] - other[1]) < kConeSingular &&
                      std::abs(unit[2] - other[2]) < kConeSingular);
    }
    if (seen) continue;
    if (units.size() == kMaxConeDirections) return std::nullopt;
    units.push_back(unit);
    cone.vectors.push_back(dense[r]);
    cone.rows.push_back(r);
  }
  return cone;
}

// Multipliers of one, two or three of the directions that combine them into the target, all >= 0.
struct ConeCombination {
  std::array<int, 3> members{-1, -1, -1};  // indices into ConeRows, -1 unused
  std::array<double, 3> weights{0, 0, 0};
};

bool nonNegative(double weight, double scale) { return weight >= -kConeSingular * scale; }

std::optional<ConeCombination> single(const ConeRows& cone, const Row3& target, int i) {
  const Row3& a = cone.vectors[i];
  const double along = dot3(a, target);
  if (along <= 0 || length3(cross3(a, target)) > kConeSingular * length3(a) * length3(target)) return std::nullopt;
  ConeCombination combination;
  combination.members[0] = i;
  combination.weights[0] = along / dot3(a, a);
  return combination;
}

// target = y_i a_i + y_j a_j, solved in the plane of a_i and a_j (target must lie in it).
std::optional<ConeCombination> pair(const ConeRows& cone, const Row3& target, int i, int j) {
  const Row3& a = cone.vectors[i];
  const Row3& b = cone.vectors[j];
  const Row3 normal = cross3(a, b);
  const double normalSquared = dot3(normal, normal);
  const double scale = length3(a) * length3(b);
  if (std::sqrt(normalSquared) <= kConeSingular * scale) return std::nullopt;
  if (std::abs(dot3(target, normal)) > kConeSingular * length3(target) * std::sqrt(normalSquared)) return std::nullopt;
  const double yi = dot3(cross3(target, b), normal) / normalSquared;
  const double yj = dot3(cross3(a, target), normal) / normalSquared;
  if (!nonNegative(yi, 1.0) || !nonNegative(yj, 1.0)) return std::nullopt;
  ConeCombination combination;
  combination.members = {i, j, -1};
  combination.weights = {std::max(0.0, yi), std::max(0.0, yj), 0.0};
  return combination;
}

// target = y_i a_i + y_j a_j + y_k a_k by Cramer's rule.
std::optional<ConeCombination> triple(const ConeRows& cone, const Row3& target, int i, int j, int k) {
  const Row3& a = cone.vectors[i];
  const Row3& b = cone.vectors[j];
  const Row3& c = cone.vectors[k];
  const Row3 bc = cross3(b, c);
  const double determinant = dot3(a, bc);
  if (std::abs(determinant) <= kConeSingular * length3(a) * length3(b) * length3(c)) return std::nullopt;
  const double yi = dot3(target, bc) / determinant;
  const double yj = dot3(target, cross3(c, a)) / determinant;
  const double yk = dot3(target, cross3(a, b)) / determinant;
  if (!nonNegative(yi, 1.0) || !nonNegative(yj, 1.0) || !nonNegative(yk, 1.0)) return std::nullopt;
  ConeCombination combination;
  combination.members = {i, j, k};
  combination.weights = {std::max(0.0, yi), std::max(0.0, yj), std::max(0.0, yk)};
  return combination;
}

// The combination as row duals of the whole program, when they certify no motion.
std::optional<std::vector<double>> certifiedDuals(const LinearProgramSpec& spec, const ConeRows& cone,
                                                  const std::optional<ConeCombination>& combination) {
  if (!combination) return std::nullopt;
  std::vector<double> y(spec.rowCount(), 0.0);
  for (int m = 0; m < 3; ++m) {
    if (combination->members[m] >= 0) y[cone.rows[combination->members[m]]] = combination->weights[m];
  }
  if (!certifiesNoMotion(spec, y)) return std::nullopt;
  return y;
}

}  // namespace

std::optional<std::vector<double>> coneNoMotionDuals(const LinearProgramSpec& spec) {
  if (spec.columnCount() == 0 || spec.columnCount() > 3) return std::nullopt;
  const std::optional<ConeRows> cone = distinctDirections(spec);
  if (!cone) return std::nullopt;
  Row3 target{0, 0, 0};  // -c
  for (int j = 0; j < spec.columnCount(); ++j) target[j] = -spec.objective[j];
  if (length3(target) == 0.0) {
    std::vector<double> zero(spec.rowCount(), 0.0);
    if (certifiesNoMotion(spec, zero)) return zero;
    return std::nullopt;
  }
  const int n = static_cast<int>(cone->vectors.size());
  for (int i = 0; i < n; ++i) {
    if (auto y = certifiedDuals(spec, *cone, single(*cone, target, i))) return y;
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (auto y = certifiedDuals(spec, *cone, pair(*cone, target, i, j))) return y;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        if (auto y = certifiedDuals(spec, *cone, triple(*cone, target, i, j, k))) return y;
      }
    }
  }
  return std::nullopt;
}

}  // namespace desia::inequality
