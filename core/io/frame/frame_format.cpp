// SPDX-License-Identifier: GPL-3.0-or-later
// Frame files: JSON (kind "frame"), OBJ lines and faces, FrameInterlock's .fpuz; the result
// document of a frame design.
#include "desia/formats.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include "desia/error.h"
#include "io/frame/frame_json.h"
#include "io/json_input.h"
#include "io/text_lines.h"

namespace desia {
namespace {

using nlohmann::json;

constexpr int kFormatVersion = 1;
constexpr double kMaxCoordinate = 1e9;

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& what) {
  throwBadInput(source, (path.empty() ? std::string() : path + ": ") + what);
}

bool endsWithIgnoringCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) != suffix[i]) return false;
  }
  return true;
}

Vec3 pointAt(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_array() || value.size() != 3)
    fail(source, path, "expected [x, y, z], found " + value.dump().substr(0, 60));
  Vec3 p{};
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number()) fail(source, path, "expected three numbers, found " + value.dump().substr(0, 60));
    p[k] = value[k].get<double>();
    if (!std::isfinite(p[k]) || std::abs(p[k]) > kMaxCoordinate)
      fail(source, path, "coordinate " + value[k].dump() + " is not a finite number up to 1e9");
  }
  return p;
}

int idAt(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_number_integer() || value.get<int64_t>() < 1 || value.get<int64_t>() > (1 << 30)) {
    fail(source, path,
         "expected an integer id from 1 to " + std::to_string(1 << 30) + ", found " + value.dump().substr(0, 40));
  }
  return static_cast<int>(value.get<int64_t>());
}

double sizeAt(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_number() || !(value.get<double>() > 0) || !std::isfinite(value.get<double>()) ||
      value.get<double>() > kMaxCoordinate) {
    fail(source, path, "expected a positive number, found " + value.dump().substr(0, 40));
  }
  return value.get<double>();
}

int directionFromLabel(const std::string& label) {
  for (int face = 0; face < 6; ++face) {
    if (label == cubeFaceName(face)) return face;
  }
  return -1;
}

std::string directionName(const Vec3& d) {
  for (int face = 0; face < 6; ++face) {
    if (cubeFaceNormal(face) == d) return cubeFaceName(face);
  }
  return "?";
}

// Parts in removal order = beams by increasing id.
std::vector<int> beamsById(const Frame& frame) {
  std::vector<int> order(frame.beams.size());
  for (size_t b = 0; b < order.size(); ++b) order[b] = static_cast<int>(b);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return frame.beams[a].id < frame.beams[b].id; });
  return order;
}

