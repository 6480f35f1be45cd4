// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/plate/plate_format.h"

#include <cmath>
#include <set>

#include "analysis/vec3.h"
#include "desia/design_io.h"
#include "desia/error.h"
#include "io/design_json.h"

namespace desia {
namespace {

using nlohmann::json;

constexpr size_t kMaxPlates = 10000;
constexpr size_t kMaxLoopVertices = 100000;

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& what) {
  throwBadInput(source, path + ": " + what);
}

Vec3 pointAt(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_array() || value.size() != 3) fail(source, path, "expected [x, y, z], found " + value.dump().substr(0, 60));
  Vec3 p{};
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number()) fail(source, path, "expected three numbers, found " + value.dump().substr(0, 60));
    p[k] = value[k].get<double>();
    if (!std::isfinite(p[k]) || std::abs(p[k]) > 1e9) fail(source, path, "coordinate " + value[k].dump() + " is not a finite number of millimetres up to 1e9");
  }
  return p;
}

Loop loopAt(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_array()) fail(source, path, "expected a list of [x, y, z] vertices");
  if (value.size() > kMaxLoopVertices) throw Error(ErrorCode::TooLarge, source + ": " + path + ": more than " + std::to_string(kMaxLoopVertices) + " vertices");
  Loop loop;
  for (size_t i = 0; i < value.size(); ++i) loop.push_back(pointAt(value[i], source, path + "[" + std::to_string(i) + "]"));
  if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();  // a closing repeat
  if (loop.size() < 3) fail(source, path, "a face needs at least 3 vertices, found " + std::to_string(loop.size()));
  return loop;
}

// The right-hand unit normal of a loop, or zero for a degenerate one.
Vec3 rightHandNormal(const Loop& loop) { return normalized(loopNormal(loop)); }

Plate plateAt(const json& entry, const std::string& source, const std::string& path);

// A plate's attached solids (milled joint pieces): each { faces: [first, second], holes? }, a
// prism read as a plate is (without id or name).
std::vector<Plate> attachedAt(const json& list, const std::string& source, const std::string& path) {
  if (!list.is_array()) fail(source, path, "expected a list of solids, each { \"faces\": [firstFace, secondFace] }");
  std::vector<Plate> solids;
  for (size_t k = 0; k < list.size(); ++k) {
    const std::string where = path + "[" + std::to_string(k) + "]";
    const json& entry = list[k];
    if (!entry.is_object() || !entry.contains("faces") || entry.contains("attached") || entry.contains("id")) {
      fail(source, where, "expected { \"faces\": [firstFace, secondFace], \"holes\": [...] }");
    }
    json solid = entry;
    solid["id"] = 1;
    solids.push_back(plateAt(solid, source, where));
    solids.back().id = 0;
  }
  return solids;
}

// CAD tools write a vertex twice in a row (the same coordinates: a zero-length edge) where an
// outline bends by nothing: such a vertex, repeated on both faces, is read once (the faces still
// match vertex for vertex). Repeated on one face only, the faces would no longer correspond:
// refused. Only exact repeats: vertices merely close together are the geometry as drawn.
void dropRepeatedVertices(Loop& first, Loop& second, const std::string& source, const std::string& path) {
  const auto same = [](const Vec3& a, const Vec3& b) { return a == b; };
  for (size_t k = first.size(); k-- > 0 && first.size() > 1;) {
    const size_t previous = (k + first.size() - 1) % first.size();
    const bool repeatedFirst = same(first[k], first[previous]), repeatedSecond = same(second[k], second[previous]);
    if (repeatedFirst && repeatedSecond) {
      first.erase(first.begin() + static_cast<std::ptrdiff_t>(k));
      second.erase(second.begin() + static_cast<std::ptrdiff_t>(k));
    } else if (repeatedFirst || repeatedSecond) {
      fail(source, path, "vertex " + std::to_string(k + 1) + " repeats vertex " + std::to_string(previous + 1) +
                             " on the " + (repeatedFirst ? "first" : "second") +
                             " face only: the faces must list corresponding vertices");
    }
  }
}

