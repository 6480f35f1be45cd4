// Inequality-based interlocking test (paper Section 3.2, Eq. 2), solved with GLPK.
//
// Two departures from the paper's recipe make the test exact for any contact normals:
// - Eq. 2 only finds motions that separate some contact; motions that slide along every contact
//   (all t_ij = 0 but v != 0: a part in a slot, free along the slot) need a second look, here two
//   LPs maximizing a generic linear functional of the velocities.
// - Round 2 fixes only a reference part, not the key: fixing both freezes any motion that
//   separates a group holding the reference from a group holding the key and other parts, and
//   such an assembly would pass. The key may move; a motion counts when another part moves.
//
// And one makes its verdicts trustworthy on computed normals (issue 14). Normals computed in
// floating point (a rotation, a cross product) carry 1e-16 errors, and an exact answer on such
// data can differ from the answer the geometry means: three normals of a planar design turned by
// a rotation no longer lie exactly in one plane, so the motion normal to that plane disappears.
// The question every program answers is therefore posed with a tolerance, the same kind of
// tolerance the blocking graphs use (a contact blocks d when d·n exceeds a tolerance):
//
//     is there a motion v, |v_j| <= 1, that penetrates no contact by more than kPenetration
//     ((v_b - v_a)·n >= -kPenetration) and makes the program's objective reach kMotion?
//
// GLPK's floating-point simplex proposes an answer and the answer is accepted only with a
// certificate checked here against every contact: a motion is checked directly, "no motion" by
// weak duality (any y >= 0 bounds the objective over all such motions by Σ|c + Aᵀy| + kPenetration
// Σy). When neither certificate holds (GLPK failed, hit its limits, or was imprecise), the same
// question is decided by GLPK's exact rational simplex on the relaxed rows. The three routes
// answer one well-defined question, so the verdict does not depend on which one decided.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

#include "analysis/linear_program.h"
#include "analysis/part_motion.h"
#include "analysis/vec3.h"
#include "desia/directed_graph.h"
#include "desia/error.h"
#include "desia/interlocking.h"
#include "desia/tolerances.h"

namespace desia {
namespace {

// How far a motion of unit speed may push into a contact and still count as sliding along it, and
// the objective a motion must reach (velocities are bounded by 1): desia/tolerances.h.
using tolerance::kMotion;
using tolerance::kPenetration;

// Contacts that involve at least one free part; with both sides fixed a contact says nothing.
std::vector<int> relevantContacts(const Assembly& assembly, const std::vector<bool>& isFree) {
  std::vector<int> relevant;
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    const Contact& contact = assembly.contacts[c];
    if (isFree[contact.a] || isFree[contact.b]) relevant.push_back(c);
  }
  return relevant;
}

// Column of each free part's x velocity (y and z follow), or -1 for a fixed part.
std::vector<int> velocityColumns(const std::vector<bool>& isFree, int* columnCount) {
  std::vector<int> column(isFree.size(), -1);
  int next = 0;
  for (size_t i = 0; i < isFree.size(); ++i) {
    if (isFree[i]) {
      column[i] = next;
      next += 3;
    }
  }
  *columnCount = next;
  return column;
}

// What one linear program looks for: a motion of the free parts (fixed parts have v = 0) in which
// some watched part moves. Watched parts are free; a free part that is not watched (the key in
// round 2) may move along to make room but does not count as a motion by itself.
struct MotionQuery {
  std::vector<bool> isFree;
  std::vector<bool> isWatched;
  bool exactOnly = false;  // skip the floating-point simplex (tests: the routes must agree)
  bool graphCertificates = true;  // let graph algorithms propose answers first (see below)
  // The contacts that touch a free part, in index order, when the caller knows them (round 1:
  // one part's own contacts, instead of a scan of every contact per part).
  const std::vector<int>* contacts = nullptr;
};

enum class Objective {
  SeparatingContacts,  // Eq. 2's question: can a contact between watched or fixed parts separate?
  GenericFunctional,   // max Σ c_i·v_i over watched parts, for a fixed generic c (see below)
};

// Deterministic "generic" weights in ±[0.5, 1.5]: a non-zero cone of motions projected on the
// watched velocities is orthogonal to such a vector only with probability zero, so max c·v > 0
// or max -c·v > 0 exactly when a watched part can move, sliding motions included (where every
// t_c of Eq. 2 stays 0). A small linear congruential sequence keeps native and WebAssembly equal.
std::vector<double> genericWeights(int count) {
  std::vector<double> weights(count);
  uint64_t state = 0x9E3779B97F4A7C15ull;
  for (double& w : weights) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const double unit = static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
    w = ((state >> 7) & 1 ? 1.0 : -1.0) * (0.5 + unit);
  }
  return weights;
}