// The frame sections of a JSON object (the document's root or its `frame` object).
FrameDocument frameFromJsonObject(const json& root, const std::string& source, double jointSize) {
  const json& object =
      root.contains("frame") && root["frame"].is_object() && root["frame"].contains("beams") ? root["frame"] : root;
  const std::string prefix = &object == &root ? "" : "frame.";
  FrameDocument document;
  Frame frame;
  const auto joints = object.find("joints");
  if (joints == object.end() || !joints->is_array())
    fail(source, prefix + "joints", "expected a list of joints ([x, y, z] or {id, position})");
  if (joints->size() > static_cast<size_t>(kMaxFrameJoints))
    throw Error(ErrorCode::TooLarge, source + ": more than " + std::to_string(kMaxFrameJoints) + " joints");
  std::map<int, int> jointIndex;
  for (size_t j = 0; j < joints->size(); ++j) {
    const std::string path = prefix + "joints[" + std::to_string(j) + "]";
    const json& entry = (*joints)[j];
    FrameJoint joint;
    if (entry.is_object()) {
      joint.id = entry.contains("id") ? idAt(entry["id"], source, path + ".id") : static_cast<int>(j + 1);
      if (!entry.contains("position")) fail(source, path, "missing field 'position'");
      joint.position = pointAt(entry["position"], source, path + ".position");
    } else {
      joint.id = static_cast<int>(j + 1);
      joint.position = pointAt(entry, source, path);
    }
    if (!jointIndex.insert({joint.id, static_cast<int>(j)}).second)
      fail(source, path, "duplicate joint id " + std::to_string(joint.id));
    frame.joints.push_back(joint);
  }
  const auto beams = object.find("beams");
  if (beams == object.end() || !beams->is_array())
    fail(source, prefix + "beams", "expected a list of beams ([a, b] or {id, joints, path})");
  if (beams->size() > static_cast<size_t>(kMaxFrameBeams))
    throw Error(ErrorCode::TooLarge, source + ": more than " + std::to_string(kMaxFrameBeams) + " beams");
  std::set<int> beamIds;
  for (size_t b = 0; b < beams->size(); ++b) {
    const std::string path = prefix + "beams[" + std::to_string(b) + "]";
    const json& entry = (*beams)[b];
    FrameBeam beam;
    beam.id = static_cast<int>(b + 1);
    const json* ends = &entry;
    if (entry.is_object()) {
      if (entry.contains("id")) beam.id = idAt(entry["id"], source, path + ".id");
      if (!entry.contains("joints")) fail(source, path, "missing field 'joints' (the ids of its two joints)");
      ends = &entry["joints"];
      if (entry.contains("path")) {
        const json& points = entry["path"];
        if (!points.is_array()) fail(source, path + ".path", "expected a list of [x, y, z] points");
        if (points.size() > static_cast<size_t>(kMaxBeamPathPoints))
          throw Error(ErrorCode::TooLarge, source + ": " + path + ".path: too many points");
        for (size_t k = 0; k < points.size(); ++k)
          beam.path.push_back(pointAt(points[k], source, path + ".path[" + std::to_string(k) + "]"));
      }
    }
    if (!ends->is_array() || ends->size() != 2) fail(source, path, "expected the ids of two joints [a, b]");
    for (int end = 0; end < 2; ++end) {
      const int id =
          idAt((*ends)[end], source, path + (ends == &entry ? "" : ".joints") + "[" + std::to_string(end) + "]");
      const auto it = jointIndex.find(id);
      if (it == jointIndex.end()) fail(source, path, "joint " + std::to_string(id) + " is not in 'joints'");
      beam.joints[end] = it->second;
    }
    beam.inputId =
        entry.is_object() && entry.contains("inputId") ? idAt(entry["inputId"], source, path + ".inputId") : beam.id;
    // A path may repeat its joints' positions at its ends.
    if (!beam.path.empty() && beam.path.front() == frame.joints[beam.joints[0]].position)
      beam.path.erase(beam.path.begin());
    if (!beam.path.empty() && beam.path.back() == frame.joints[beam.joints[1]].position) beam.path.pop_back();
    if (!beamIds.insert(beam.id).second) fail(source, path, "duplicate beam id " + std::to_string(beam.id));
    frame.beams.push_back(beam);
  }
  if (object.contains("jointSize")) frame.jointSize = sizeAt(object["jointSize"], source, prefix + "jointSize");
  if (object.contains("beamSection")) frame.beamSection = sizeAt(object["beamSection"], source, prefix + "beamSection");
  if (jointSize > 0) frame.jointSize = jointSize;
  if (root.contains("name") && root["name"].is_string()) document.name = root["name"].get<std::string>();
  document.layout = layoutFrame(std::move(frame), source);
  const Frame& f = document.layout.frame;
  // A design result: the joint voxels (part ids) and the removal plan.
  if (object.contains("jointVoxels")) {
    const json& voxels = object["jointVoxels"];
    if (!voxels.is_array() || voxels.size() != f.joints.size()) {
      fail(source, prefix + "jointVoxels",
           "expected one list of 27 beam ids per joint (" + std::to_string(f.joints.size()) + " joints)");
    }
    std::map<int, int> beamIndex;
    for (size_t b = 0; b < f.beams.size(); ++b) beamIndex[f.beams[b].id] = static_cast<int>(b);
    for (size_t j = 0; j < voxels.size(); ++j) {
      const std::string path = prefix + "jointVoxels[" + std::to_string(j) + "]";
      if (!voxels[j].is_array() || voxels[j].size() != kJointVoxelCount)
        fail(source, path, "expected 27 beam ids (x fastest, then y, then z)");
      JointLabels labels{};
      for (int v = 0; v < kJointVoxelCount; ++v) {
        const int id = idAt(voxels[j][v], source, path + "[" + std::to_string(v) + "]");
        const auto it = beamIndex.find(id);
        if (it == beamIndex.end())
          fail(source, path + "[" + std::to_string(v) + "]", "beam " + std::to_string(id) + " is not in 'beams'");
        labels[v] = it->second;
      }
      document.labels.push_back(labels);
    }
    validateJointLabels(document.layout, document.labels, source);
  }
  document.order = beamsById(f);
  if (object.contains("removal")) {
    const json& removal = object["removal"];
    if (!removal.is_array() || removal.size() + 1 != f.beams.size()) {
      fail(source, prefix + "removal",
           "expected a direction for every beam but the last (" + std::to_string(f.beams.size() - 1) + " entries)");
    }
    for (size_t k = 0; k < removal.size(); ++k) {
      const std::string path = prefix + "removal[" + std::to_string(k) + "]";
      const json& entry = removal[k];
      if (!entry.is_object() || !entry.contains("part") || !entry.contains("direction"))
        fail(source, path, "expected {part, direction}");
      const int part = idAt(entry["part"], source, path + ".part");
      if (part != f.beams[document.order[k]].id) {
        fail(source, path + ".part",
             "beams leave in id order: expected " + std::to_string(f.beams[document.order[k]].id) + ", found " +
                 std::to_string(part));
      }
      const int face = entry["direction"].is_string() ? directionFromLabel(entry["direction"].get<std::string>()) : -1;
      if (face < 0)
        fail(source, path + ".direction",
             "expected an axis direction such as \"+y\", found " + entry["direction"].dump().substr(0, 40));
      document.directions.push_back(cubeFaceNormal(face));
    }
  }
  return document;
}