Plate plateAt(const json& entry, const std::string& source, const std::string& path) {
  if (!entry.is_object()) fail(source, path, "expected an object with 'id' and 'outline' and 'thickness', or 'id' and 'faces'");
  Plate plate;
  const auto id = entry.find("id");
  if (id == entry.end() || !id->is_number_integer() || id->get<int64_t>() < 1 || id->get<int64_t>() > (1 << 30)) {
    fail(source, path + ".id", "expected an integer from 1 to " + std::to_string(1 << 30));
  }
  plate.id = static_cast<int>(id->get<int64_t>());
  if (entry.contains("name")) {
    if (!entry["name"].is_string()) fail(source, path + ".name", "expected a string");
    plate.name = entry["name"].get<std::string>();
  }
  const std::string who = path + " (plate " + std::to_string(plate.id) + ")";
  if (entry.contains("faces")) {
    const json& faces = entry["faces"];
    if (!faces.is_array() || faces.size() != 2) fail(source, who + ".faces", "expected [firstFace, secondFace]");
    plate.bottom.push_back(loopAt(faces[0], source, who + ".faces[0]"));
    plate.top.push_back(loopAt(faces[1], source, who + ".faces[1]"));
    if (plate.bottom[0].size() != plate.top[0].size()) {
      fail(source, who + ".faces", "the faces do not match: " + std::to_string(plate.bottom[0].size()) + " and " +
                                     std::to_string(plate.top[0].size()) + " vertices (a plate's faces list corresponding vertices in the same order)");
    }
    dropRepeatedVertices(plate.bottom[0], plate.top[0], source, who + ".faces");
    if (entry.contains("outline") || entry.contains("thickness")) fail(source, who, "give either 'faces' or 'outline' and 'thickness', not both");
    if (entry.contains("holes")) {
      const json& holes = entry["holes"];
      if (!holes.is_array()) fail(source, who + ".holes", "expected a list of [firstFaceLoop, secondFaceLoop] pairs");
      for (size_t h = 0; h < holes.size(); ++h) {
        const std::string where = who + ".holes[" + std::to_string(h) + "]";
        if (!holes[h].is_array() || holes[h].size() != 2) fail(source, where, "expected [firstFaceLoop, secondFaceLoop]");
        plate.bottom.push_back(loopAt(holes[h][0], source, where + "[0]"));
        plate.top.push_back(loopAt(holes[h][1], source, where + "[1]"));
        if (plate.bottom.back().size() == plate.top.back().size()) {
          dropRepeatedVertices(plate.bottom.back(), plate.top.back(), source, where);
        }
      }
    }
    if (entry.contains("attached")) plate.attached = attachedAt(entry["attached"], source, who + ".attached");
    return plate;
  }
  if (!entry.contains("outline")) fail(source, who, "missing 'outline' (or 'faces')");
  if (entry.contains("attached")) fail(source, who + ".attached", "attached solids go with the 'faces' form");
  plate.bottom.push_back(loopAt(entry["outline"], source, who + ".outline"));
  const auto thickness = entry.find("thickness");
  if (thickness == entry.end() || !thickness->is_number()) fail(source, who + ".thickness", "expected a number of millimetres");
  const double t = thickness->get<double>();
  if (!(t > 0) || !std::isfinite(t)) fail(source, who + ".thickness", "must be positive, found " + thickness->dump());
  if (entry.contains("holes")) {
    const json& holes = entry["holes"];
    if (!holes.is_array()) fail(source, who + ".holes", "expected a list of loops");
    for (size_t h = 0; h < holes.size(); ++h) plate.bottom.push_back(loopAt(holes[h], source, who + ".holes[" + std::to_string(h) + "]"));
  }
  const Vec3 n = rightHandNormal(plate.bottom[0]);
  if (norm(n) == 0) fail(source, who + ".outline", "has no area");
  for (const Loop& loop : plate.bottom) {
    Loop top;
    for (const Vec3& p : loop) {
      top.push_back({p[0] + t * n[0], p[1] + t * n[1], p[2] + t * n[2]});
      // The second face is written out as given coordinates (documents always take the faces form),
      // so it must obey the coordinate limit too, or a written document would not read back.
      for (const double c : top.back()) {
        if (!(std::abs(c) <= 1e9)) {
          fail(source, who + ".thickness", "puts the second face beyond 1e9 millimetres, found " + thickness->dump());
        }
      }
    }
    plate.top.push_back(top);
  }
  return plate;
}

}  // namespace

std::vector<Plate> parsePlates(const json& plates, const std::string& source) {
  if (!plates.is_array()) throwBadInput(source, "plates: expected an array of plates");
  if (plates.empty()) throwBadInput(source, "plates: the design has no plates");
  if (plates.size() > kMaxPlates) throw Error(ErrorCode::TooLarge, source + ": plates: more than " + std::to_string(kMaxPlates) + " plates");
  std::vector<Plate> result;
  std::set<int> ids;
  for (size_t i = 0; i < plates.size(); ++i) {
    const std::string path = "plates[" + std::to_string(i) + "]";
    Plate plate = plateAt(plates[i], source, path);
    if (!ids.insert(plate.id).second) fail(source, path + ".id", "duplicate plate id " + std::to_string(plate.id));
    result.push_back(std::move(plate));
  }
  return result;
}

