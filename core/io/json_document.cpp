// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON assembly document (docs/json-schema.md).
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <nlohmann/json.hpp>
#include <set>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "io/design_json.h"
#include "io/frame/frame_json.h"  // isFpuzSource, defined here: it picks the reader
#include "io/json_input.h"
#include "io/kind_entries.h"

namespace desia {
namespace {

using nlohmann::json;

constexpr int kFormatVersion = 1;
constexpr size_t kMaxParts = 100000;
constexpr size_t kMaxContacts = 2000000;

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& what) {
  throwBadInput(source, (path.empty() ? std::string() : path + ": ") + what);
}

const json& require(const json& object, const char* key, const std::string& source, const std::string& path) {
  auto it = object.find(key);
  if (it == object.end()) fail(source, path, std::string("missing field '") + key + "'");
  return *it;
}

int64_t integerField(const json& value, const std::string& source, const std::string& path, int64_t lo, int64_t hi) {
  if (!value.is_number_integer()) fail(source, path, "expected an integer, found " + value.dump());
  const int64_t v = value.get<int64_t>();
  if (v < lo || v > hi) fail(source, path, std::to_string(v) + " is out of range (" + std::to_string(lo) + " to " + std::to_string(hi) + ")");
  return v;
}

AssemblyKind parseKind(const json& root, const std::string& source) {
  const json& kind = require(root, "kind", source, "");
  const std::string name = kind.is_string() ? kind.get<std::string>() : "";
  if (name == "voxel") return AssemblyKind::Voxel;
  if (name == "plate") return AssemblyKind::Plate;
  if (name == "frame") return AssemblyKind::Frame;
  if (name == "contacts") return AssemblyKind::Contacts;
  fail(source, "kind", "expected \"voxel\", \"plate\", \"frame\" or \"contacts\", found " + kind.dump());
}

VoxelGrid parseVoxelSection(const json& root, const std::string& source) {
  const json& voxel = require(root, "voxel", source, "");
  if (!voxel.is_object()) fail(source, "voxel", "expected an object");
  const json& size = require(voxel, "size", source, "voxel");
  if (!size.is_array() || size.size() != 3) fail(source, "voxel.size", "expected [nx, ny, nz]");
  int64_t n[3];
  for (int k = 0; k < 3; ++k) n[k] = integerField(size[k], source, "voxel.size[" + std::to_string(k) + "]", 1, VoxelLimits::kMaxSide);
  if (n[0] * n[1] * n[2] > VoxelLimits::kMaxVoxels) {
    throw Error(ErrorCode::TooLarge, source + ": voxel.size: grid has more than " + std::to_string(VoxelLimits::kMaxVoxels) + " voxels");
  }
  VoxelGrid grid(static_cast<int>(n[0]), static_cast<int>(n[1]), static_cast<int>(n[2]));
  const json& labels = require(voxel, "labels", source, "voxel");
  if (!labels.is_array()) fail(source, "voxel.labels", "expected an array of integers");
  if (static_cast<int64_t>(labels.size()) != grid.voxelCount()) {
    fail(source, "voxel.labels", "has " + std::to_string(labels.size()) + " values, but size " + std::to_string(n[0]) + " x " +
                                     std::to_string(n[1]) + " x " + std::to_string(n[2]) + " needs " + std::to_string(grid.voxelCount()));
  }
  for (int64_t i = 0; i < grid.voxelCount(); ++i) {
    grid.setLabelAt(i, static_cast<int>(integerField(labels[i], source, "voxel.labels[" + std::to_string(i) + "]", 0, grid.voxelCount())));
  }
  validateVoxelParts(grid, source);
  return grid;
}

std::vector<Part> parseParts(const json& root, const std::string& source) {
  const json& parts = require(root, "parts", source, "");
  if (!parts.is_array()) fail(source, "parts", "expected an array");
  if (parts.size() > kMaxParts) throw Error(ErrorCode::TooLarge, source + ": parts: more than " + std::to_string(kMaxParts) + " parts");
  std::vector<Part> result;
  std::set<int> seen;
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string path = "parts[" + std::to_string(i) + "]";
    if (!parts[i].is_object()) fail(source, path, "expected an object with an 'id'");
    Part part;
    part.id = static_cast<int>(integerField(require(parts[i], "id", source, path), source, path + ".id", 1, 1 << 30));
    if (!seen.insert(part.id).second) fail(source, path + ".id", "duplicate part id " + std::to_string(part.id));
    if (parts[i].contains("name")) {
      if (!parts[i]["name"].is_string()) fail(source, path + ".name", "expected a string");
      part.name = parts[i]["name"].get<std::string>();
    }
    result.push_back(part);
  }
  if (result.empty()) fail(source, "parts", "the assembly is empty: no parts");
  return result;
}