bool involvesUnwatchedFreePart(const Contact& contact, const MotionQuery& query) {
  auto unwatchedFree = [&](int part) { return query.isFree[part] && !query.isWatched[part]; };
  return unwatchedFree(contact.a) || unwatchedFree(contact.b);
}

// One motion program: a row s_c = (v_b - v_a)·n_c >= 0 per contact that touches a free part,
// velocities bounded to [-1, 1] (scaling keeps a motion a motion).
//
// Eq. 2 maximizes Σ t_c with t_c <= s_c and 0 <= t_c <= 1; its optimum is positive exactly when
// some s_c can be positive. Maximizing Σ s_c over the same constraints answers the same question
// without the t columns (3N instead of 3N + C variables), and GLPK gets there in far fewer
// pivots: on a 1500-part cube that falls apart, 16 s for Eq. 2 as written.
struct MotionProgram {
  LinearProgramSpec spec;           // rows and columns; the objective is set per question
  std::vector<int> velocityColumn;  // per part, -1 when fixed
  std::vector<double> separation;   // Eq. 2's objective: Σ s_c over contacts between watched or fixed parts
  std::vector<double> functional;   // the generic weights on the watched velocities (0 elsewhere)
};

// The rows are the same for every question asked of one query, so they are built once.
MotionProgram buildMotionProgram(const Assembly& assembly, const MotionQuery& query) {
  MotionProgram program;
  int velocityCount = 0;
  program.velocityColumn = velocityColumns(query.isFree, &velocityCount);
  program.separation.assign(velocityCount, 0.0);
  program.functional.assign(velocityCount, 0.0);
  const std::vector<double> weights = genericWeights(velocityCount);
  for (int part = 0; part < assembly.partCount(); ++part) {
    if (!query.isWatched[part]) continue;
    for (int k = 0; k < 3; ++k) {
      const int column = program.velocityColumn[part] + k;
      program.functional[column] = weights[column];
    }
  }
  LinearProgramSpec& spec = program.spec;
  for (int c : query.contacts ? *query.contacts : relevantContacts(assembly, query.isFree)) {
    const Contact& contact = assembly.contacts[c];
    const int row = spec.rowCount();
    spec.rowLower.push_back(0.0);
    const bool separationCounts = !involvesUnwatchedFreePart(contact, query);
    for (const auto& [part, sign] : {std::pair<int, double>{contact.b, 1.0}, std::pair<int, double>{contact.a, -1.0}}) {
      if (program.velocityColumn[part] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        const int column = program.velocityColumn[part] + k;
        spec.addEntry(row, column, sign * contact.normal[k]);
        if (separationCounts) program.separation[column] += sign * contact.normal[k];
      }
    }
  }
  for (int j = 0; j < velocityCount; ++j) spec.addColumn(-1.0, 1.0, 0.0);
  return program;
}

void setObjective(MotionProgram* program, Objective objective, double functionalSign) {
  std::vector<double>& cost = program->spec.objective;
  for (size_t j = 0; j < cost.size(); ++j) {
    cost[j] = objective == Objective::SeparatingContacts ? program->separation[j] : functionalSign * program->functional[j];
  }
}

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

bool certifiesNoMotion(const LinearProgramSpec& spec, const std::vector<double>& rowDuals) {
  return std::min(dualBound(spec, rowDuals, -1.0), dualBound(spec, rowDuals, 1.0)) < kMotion;
}