json platesToJson(const std::vector<Plate>& plates) {
  auto loopJson = [](const Loop& loop) {
    json points = json::array();
    for (const Vec3& p : loop) points.push_back({p[0], p[1], p[2]});
    return points;
  };
  json list = json::array();
  for (const Plate& plate : plates) {
    json entry = {{"id", plate.id}};
    if (!plate.name.empty()) entry["name"] = plate.name;
    entry["faces"] = {loopJson(plate.bottom[0]), loopJson(plate.top[0])};
    if (plate.bottom.size() > 1) {
      json holes = json::array();
      for (size_t l = 1; l < plate.bottom.size(); ++l) holes.push_back({loopJson(plate.bottom[l]), loopJson(plate.top[l])});
      entry["holes"] = holes;
    }
    if (!plate.attached.empty()) {
      json solids = platesToJson(plate.attached);
      for (json& solid : solids) solid.erase("id");
      entry["attached"] = solids;
    }
    list.push_back(entry);
  }
  return list;
}

std::string plateDesignToJson(const AssemblyDocument& input, const PlateDesignResult& result, int indent) {
  const std::vector<Plate>& plates = input.plates;
  std::vector<int> newId(plates.size(), 0);
  for (size_t k = 0; k < result.order.size(); ++k) newId[result.order[k]] = static_cast<int>(k) + 1;
  json root;
  root["format"] = "desia-assembly";
  root["version"] = 1;
  root["kind"] = "plate";
  root["name"] = (input.name.empty() ? std::string("plate structure") : input.name) + " - joint plan";
  if (input.plateOptions.contactTolerance != PlateOptions{}.contactTolerance) {
    root["contactTolerance"] = input.plateOptions.contactTolerance;  // the tolerance it was verified with
  }
  const bool cut = result.realization != JointRealization::Planned;  // cut or milled: the jointed plates
  json parts = json::array(), platesJson = json::array();
  std::vector<Plate> ordered, fabrication;
  for (int index : result.order) {
    Plate plate = cut ? result.jointedPlates[index] : plates[index];
    if (cut) {
      fabrication.push_back(result.fabricationPlates[index]);
      fabrication.back().id = newId[index];
    }
    plate.id = newId[index];
    ordered.push_back(plate);
    json part = {{"id", plate.id}, {"inputId", plates[index].id}};
    if (!plate.name.empty()) part["name"] = plate.name;
    parts.push_back(part);
  }
  platesJson = platesToJson(ordered);
  for (size_t k = 0; k < ordered.size(); ++k) platesJson[k]["inputId"] = parts[k]["inputId"];
  root["parts"] = parts;
  json contacts = json::array();
  for (const Contact& c : result.jointAssembly.contacts) {
    contacts.push_back({{"a", c.a + 1}, {"b", c.b + 1}, {"normal", vectorJson(c.normal)}, {"area", c.area}});
  }
  root["contacts"] = contacts;
  json joints = json::array();
  for (const PlateJoint& joint : result.joints) {
    joints.push_back({{"mover", newId[joint.mover]}, {"other", newId[joint.other]}, {"type", jointTypeName(joint.type)},
                      {"direction", vectorJson(joint.direction)}});
  }
  root["joints"] = joints;
  json removal = json::array();
  for (size_t k = 0; k < result.order.size(); ++k) {
    json step = {{"part", static_cast<int>(k) + 1}};
    step["direction"] = k < result.directions.size() ? vectorJson(result.directions[k]) : json(nullptr);
    removal.push_back(step);
  }
  root["removal"] = removal;
  root["plates"] = platesJson;
  // "cut" / "milled": the plates carry their tenons and mortises (milled: dovetail solids in
  // `attached`) and the contacts are theirs; "planned": the
  // paper's graph design alone, the plates as given and the contacts those of the joint model.
  root["jointGeometry"] = jointRealizationName(result.realization);
  if (cut && result.clearance > 0) {
    // With the clearance cut into the mortises: what the exports make. `plates` is what was verified.
    root["clearance"] = result.clearance;
    root["fabricationPlates"] = platesToJson(fabrication);
  }
  return root.dump(indent);
}

}  // namespace desia