// Contacts are the bulk of a plan's JSON (45,005 for a table of 4,002 plates), and a JSON object
// per contact (a map of its four keys) took four times its text's size. Each well-formed contact is
// packed as it is parsed into a binary value, which no JSON text can give, and parseContacts reads
// it with the same checks as the object; anything else stays an object, for the checks to name.
constexpr std::uint8_t kPackedContact = 0x43;
constexpr int64_t kLargestPartId = 1 << 30;

struct ContactFields {
  int64_t a = 0, b = 0;
  Vec3 normal{};
  std::optional<double> area;
};

std::vector<std::uint8_t> packedContact(const ContactFields& fields) {
  const double hasArea = fields.area ? 1 : 0, area = fields.area.value_or(0);
  std::vector<std::uint8_t> bytes(sizeof(int64_t) * 2 + sizeof(double) * 5);
  std::uint8_t* at = bytes.data();
  for (const int64_t id : {fields.a, fields.b}) std::memcpy(at, &id, sizeof id), at += sizeof id;
  for (const double value : {fields.normal[0], fields.normal[1], fields.normal[2], hasArea, area})
    std::memcpy(at, &value, sizeof value), at += sizeof value;
  return bytes;
}

ContactFields unpackedContact(const json::binary_t& bytes) {
  ContactFields fields;
  const std::uint8_t* at = bytes.data();
  for (int64_t* id : {&fields.a, &fields.b}) std::memcpy(id, at, sizeof *id), at += sizeof *id;
  double values[5];
  std::memcpy(values, at, sizeof values);
  fields.normal = {values[0], values[1], values[2]};
  if (values[3] != 0) fields.area = values[4];
  return fields;
}

// The contact's fields when it has exactly the form parseContacts accepts (ids in range, a normal
// of three numbers, a number for its area, no other key); none otherwise.
std::optional<ContactFields> wellFormedContact(const json& entry) {
  if (!entry.is_object() || !entry.contains("a") || !entry.contains("b") || !entry.contains("normal")) return std::nullopt;
  ContactFields fields;
  for (const auto& [key, value] : entry.items()) {
    if (key == "a" || key == "b") {
      if (!value.is_number_integer()) return std::nullopt;
      const bool inRange = value.is_number_unsigned()
                               ? value.get<uint64_t>() >= 1 && value.get<uint64_t>() <= static_cast<uint64_t>(kLargestPartId)
                               : value.get<int64_t>() >= 1 && value.get<int64_t>() <= kLargestPartId;
      if (!inRange) return std::nullopt;
      (key == "a" ? fields.a : fields.b) = value.get<int64_t>();
    } else if (key == "normal") {
      if (!value.is_array() || value.size() != 3) return std::nullopt;
      for (int k = 0; k < 3; ++k) {
        if (!value[k].is_number()) return std::nullopt;
        fields.normal[k] = value[k].get<double>();
      }
    } else if (key == "area") {
      if (!value.is_number()) return std::nullopt;
      fields.area = value.get<double>();
    } else {
      return std::nullopt;
    }
  }
  return fields;
}

// A document's JSON, with the root's contacts packed as they are parsed (only documents that have
// contacts are parsed with a callback: it is called for every value, a voxel grid's millions too).
json parseDocumentJson(const std::string& text, const std::string& source) {
  if (text.find("\"contacts\"") == std::string::npos) return parseJsonText(text, source);
  std::string rootKey;
  return parseJsonText(text, source, [&rootKey](int depth, json::parse_event_t event, json& parsed) {
    if (depth == 1 && event == json::parse_event_t::key) rootKey = parsed.get<std::string>();
    if (depth == 2 && event == json::parse_event_t::object_end && rootKey == "contacts") {
      if (const std::optional<ContactFields> fields = wellFormedContact(parsed))
        parsed = json::binary(packedContact(*fields), kPackedContact);
    }
    return true;
  });
}

bool isPackedContact(const json& entry) {
  return entry.is_binary() && entry.get_binary().has_subtype() && entry.get_binary().subtype() == kPackedContact;
}