MotionSearch motionFrom(const Assembly& assembly, const MotionProgram& program, const std::vector<double>& x) {
  MotionSearch search;
  search.movable = true;
  search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  for (int i = 0; i < assembly.partCount(); ++i) {
    if (program.velocityColumn[i] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const double v = x[program.velocityColumn[i] + k];
      search.velocities[i][k] = std::abs(v) < tolerance::kVelocityNoise ? 0.0 : v;
    }
  }
  return search;
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

// Decides one motion program (see the file comment): graph certificates when the rows allow them,
// then GLPK's dual simplex, then its primal simplex, each accepted only with a checked
// certificate, then the exact rational simplex.
MotionSearch decideMotionProgram(const Assembly& assembly, const MotionQuery& query, MotionProgram program,
                                 const DifferenceGraph* graph = nullptr) {
  const MotionSearch none;  // no velocities: findFreeMotion fills in the zeros
  if (program.spec.columnCount() == 0) return none;
  if (graph && !query.exactOnly) {
    MotionSearch decided;
    if (auto x = graphMotion(*graph, program.spec)) {
      decided = motionFrom(assembly, program, *x);
    } else if (!graphCertifiesNoMotion(*graph, program.spec)) {
      graph = nullptr;  // neither certificate: GLPK decides
    }
    if (graph) {
      decided.decidedByGraphs = true;
      return decided;
    }
  }
  std::string failures;
  for (SimplexMethod method : {SimplexMethod::Dual, SimplexMethod::Primal}) {
    if (query.exactOnly) break;
    LinearProgramSolution solution = solveLinearProgram(program.spec, method);
    if (!solution.optimal) {
      failures += (failures.empty() ? "" : "; ") + solution.failure;
      continue;
    }
    if (certifiesMotion(program.spec, &solution.columnValues)) return motionFrom(assembly, program, solution.columnValues);
    if (certifiesNoMotion(program.spec, solution.rowDuals)) return none;
  }
  for (double& lower : program.spec.rowLower) lower = -kPenetration;
  LinearProgramSolution exact = solveLinearProgram(program.spec, SimplexMethod::ExactRational);
  if (!exact.optimal) {
    throw Error(ErrorCode::TooLarge,
                "the inequality test could not decide a linear program of " + std::to_string(program.spec.rowCount()) +
                    " contacts and " + std::to_string(program.spec.columnCount()) + " velocities within its limits (" +
                    failures + "; exact simplex: " + exact.failure + "); use --method dbg");
  }
  if (exact.objectiveValue < kMotion) return none;
  return motionFrom(assembly, program, exact.columnValues);
}

// Is there a motion in which a watched part moves? Eq. 2's question first (its solution separates contacts,
// the clearest witness), then the generic functional in both signs for sliding motions.
MotionSearch findWatchedMotion(const Assembly& assembly, const MotionQuery& query) {
  MotionProgram program = buildMotionProgram(assembly, query);
  std::optional<DifferenceGraph> graph;
  if (query.graphCertificates && !query.exactOnly) graph = differenceGraph(program.spec);
  const DifferenceGraph* graphOrNull = graph ? &*graph : nullptr;
  setObjective(&program, Objective::SeparatingContacts, 1.0);
  MotionSearch search = decideMotionProgram(assembly, query, program, graphOrNull);
  bool byGraphs = search.decidedByGraphs;
  for (double sign : {1.0, -1.0}) {
    if (search.movable) break;
    setObjective(&program, Objective::GenericFunctional, sign);
    search = decideMotionProgram(assembly, query, program, graphOrNull);
    byGraphs = byGraphs && search.decidedByGraphs;
  }
  search.decidedByGraphs = byGraphs;
  return search;
}

// The parts that really take part in a motion: speeds within three orders of magnitude of the
// fastest (the tolerated penetration lets the others creep by kPenetration).
std::vector<int> movingParts(const MotionSearch& search) {
  double fastest = 0;
  for (const Vec3& v : search.velocities) fastest = std::max(fastest, norm(v));
  std::vector<int> parts;
  for (int i = 0; i < static_cast<int>(search.velocities.size()); ++i) {
    if (norm(search.velocities[i]) > tolerance::kMovingSpeedFraction * fastest) parts.push_back(i);
  }
  return parts;
}

Witness witnessFromMotion(const MotionSearch& search) {
  Witness witness;
  witness.parts = movingParts(search);
  bool common = !witness.parts.empty();
  Vec3 first = witness.parts.empty() ? Vec3{0, 0, 0} : normalized(search.velocities[witness.parts[0]]);
  for (int part : witness.parts) {
    Vec3 v = normalized(search.velocities[part]);
    witness.velocities.push_back(v);
    if (norm({v[0] - first[0], v[1] - first[1], v[2] - first[2]}) > tolerance::kSameVelocityDirection) common = false;
  }
  if (common) witness.direction = directionLabel(first);
  return witness;
}

std::string describeMotion(const Assembly& assembly, const Witness& witness) {
  std::ostringstream out;
  out << "part" << (witness.parts.size() > 1 ? "s " : " ");
  for (size_t i = 0; i < witness.parts.size(); ++i) out << (i ? ", " : "") << assembly.parts[witness.parts[i]].id;
  if (!witness.direction.empty()) {
    out << " can move along " << witness.direction;
  } else {
    out << " can move at once in different directions";
  }
  return out.str();
}

// Base directions (both signs) along which the part alone is free.
std::vector<Vec3> freeDirectionsOfPart(const Assembly& assembly, const std::vector<BaseDirection>& directions, int part) {
  std::vector<int> touching;
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    if (assembly.contacts[c].a == part || assembly.contacts[c].b == part) touching.push_back(c);
  }
  std::vector<Vec3> free;
  for (const BaseDirection& base : directions) {
    for (const Vec3& d : {base.vector, negated(base.vector)}) {
      bool blocked = false;
      for (int c : touching) {
        const Contact& contact = assembly.contacts[c];
        const double along = dot(d, contact.normal);
        if ((contact.a == part && along > tolerance::kDirection) ||
            (contact.b == part && along < -tolerance::kDirection)) {
          blocked = true;
          break;
        }
      }
      if (!blocked) free.push_back(d);
    }
  }
  return free;
}