// Wavefront OBJ: `v` vertices are joints; every `l` polyline segment and every `f` face edge is a
// beam (an edge shared by faces, or given twice, is one beam).
FrameDocument frameFromObj(const std::string& text, const std::string& source, double jointSize) {
  Frame frame;
  std::vector<std::pair<int, int>> edges;
  std::set<std::pair<int, int>> seen;
  TextLineReader reader(text, source);
  TextLine line;
  auto vertexIndex = [&](const Token& token, int lineNumber) {
    const std::string digits = token.text.substr(0, token.text.find('/'));
    char* end = nullptr;
    const long value = std::strtol(digits.c_str(), &end, 10);
    const long count = static_cast<long>(frame.joints.size());
    if (digits.empty() || *end != '\0' || value == 0 || value > count || value < -count) {
      throwBadInput(
          location(source, lineNumber, token.column),
          "vertex reference '" + token.text + "' is not a vertex defined above (" + std::to_string(count) + " so far)");
    }
    return static_cast<int>(value > 0 ? value - 1 : count + value);
  };
  auto addEdge = [&](int a, int b) {
    if (a == b) return;
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    if (seen.insert(key).second) edges.push_back({a, b});
  };
  while (reader.next(line)) {
    if (line.tokens.empty()) continue;
    const std::string& record = line.tokens[0].text;
    if (record == "v") {
      if (line.tokens.size() < 4) throwBadInput(location(source, line.number), "vertex needs 'v x y z'");
      FrameJoint joint;
      joint.id = static_cast<int>(frame.joints.size() + 1);
      for (int k = 0; k < 3; ++k) {
        char* end = nullptr;
        joint.position[k] = std::strtod(line.tokens[1 + k].text.c_str(), &end);
        if (*end != '\0' || !std::isfinite(joint.position[k]) || std::abs(joint.position[k]) > kMaxCoordinate) {
          throwBadInput(location(source, line.number, line.tokens[1 + k].column),
                        "vertex coordinate '" + line.tokens[1 + k].text + "' is not a finite number up to 1e9");
        }
      }
      if (frame.joints.size() >= static_cast<size_t>(kMaxFrameJoints))
        throw Error(ErrorCode::TooLarge, source + ": more than " + std::to_string(kMaxFrameJoints) + " joints");
      frame.joints.push_back(joint);
    } else if (record == "l" || record == "f") {
      std::vector<int> vertices;
      for (size_t t = 1; t < line.tokens.size(); ++t) vertices.push_back(vertexIndex(line.tokens[t], line.number));
      if (vertices.size() < 2)
        throwBadInput(location(source, line.number), "'" + record + "' needs at least two vertices");
      for (size_t k = 0; k + 1 < vertices.size(); ++k) addEdge(vertices[k], vertices[k + 1]);
      if (record == "f" && vertices.size() > 2) addEdge(vertices.back(), vertices.front());
      if (edges.size() > static_cast<size_t>(kMaxFrameBeams))
        throw Error(ErrorCode::TooLarge, source + ": more than " + std::to_string(kMaxFrameBeams) + " beams");
    }
  }
  for (size_t b = 0; b < edges.size(); ++b) {
    FrameBeam beam;
    beam.id = beam.inputId = static_cast<int>(b + 1);
    beam.joints = {edges[b].first, edges[b].second};
    frame.beams.push_back(beam);
  }
  if (jointSize > 0) frame.jointSize = jointSize;
  FrameDocument document;
  document.layout = layoutFrame(std::move(frame), source);
  document.order = beamsById(document.layout.frame);
  return document;
}