// Each contact checked in one order, packed or not (a packed contact passed the checks of form).
std::vector<Contact> parseContacts(const json& root, const Assembly& assembly, const std::string& source) {
  const json& contacts = require(root, "contacts", source, "");
  if (!contacts.is_array()) fail(source, "contacts", "expected an array");
  if (contacts.size() > kMaxContacts) throw Error(ErrorCode::TooLarge, source + ": contacts: more than " + std::to_string(kMaxContacts) + " contacts");
  std::vector<Contact> result;
  for (size_t i = 0; i < contacts.size(); ++i) {
    const std::string path = "contacts[" + std::to_string(i) + "]";
    const json& entry = contacts[i];
    const bool packed = isPackedContact(entry);
    const ContactFields given = packed ? unpackedContact(entry.get_binary()) : ContactFields{};
    if (!packed && !entry.is_object()) fail(source, path, "expected an object {a, b, normal}");
    Contact contact;
    for (const char* side : {"a", "b"}) {
      const int64_t id = packed ? (side[0] == 'a' ? given.a : given.b)
                                : integerField(require(entry, side, source, path), source, path + "." + side, 1, kLargestPartId);
      const int index = assembly.indexOfId(static_cast<int>(id));
      if (index < 0) fail(source, path + "." + side, "part " + std::to_string(id) + " is not in 'parts'");
      (side[0] == 'a' ? contact.a : contact.b) = index;
    }
    if (contact.a == contact.b) fail(source, path, "a part cannot touch itself (a = b = " + std::to_string(assembly.parts[contact.a].id) + ")");
    Vec3 raw = given.normal;
    if (!packed) {
      const json& normal = require(entry, "normal", source, path);
      if (!normal.is_array() || normal.size() != 3) fail(source, path + ".normal", "expected [nx, ny, nz]");
      for (int k = 0; k < 3; ++k) {
        if (!normal[k].is_number()) fail(source, path + ".normal", "expected three numbers, found " + normal.dump());
        raw[k] = normal[k].get<double>();
      }
    }
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(raw[k])) fail(source, path + ".normal", "is not finite");
    }
    const std::optional<Vec3> unit = cleanedNormal(raw);
    if (!unit) fail(source, path + ".normal", "is the zero vector");
    contact.normal = *unit;
    const bool hasArea = packed ? given.area.has_value() : entry.contains("area");
    if (hasArea) {
      const bool number = packed || entry["area"].is_number();
      const double area = packed ? *given.area : number ? entry["area"].get<double>() : 0;
      if (!number || !(area > 0)) fail(source, path + ".area", "expected a positive number");
      contact.area = area;
    }
    result.push_back(contact);
  }
  return result;
}

// The ids of `plates` must be exactly the parts' ids: one plate per part, one part per plate.
void requirePlatePerPart(const std::vector<Plate>& plates, const Assembly& assembly, const std::string& source,
                         const std::string& section) {
  std::set<int> plateIds;
  for (const Plate& plate : plates) {
    if (assembly.indexOfId(plate.id) < 0) fail(source, section, "plate " + std::to_string(plate.id) + " is not in 'parts'");
    plateIds.insert(plate.id);
  }
  for (const Part& part : assembly.parts) {
    if (!plateIds.count(part.id)) fail(source, section, "part " + std::to_string(part.id) + " has no plate");
  }
}

Vec3 removalDirection(const json& entry, const std::string& source, const std::string& path) {
  const json& d = require(entry, "direction", source, path);
  if (!d.is_array() || d.size() != 3 || !d[0].is_number() || !d[1].is_number() || !d[2].is_number()) {
    fail(source, path + ".direction", "expected [x, y, z], found " + d.dump().substr(0, 60));
  }
  const Vec3 v{d[0].get<double>(), d[1].get<double>(), d[2].get<double>()};
  const std::optional<Vec3> unit = std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) ? cleanedNormal(v) : std::nullopt;
  if (!unit) fail(source, path + ".direction", "is not a direction: " + d.dump());
  return *unit;
}