InterlockingResult testWithCleanNormals(const Assembly& assembly, const std::vector<BaseDirection>& directions,
                                        const InequalityOptions& options) {
  const int n = assembly.partCount();
  InterlockingResult result;
  if (n < 3) {
    result.reason = "an interlocking assembly needs at least three parts; this one has " + std::to_string(n);
    return result;
  }
  // Round 1: which parts can move alone? The verdict names at most the first two.
  const PartsMovableAlone alone = findPartsMovableAlone(assembly, options, 2);
  const std::vector<int>& movableAlone = alone.parts;
  const std::vector<MotionSearch>& motions = alone.motions;
  if (movableAlone.size() > 1) {
    result.hasWitness = true;
    result.witness = witnessFromMotion(motions[1]);
    result.reason = "more than one part can move alone (parts " + std::to_string(assembly.parts[movableAlone[0]].id) +
                    " and " + std::to_string(assembly.parts[movableAlone[1]].id) + "): " +
                    describeMotion(assembly, result.witness);
    return result;
  }
  // Round 2: fix a reference part other than the key; the key may move, but no other part may.
  const int key = movableAlone.empty() ? -1 : movableAlone[0];
  const int reference = key == 0 ? 1 : 0;
  MotionQuery query{std::vector<bool>(n, true), std::vector<bool>(n, true), options.exactOnly,
                    options.graphCertificates};
  query.isFree[reference] = query.isWatched[reference] = false;
  if (key >= 0) query.isWatched[key] = false;
  const MotionSearch search = findWatchedMotion(assembly, query);
  if (search.movable) {
    result.hasWitness = true;
    result.witness = witnessFromMotion(search);
    result.reason = (key >= 0 ? "besides the key, " : "") + describeMotion(assembly, result.witness);
    return result;
  }
  if (key < 0) return deadlockedResult("the linear program admits no motion: no part or part group can move");
  std::vector<Vec3> keyDirections = freeDirectionsOfPart(assembly, directions, key);
  if (keyDirections.empty()) keyDirections.push_back(normalized(motions[0].velocities[key]));
  return interlockingResult(assembly, key, std::move(keyDirections));
}

}  // namespace

MotionSearch findFreeMotion(const Assembly& assembly, const std::vector<bool>& isFree, const InequalityOptions& options) {
  MotionSearch search = findWatchedMotion(assembly, {isFree, isFree, options.exactOnly, options.graphCertificates});
  if (search.velocities.empty()) search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  return search;
}

MotionSearch findMotionOfWatchedParts(const Assembly& assembly, const std::vector<bool>& isFree,
                                      const std::vector<bool>& isWatched, const InequalityOptions& options) {
  MotionSearch search = findWatchedMotion(assembly, {isFree, isWatched, options.exactOnly, options.graphCertificates});
  if (search.velocities.empty()) search.velocities.assign(assembly.partCount(), Vec3{0, 0, 0});
  return search;
}

PartsMovableAlone findPartsMovableAlone(const Assembly& assembly, const InequalityOptions& options, int enough) {
  const int n = assembly.partCount();
  std::vector<std::vector<int>> contactsOf(n);
  for (int c = 0; c < static_cast<int>(assembly.contacts.size()); ++c) {
    const Contact& contact = assembly.contacts[c];
    contactsOf[contact.a].push_back(c);
    if (contact.b != contact.a) contactsOf[contact.b].push_back(c);
  }
  PartsMovableAlone alone;
  MotionQuery query{std::vector<bool>(n, false), std::vector<bool>(n, false), options.exactOnly,
                    options.graphCertificates};
  for (int i = 0; i < n && static_cast<int>(alone.parts.size()) < enough; ++i) {
    query.isFree[i] = query.isWatched[i] = true;
    query.contacts = &contactsOf[i];
    MotionSearch search = findWatchedMotion(assembly, query);
    query.isFree[i] = query.isWatched[i] = false;
    if (search.movable) {
      alone.parts.push_back(i);
      alone.motions.push_back(std::move(search));
    }
  }
  return alone;
}

InterlockingResult testInterlockingByInequalities(const Assembly& assembly, const std::vector<BaseDirection>& directions,
                                                  const InequalityOptions& options) {
  if (hasCleanNormals(assembly)) return testWithCleanNormals(assembly, directions, options);
  return testWithCleanNormals(withCleanedNormals(assembly), directions, options);
}

InterlockingResult testInterlockingByInequalities(const Assembly& assembly) {
  if (hasCleanNormals(assembly)) return testWithCleanNormals(assembly, computeBaseDirections(assembly), {});
  const Assembly clean = withCleanedNormals(assembly);
  return testWithCleanNormals(clean, computeBaseDirections(clean), {});
}

}  // namespace desia