// FrameInterlock's .fpuz (original-code-notes.md section C): "V voxelSize", V joint lines, "P",
// P lines "f0 f1" (f = 6 * joint + face), "J N", J lines of N^3 voxel values (x fastest; value =
// beam index + 1, P + 1 = not assigned, 0 = empty).
FrameDocument frameFromFpuz(const std::string& text, const std::string& source, double jointSize) {
  TextLineReader reader(text, source);
  TextLine line;
  std::vector<Token> tokens;
  std::vector<int> lineOf;
  while (reader.next(line)) {
    for (const Token& token : line.tokens) {
      tokens.push_back(token);
      lineOf.push_back(line.number);
    }
    if (tokens.size() > 50'000'000) throw Error(ErrorCode::TooLarge, source + ": the file is too large");
  }
  size_t at = 0;
  auto where = [&](size_t k) { return k < lineOf.size() ? lineOf[k] : reader.lastLineWithData(); };
  auto nextToken = [&](const std::string& what) -> const Token& {
    if (at >= tokens.size()) throwBadInput(location(source, reader.lastLineWithData()), "the file ends before " + what);
    return tokens[at++];
  };
  auto integer = [&](const std::string& what, int64_t lo, int64_t hi) {
    const Token& token = nextToken(what);
    return parseIntegerToken(token, source, where(at - 1), what, lo, hi);
  };
  auto real = [&](const std::string& what) {
    const Token& token = nextToken(what);
    char* end = nullptr;
    const double value = std::strtod(token.text.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value) || std::abs(value) > kMaxCoordinate) {
      throwBadInput(location(source, where(at - 1), token.column),
                    what + " '" + token.text + "' is not a finite number up to 1e9");
    }
    return value;
  };
  Frame frame;
  const int64_t jointCount = integer("the joint count", 1, kMaxFrameJoints);
  const double voxelSize = real("the voxel size");
  if (!(voxelSize > 0)) throwBadInput(location(source, where(at - 1)), "the voxel size must be positive");
  for (int64_t j = 0; j < jointCount; ++j) {
    FrameJoint joint;
    joint.id = static_cast<int>(j + 1);
    for (int k = 0; k < 3; ++k) joint.position[k] = real("a joint coordinate");
    frame.joints.push_back(joint);
  }
  const int64_t beamCount = integer("the beam count", 1, kMaxFrameBeams);
  std::vector<std::array<int, 2>> faces;
  for (int64_t b = 0; b < beamCount; ++b) {
    FrameBeam beam;
    beam.id = beam.inputId = static_cast<int>(b + 1);
    std::array<int, 2> face{};
    for (int end = 0; end < 2; ++end) {
      const int64_t value = integer("a beam end (6 * joint + face)", 0, 6 * jointCount - 1);
      beam.joints[end] = static_cast<int>(value / 6);
      face[end] = static_cast<int>(value % 6);
    }
    faces.push_back(face);
    frame.beams.push_back(beam);
  }
  integer("the joint count of the voxel section", jointCount, jointCount);
  const int64_t side = integer("the voxels per cube side", kJointVoxelsPerSide, kJointVoxelsPerSide);
  frame.jointSize = jointSize > 0 ? jointSize : voxelSize * static_cast<double>(side);
  std::vector<JointLabels> labels(jointCount);
  bool assigned = true;
  for (int64_t j = 0; j < jointCount; ++j) {
    for (int v = 0; v < kJointVoxelCount; ++v) {
      const int64_t value = integer("a voxel value", 0, beamCount + 1);
      if (value == 0)
        throwBadInput(location(source, where(at - 1)),
                      "joint " + std::to_string(j + 1) +
                          " has an empty voxel (0); every voxel of a joint cube belongs to a beam here");
      if (value == beamCount + 1) assigned = false;
      labels[j][v] = static_cast<int>(value - 1);
    }
  }
  if (at != tokens.size())
    throwBadInput(location(source, where(at), tokens[at].column), "unexpected data after the last joint");
  FrameDocument document;
  document.layout = layoutFrame(std::move(frame), source);
  const Frame& f = document.layout.frame;
  for (size_t b = 0; b < f.beams.size(); ++b) {
    for (int end = 0; end < 2; ++end) {
      if (document.layout.endFace[b][end] != faces[b][end]) {
        throwBadInput(source, "beam " + std::to_string(b + 1) + ": the file has it enter the " +
                                  cubeFaceName(faces[b][end]) + " face of joint " +
                                  std::to_string(f.beams[b].joints[end] + 1) +
                                  ", but its direction there is closest to the " +
                                  cubeFaceName(document.layout.endFace[b][end]) + " face");
      }
    }
  }
  document.order = beamsById(f);
  if (assigned) {
    validateJointLabels(document.layout, labels, source);
    document.labels = std::move(labels);
  }
  return document;
}

}  // namespace