// A result's `joints`: [{mover, other, type, direction}], parts by id.
std::vector<PlateResultJoint> parsePlateResultJoints(const json& list, const Assembly& assembly,
                                                     const std::string& source) {
  if (!list.is_array()) fail(source, "joints", "expected a list of {mover, other, type, direction}");
  std::vector<PlateResultJoint> joints;
  for (size_t k = 0; k < list.size(); ++k) {
    const std::string path = "joints[" + std::to_string(k) + "]";
    if (!list[k].is_object()) fail(source, path, "expected {\"mover\": id, \"other\": id, \"type\", \"direction\"}");
    PlateResultJoint joint;
    for (auto [side, id] : {std::pair<const char*, int*>{"mover", &joint.mover}, {"other", &joint.other}}) {
      const std::string where = path + "." + side;
      *id = static_cast<int>(integerField(require(list[k], side, source, path), source, where, 1, 1 << 30));
      if (assembly.indexOfId(*id) < 0) fail(source, where, "part " + std::to_string(*id) + " is not in 'parts'");
    }
    const json& type = require(list[k], "type", source, path);
    if (!type.is_string() || type.get<std::string>().empty()) fail(source, path + ".type", "expected a joint type's name");
    joint.type = type.get<std::string>();
    joint.direction = removalDirection(list[k], source, path);
    joints.push_back(std::move(joint));
  }
  return joints;
}

// A result's plan: `removal` lists every part once, by id, in the order they leave (the key
// first), each with its direction but the last (null: it stays); `jointGeometry` says what the
// plates are. Read by id, whatever the order of `parts` and `plates`.
PlateResultPlan parsePlateResultPlan(const json& root, const Assembly& assembly, const std::string& source) {
  PlateResultPlan plan;
  const json& realization = require(root, "jointGeometry", source, "");
  plan.jointGeometry = realization.is_string() ? realization.get<std::string>() : "";
  if (plan.jointGeometry != "cut" && plan.jointGeometry != "milled" && plan.jointGeometry != "planned") {
    fail(source, "jointGeometry", "expected \"cut\", \"milled\" or \"planned\", found " + realization.dump().substr(0, 60));
  }
  const json& removal = require(root, "removal", source, "");
  if (!removal.is_array() || removal.size() != assembly.parts.size()) {
    fail(source, "removal", "expected one entry per part (" + std::to_string(assembly.parts.size()) + ")");
  }
  std::set<int> seen;
  for (size_t k = 0; k < removal.size(); ++k) {
    const std::string path = "removal[" + std::to_string(k) + "]";
    if (!removal[k].is_object()) fail(source, path, "expected {\"part\": id, \"direction\": [x, y, z] or null}");
    const int id = static_cast<int>(integerField(require(removal[k], "part", source, path), source, path + ".part", 1, 1 << 30));
    if (assembly.indexOfId(id) < 0) fail(source, path + ".part", "part " + std::to_string(id) + " is not in 'parts'");
    if (!seen.insert(id).second) fail(source, path + ".part", "part " + std::to_string(id) + " leaves twice");
    plan.removalOrder.push_back(id);
    const bool last = k + 1 == removal.size();
    if (last) {
      if (!removal[k].contains("direction") || !removal[k]["direction"].is_null()) {
        fail(source, path + ".direction", "the last part stays: expected null");
      }
    } else {
      plan.directions.push_back(removalDirection(removal[k], source, path));
    }
  }
  if (root.contains("joints")) plan.joints = parsePlateResultJoints(root["joints"], assembly, source);
  if (root.contains("clearance")) {
    const json& clearance = root["clearance"];
    if (!clearance.is_number() || !(clearance.get<double>() >= 0 && clearance.get<double>() <= 10)) {
      fail(source, "clearance", "expected a number of millimetres from 0 to 10, found " + clearance.dump().substr(0, 60));
    }
    plan.clearance = clearance.get<double>();
  }
  return plan;
}

// A plan or result: its contacts are given (the joints'); its plates are what is made, one per part.
void readPlatePlan(const json& root, const std::string& source, AssemblyDocument& document) {
  const PlateFrameEntries& plates = plateFrameEntries();
  document.plates = plates.readPlanPlates(root, "plates", source, document.plateOptions);
  requirePlatePerPart(document.plates, document.assembly, source, "plates");
  if (root.contains("removal") || root.contains("jointGeometry")) {
    document.plateResult = parsePlateResultPlan(root, document.assembly, source);
  } else if (root.contains("fabricationPlates") || root.contains("clearance") || root.contains("joints")) {
    fail(source, "removal", "a result with fabricationPlates, clearance or joints needs its plan (removal and jointGeometry)");
  }
  if (root.contains("fabricationPlates")) {
    // The plates with the clearance cut into their mortises: what the cut files make.
    document.fabricationPlates = plates.readPlanPlates(root, "fabricationPlates", source, document.plateOptions);
    requirePlatePerPart(document.fabricationPlates, document.assembly, source, "fabricationPlates");
  }
}

}  // namespace

const char* assemblyKindName(AssemblyKind kind) {
  switch (kind) {
    case AssemblyKind::Voxel: return "voxel";
    case AssemblyKind::Plate: return "plate";
    case AssemblyKind::Frame: return "frame";
    case AssemblyKind::Contacts: return "contacts";
  }
  return "contacts";
}

AssemblyDocument documentFromVoxels(VoxelGrid grid, std::string name) {
  AssemblyDocument document;
  document.kind = AssemblyKind::Voxel;
  document.name = std::move(name);
  document.assembly = assemblyFromVoxels(grid);
  document.voxels = std::move(grid);
  return document;
}

namespace {

AssemblyDocument documentFromJson(json root, const std::string& source) {
  if (!root.is_object()) fail(source, "", "the JSON document must be an object");
  if (root.contains("format") && root["format"] != "desia-assembly") {
    fail(source, "format", "expected \"desia-assembly\", found " + root["format"].dump());
  }
  if (root.contains("version") && root["version"] != kFormatVersion) {
    fail(source, "version", "unsupported version " + root["version"].dump() + " (this build reads version 1)");
  }
  AssemblyDocument document;
  document.kind = parseKind(root, source);
  if (root.contains("name")) {
    if (!root["name"].is_string()) fail(source, "name", "expected a string");
    document.name = root["name"].get<std::string>();
  }
  if (document.kind == AssemblyKind::Voxel) {
    std::string name = document.name;
    document = documentFromVoxels(parseVoxelSection(root, source), name);
    return document;
  }
  if (document.kind == AssemblyKind::Frame && root.contains("beams") && !root.contains("contacts")) {
    // A frame (paper Section 5.3): parts are its beams, contacts come from its joint voxels.
    return plateFrameEntries().frameFromJson(root, source, document.name);
  }
  PlateOptions plateOptions;
  if (document.kind == AssemblyKind::Plate && root.contains("contactTolerance")) {
    const json& tolerance = root["contactTolerance"];
    if (!tolerance.is_number() || !(tolerance.get<double>() > 0) || tolerance.get<double>() > 10) {
      fail(source, "contactTolerance", "expected a positive number of millimetres up to 10, found " + tolerance.dump());
    }
    plateOptions.contactTolerance = tolerance.get<double>();
  }
  if (document.kind == AssemblyKind::Plate && root.contains("plates") && !root.contains("contacts")) {
    // A plate design: parts and contacts come from the geometry (paper Section 5.2).
    document = plateFrameEntries().plateDesignFromJson(root, plateOptions, source, document.name);
  } else {
    document.plateOptions = plateOptions;
    document.assembly.parts = parseParts(root, source);
    document.assembly.contacts = parseContacts(root, document.assembly, source);
    if (document.kind == AssemblyKind::Plate && root.contains("plates")) readPlatePlan(root, source, document);
  }
  return document;
}

// The text's first character that is not white space ('\0' for none).
char firstNonBlank(const std::string& text) {
  const size_t at = text.find_first_not_of(" \n\r\t");
  return at == std::string::npos ? '\0' : text[at];
}

}  // namespace

AssemblyDocument parseJsonDocument(const std::string& text, const std::string& source) {
  return documentFromJson(parseDocumentJson(text, source), source);
}

AssemblyDocument parseAssemblyText(std::string&& text, const std::string& source) {
  const char first = firstNonBlank(text);
  if (isFpuzSource(source) || looksLikePuz(text) || (first != '{' && first != '[')) {
    return parseAssemblyText(static_cast<const std::string&>(text), source);
  }
  // The text is let go once parsed: the parsed JSON and the text at once were the peak.
  json root = parseDocumentJson(text, source);
  std::string().swap(text);
  return documentFromJson(std::move(root), source);
}

AssemblyDocument parseAssemblyText(const std::string& text, const std::string& source) {
  if (isFpuzSource(source)) return plateFrameEntries().frameFromFpuz(text, source);
  if (looksLikePuz(text)) {
    PuzFile file = readPuz(text, source);
    AssemblyDocument document = documentFromVoxels(std::move(file.grid));
    document.voxelSize = file.voxelSize;
    return document;
  }
  for (char c : text) {
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (c == '{' || c == '[') return parseJsonDocument(text, source);
    break;
  }
  if (text.find_first_not_of(" \n\r\t") == std::string::npos) throwBadInput(source, "the input is empty");
  // Neither a digit nor a JSON brace: let the .puz reader name the first bad byte or token.
  return documentFromVoxels(parsePuz(text, source));
}