json frameSectionsJson(const FrameDocument& document) {
  const Frame& frame = document.layout.frame;
  json root = json::object();
  root["jointSize"] = frame.jointSize;
  root["beamSection"] = frame.beamSection;
  json joints = json::array();
  for (const FrameJoint& joint : frame.joints) joints.push_back({{"id", joint.id}, {"position", joint.position}});
  root["joints"] = joints;
  json beams = json::array();
  for (const FrameBeam& beam : frame.beams) {
    json entry = {{"id", beam.id}, {"joints", {frame.joints[beam.joints[0]].id, frame.joints[beam.joints[1]].id}}};
    if (beam.inputId != beam.id) entry["inputId"] = beam.inputId;
    if (!beam.path.empty()) entry["path"] = beam.path;
    beams.push_back(entry);
  }
  root["beams"] = beams;
  if (!document.labels.empty()) {
    json voxels = json::array();
    for (const JointLabels& labels : document.labels) {
      json ids = json::array();
      for (int label : labels) ids.push_back(frame.beams[label].id);
      voxels.push_back(ids);
    }
    root["jointVoxels"] = voxels;
  }
  if (!document.directions.empty()) {
    json removal = json::array();
    for (size_t k = 0; k < document.directions.size(); ++k) {
      removal.push_back(
          {{"part", frame.beams[document.order[k]].id}, {"direction", directionName(document.directions[k])}});
    }
    root["removal"] = removal;
  }
  return root;
}



FrameDocument parseFrameText(const std::string& text, const std::string& source, double jointSize) {
  if (endsWithIgnoringCase(source, ".obj")) return frameFromObj(text, source, jointSize);
  if (isFpuzSource(source)) return frameFromFpuz(text, source, jointSize);
  const json root = parseJsonText(text, source);
  if (!root.is_object()) fail(source, "", "the JSON document must be an object");
  if (!root.contains("kind") || root["kind"] != "frame")
    fail(source, "kind", "expected \"frame\" for a frame structure");
  return frameFromJsonObject(root, source, jointSize);
}

std::string frameDocumentToJson(const FrameDocument& document, int indent) {
  json root;
  root["format"] = "desia-assembly";
  root["version"] = kFormatVersion;
  root["kind"] = "frame";
  if (!document.name.empty()) root["name"] = document.name;
  if (!document.labels.empty()) {
    json parts = json::array();
    for (int beam : document.order) parts.push_back({{"id", document.layout.frame.beams[beam].id}});
    root["parts"] = parts;
  }
  const json sections = frameSectionsJson(document);  // must outlive the loop
  for (const auto& [key, value] : sections.items()) root[key] = value;
  return root.dump(indent);
}

std::string frameResultToJson(const FrameLayout& layout, const FrameDesignResult& result, const std::string& name,
                              int indent) {
  if (result.status != DesignStatus::Success)
    throwBadInput("", "only a successful frame design has a result document");
  // Beams renumbered in removal order: part 1 is the key.
  Frame frame = layout.frame;
  frame.beams.clear();
  std::vector<int> newIndex(layout.frame.beams.size(), -1);
  for (size_t k = 0; k < result.order.size(); ++k) {
    FrameBeam beam = layout.frame.beams[result.order[k]];
    beam.inputId = beam.inputId ? beam.inputId : beam.id;
    beam.id = static_cast<int>(k + 1);
    newIndex[result.order[k]] = static_cast<int>(k);
    frame.beams.push_back(beam);
  }
  FrameDocument document;
  document.name = name;
  document.layout = layoutFrame(frame, "result");
  for (const JointLabels& labels : result.labels) {
    JointLabels renamed{};
    for (int v = 0; v < kJointVoxelCount; ++v) renamed[v] = newIndex[labels[v]];
    document.labels.push_back(renamed);
  }
  for (size_t k = 0; k < result.order.size(); ++k) document.order.push_back(static_cast<int>(k));
  document.directions = result.directions;
  return frameDocumentToJson(document, indent);
}