namespace {

// The sections parsePlateResultPlan reads, as plateDesignToJson writes them.
void writePlateResultPlan(const PlateResultPlan& plan, json& root) {
  json removal = json::array();
  for (size_t k = 0; k < plan.removalOrder.size(); ++k) {
    removal.push_back({{"part", plan.removalOrder[k]},
                       {"direction", k < plan.directions.size() ? vectorJson(plan.directions[k]) : json(nullptr)}});
  }
  root["removal"] = removal;
  root["jointGeometry"] = plan.jointGeometry;
  if (plan.clearance > 0) root["clearance"] = plan.clearance;
  if (!plan.joints.empty()) {
    json joints = json::array();
    for (const PlateResultJoint& joint : plan.joints) {
      joints.push_back({{"mover", joint.mover}, {"other", joint.other}, {"type", joint.type},
                        {"direction", vectorJson(joint.direction)}});
    }
    root["joints"] = joints;
  }
}

}  // namespace

std::string documentToJson(const AssemblyDocument& document, int indent) {
  json root;
  root["format"] = "desia-assembly";
  root["version"] = kFormatVersion;
  root["kind"] = assemblyKindName(document.kind);
  if (!document.name.empty()) root["name"] = document.name;
  json parts = json::array();
  if (document.kind == AssemblyKind::Voxel) {
    const VoxelGrid& grid = document.voxels;
    root["voxel"] = {{"size", {grid.nx(), grid.ny(), grid.nz()}}, {"labels", grid.labels()}};
    const std::vector<int64_t> counts = grid.labelCounts();
    for (const Part& part : document.assembly.parts) parts.push_back({{"id", part.id}, {"voxelCount", counts[part.id]}});
    root["parts"] = parts;
  } else if (document.kind == AssemblyKind::Frame && document.frame) {
    // A frame is its geometry (and joint voxels): parts and contacts are derived again when read.
    const json sections = plateFrameEntries().frameSections(*document.frame);  // must outlive the loop below
    for (const auto& [key, value] : sections.items()) root[key] = value;
  } else if (document.kind == AssemblyKind::Plate && document.contactsFromGeometry) {
    // A plate design is its geometry: parts and contacts are derived again when it is read.
    if (document.plateOptions.contactTolerance != PlateOptions{}.contactTolerance) {
      root["contactTolerance"] = document.plateOptions.contactTolerance;
    }
    root["plates"] = plateFrameEntries().platesJson(document.plates);
  } else {
    for (const Part& part : document.assembly.parts) {
      json entry = {{"id", part.id}};
      if (!part.name.empty()) entry["name"] = part.name;
      parts.push_back(entry);
    }
    root["parts"] = parts;
    json contacts = json::array();
    for (const Contact& contact : document.assembly.contacts) {
      contacts.push_back({{"a", document.assembly.parts[contact.a].id},
                          {"b", document.assembly.parts[contact.b].id},
                          {"normal", contact.normal},
                          {"area", contact.area}});
    }
    root["contacts"] = contacts;
    // A plan: its plates (read and checked) with its given contacts, and a result's plan.
    if (!document.plates.empty()) root["plates"] = plateFrameEntries().platesJson(document.plates);
    if (document.plateResult) writePlateResultPlan(*document.plateResult, root);
    if (!document.fabricationPlates.empty()) root["fabricationPlates"] = plateFrameEntries().platesJson(document.fabricationPlates);
    if (document.kind == AssemblyKind::Plate &&
        document.plateOptions.contactTolerance != PlateOptions{}.contactTolerance) {
      root["contactTolerance"] = document.plateOptions.contactTolerance;
    }
  }
  return root.dump(indent);
}

bool isFpuzSource(const std::string& source) {
  constexpr char kSuffix[] = ".fpuz";
  constexpr size_t kLength = sizeof(kSuffix) - 1;
  if (source.size() < kLength) return false;
  for (size_t i = 0; i < kLength; ++i) {
    if (std::tolower(static_cast<unsigned char>(source[source.size() - kLength + i])) != kSuffix[i]) return false;
  }
  return true;
}

bool isFrameDocument(const AssemblyDocument& document) {
  return document.kind == AssemblyKind::Frame && document.frame.has_value();
}

}  // namespace desia