AssemblyDocument assemblyDocumentFromFrame(const FrameDocument& frameDocument) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Frame;
  document.name = frameDocument.name;
  const Frame& frame = frameDocument.layout.frame;
  if (!frameDocument.labels.empty()) {
    document.assembly = frameAssembly(frameDocument.layout, frameDocument.labels, frameDocument.order);
  } else {
    for (int beam : frameDocument.order) document.assembly.parts.push_back({frame.beams[beam].id, ""});
  }
  document.frame = frameDocument;
  document.contactsFromGeometry = true;
  // The beams whose removal splits the parts-graph (beams sharing a joint), as part indices: the
  // check report names them before any design, as it does a plate structure's (the designer
  // refuses such a frame: FrameDesigner::refusal).
  std::vector<int> partOf(frame.beams.size(), -1);
  for (size_t k = 0; k < frameDocument.order.size(); ++k) partOf[frameDocument.order[k]] = static_cast<int>(k);
  for (int beam : frameCutBeams(frameDocument.layout)) document.plateCutPoints.push_back(partOf[beam]);
  std::sort(document.plateCutPoints.begin(), document.plateCutPoints.end());
  return document;
}

FrameDocument frameFromAssemblyDocument(const AssemblyDocument& document, const std::string& source) {
  if (document.kind != AssemblyKind::Frame) {
    throwBadInput(
        source, std::string("expected a frame structure, this is a ") + assemblyKindName(document.kind) + " document");
  }
  if (!document.frame) throwBadInput(source, "this frame document has contacts but no beams");
  FrameDocument frame = *document.frame;
  frame.name = document.name;
  return frame;
}

AssemblyDocument frameAssemblyDocumentFromJson(const json& root, const std::string& source, const std::string& name) {
  FrameDocument frame = frameFromJsonObject(root, source, 0);
  frame.name = name;
  return assemblyDocumentFromFrame(frame);
}

AssemblyDocument frameAssemblyDocumentFromFpuz(const std::string& text, const std::string& source) {
  return assemblyDocumentFromFrame(frameFromFpuz(text, source, 0));
}

std::string formatFpuz(const FrameDocument& document) {
  const FrameLayout& layout = document.layout;
  const Frame& frame = layout.frame;
  std::vector<int> partOf(frame.beams.size());
  for (size_t k = 0; k < document.order.size(); ++k) partOf[document.order[k]] = static_cast<int>(k);
  auto number = [](double value) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", value + 0.0);
    return std::string(buffer);
  };
  std::string out = std::to_string(frame.joints.size()) + " " + number(layout.voxelSize) + "\n";
  for (const FrameJoint& joint : frame.joints)
    out += number(joint.position[0]) + " " + number(joint.position[1]) + " " + number(joint.position[2]) + "\n";
  out += std::to_string(frame.beams.size()) + "\n";
  for (int beam : document.order) {
    out += std::to_string(6 * frame.beams[beam].joints[0] + layout.endFace[beam][0]) + " " +
           std::to_string(6 * frame.beams[beam].joints[1] + layout.endFace[beam][1]) + "\n";
  }
  out += std::to_string(frame.joints.size()) + " " + std::to_string(kJointVoxelsPerSide) + "\n";
  // Without designed joints: every voxel unassigned (P + 1) but the face voxels the beams enter.
  const int unassigned = static_cast<int>(frame.beams.size()) + 1;
  for (size_t j = 0; j < frame.joints.size(); ++j) {
    std::array<int, kJointVoxelCount> values;
    values.fill(unassigned);
    for (int face = 0; face < 6; ++face) {
      if (layout.faceBeam[j][face] >= 0) values[faceCentreVoxel(face)] = partOf[layout.faceBeam[j][face]] + 1;
    }
    if (!document.labels.empty()) {
      for (int v = 0; v < kJointVoxelCount; ++v) values[v] = partOf[document.labels[j][v]] + 1;
    }
    for (int value : values) out += std::to_string(value) + " ";
    out += "\n";
  }
  return out;
}

}  // namespace desia
