// SPDX-License-Identifier: GPL-3.0-or-later
// 3MF files as mesh assemblies (issue 29): the model part named by the package's relationships
// (3MF Core Specification 1.3, chapters 2-4), read by a small XML reader of the few elements it
// needs — model (unit), object (id, name), vertex, triangle, component, item — each build item a
// part, its object's meshes and components flattened under the transforms, in millimetres.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "desia/error.h"
#include "desia/formats.h"
#include "three_mf.h"

namespace desia {
namespace {

const char* const kModelRelationship = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";
const char* const kDefaultModelPath = "3D/3dmodel.model";
// Components refer to other objects; deeper nesting than this is taken for a cycle.
constexpr int kMaxComponentDepth = 32;
// Objects placed by one build item, counting repeats: components that each use an object twice,
// nested 32 deep, would place it 2^32 times without a triangle to count.
constexpr size_t kMaxPlacedObjects = 1'000'000;

// One start or end tag: its local name (namespace prefix dropped), attributes and line.
struct XmlTag {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  bool end = false;          // </name>
  bool selfClosing = false;  // <name ... />
  int line = 1;

  const std::string* attribute(const std::string& key) const {
    for (const auto& [name, value] : attributes) {
      if (name == key) return &value;
    }
    return nullptr;
  }
};

std::string localName(const std::string& name) {
  const size_t colon = name.find(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

// The five predefined entities and numeric references (ASCII only: names are shown, not used).
std::string decodedEntities(const std::string& value) {
  if (value.find('&') == std::string::npos) return value;
  static const std::pair<const char*, char> kEntities[] = {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (size_t i = 0; i < value.size();) {
    bool replaced = false;
    for (const auto& [entity, character] : kEntities) {
      if (value.compare(i, std::char_traits<char>::length(entity), entity) == 0) {
        out += character;
        i += std::char_traits<char>::length(entity);
        replaced = true;
        break;
      }
    }
    if (!replaced) out += value[i++];
  }
  return out;
}

// Start and end tags in document order; comments, processing instructions, CDATA and the
// doctype are skipped, text between tags is ignored (3MF keeps its data in attributes).
class XmlTags {
 public:
  XmlTags(const std::string& text, std::string where) : text_(text), where_(std::move(where)) {}

  bool next(XmlTag* tag) {
    while (true) {
      const size_t open = text_.find('<', at_);
      if (open == std::string::npos) return false;
      advanceTo(open);
      if (skipMarkup("<?", "?>") || skipMarkup("<!--", "-->") || skipMarkup("<![CDATA[", "]]>") || skipMarkup("<!", ">")) continue;
      readTag(tag);
      return true;
    }
  }

  [[noreturn]] void fail(int line, const std::string& what) const { throwBadInput(where_ + ":" + std::to_string(line), what); }
  [[noreturn]] void tooLarge(int line, const std::string& what) const {
    throw Error(ErrorCode::TooLarge, where_ + ":" + std::to_string(line) + ": " + what);
  }

 private:
  void advanceTo(size_t position) {
    for (; at_ < position; ++at_) line_ += text_[at_] == '\n' ? 1 : 0;
  }

  bool skipMarkup(const char* opening, const char* closing) {
    if (text_.compare(at_, std::char_traits<char>::length(opening), opening) != 0) return false;
    const size_t end = text_.find(closing, at_);
    if (end == std::string::npos) fail(line_, std::string("'") + opening + "' is never closed");
    advanceTo(end + std::char_traits<char>::length(closing));
    return true;
  }

  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  static bool isNameEnd(char c) { return isSpace(c) || c == '>' || c == '/' || c == '='; }

  void skipSpace() {
    while (at_ < text_.size() && isSpace(text_[at_])) advanceTo(at_ + 1);
  }

  std::string readName() {
    const size_t start = at_;
    while (at_ < text_.size() && !isNameEnd(text_[at_])) ++at_;
    return text_.substr(start, at_ - start);
  }

  void readTag(XmlTag* tag) {
    *tag = XmlTag{};
    tag->line = line_;
    ++at_;  // '<'
    if (at_ < text_.size() && text_[at_] == '/') tag->end = true, ++at_;
    tag->name = localName(readName());
    if (tag->name.empty()) fail(tag->line, "a tag without a name");
    while (true) {
      skipSpace();
      if (at_ >= text_.size()) fail(tag->line, "<" + tag->name + "> is never closed");
      if (text_[at_] == '>') break;
      if (text_.compare(at_, 2, "/>") == 0) {
        tag->selfClosing = true;
        ++at_;
        break;
      }
      const std::string key = localName(readName());
      skipSpace();
      if (key.empty() || at_ >= text_.size() || text_[at_] != '=') fail(tag->line, "<" + tag->name + ">: an attribute without a value");
      advanceTo(at_ + 1);
      skipSpace();
      const char quote = at_ < text_.size() ? text_[at_] : '\0';
      if (quote != '"' && quote != '\'') fail(tag->line, "<" + tag->name + ">: the value of '" + key + "' is not quoted");
      const size_t close = text_.find(quote, at_ + 1);
      if (close == std::string::npos) fail(tag->line, "<" + tag->name + ">: the value of '" + key + "' is never closed");
      tag->attributes.emplace_back(key, decodedEntities(text_.substr(at_ + 1, close - at_ - 1)));
      advanceTo(close + 1);
    }
    ++at_;  // '>'
  }

  const std::string& text_;
  std::string where_;
  size_t at_ = 0;
  int line_ = 1;
};

// A 3MF transform (section 3.3): 12 numbers m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32 of a
// row-vector matrix, x' = x m00 + y m10 + z m20 + m30 and so on.
using Transform = std::array<double, 12>;
constexpr Transform kIdentity = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};

// `first`, then `then`.
Transform composed(const Transform& first, const Transform& then) {
  Transform out{};
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 3; ++column) {
      double sum = row == 3 ? then[9 + column] : 0;
      for (int k = 0; k < 3; ++k) sum += first[row * 3 + k] * then[k * 3 + column];
      out[row * 3 + column] = sum;
    }
  }
  return out;
}

std::array<double, 3> applied(const Transform& m, const std::array<double, 3>& p) {
  return {p[0] * m[0] + p[1] * m[3] + p[2] * m[6] + m[9], p[0] * m[1] + p[1] * m[4] + p[2] * m[7] + m[10],
          p[0] * m[2] + p[1] * m[5] + p[2] * m[8] + m[11]};
}

double determinant(const Transform& m) {
  return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
}

// Millimetres per model unit (section 3.4.1: micron, millimeter, centimeter, inch, foot, meter).
double millimetresPerModelUnit(const std::string& unit, const XmlTags& tags, int line) {
  constexpr double kMicronsPerMillimetre = 1000;
  static const std::pair<const char*, double> kUnits[] = {{"micron", 1 / kMicronsPerMillimetre}, {"millimeter", 1},
                                                           {"centimeter", 10},  {"inch", 25.4},
                                                           {"foot", 304.8},     {"meter", 1000}};
  for (const auto& [name, millimetres] : kUnits) {
    if (unit == name) return millimetres;
  }
  tags.fail(line, "<model>: unknown unit '" + unit + "' (expected micron, millimeter, centimeter, inch, foot or meter)");
}

struct Component {
  int objectId = 0;
  Transform transform = kIdentity;
  int line = 0;
};

struct ModelObject {
  std::string name;
  TriangleMesh mesh;
  std::vector<Component> components;
};

struct Model {
  double millimetres = 1;
  std::map<int, ModelObject> objects;
  std::vector<Component> items;  // the build: an object and its transform each
};

class ModelReader {
 public:
  ModelReader(const std::string& text, const std::string& where) : tags_(text, where) {}

  Model read() {
    XmlTag tag;
    while (tags_.next(&tag)) {
      if (tag.end) {
        if (tag.name == "object") object_ = nullptr;
        continue;
      }
      if (tag.name == "model") {
        if (const std::string* unit = tag.attribute("unit")) model_.millimetres = millimetresPerModelUnit(*unit, tags_, tag.line);
      } else if (tag.name == "object") {
        startObject(tag);
      } else if (tag.name == "vertex") {
        currentObject(tag).mesh.vertices.push_back({number(tag, "x"), number(tag, "y"), number(tag, "z")});
      } else if (tag.name == "triangle") {
        addTriangle(tag);
      } else if (tag.name == "component") {
        currentObject(tag).components.push_back(reference(tag));
      } else if (tag.name == "item") {
        model_.items.push_back(reference(tag));
      }
    }
    return std::move(model_);
  }

 private:
  double number(const XmlTag& tag, const char* key) const {
    const std::string& text = required(tag, key);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
      tags_.fail(tag.line, "<" + tag.name + ">: " + key + " '" + text + "' is not a finite number");
    }
    return value;
  }

  int64_t integer(const XmlTag& tag, const char* key, int64_t limit) const {
    const std::string& text = required(tag, key);
    char* end = nullptr;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || end != text.c_str() + text.size() || value < 0 || value > limit) {
      tags_.fail(tag.line, "<" + tag.name + ">: " + key + " '" + text + "' is not an index from 0 to " + std::to_string(limit));
    }
    return value;
  }

  const std::string& required(const XmlTag& tag, const char* key) const {
    const std::string* value = tag.attribute(key);
    if (!value) tags_.fail(tag.line, "<" + tag.name + "> has no " + key);
    return *value;
  }

  ModelObject& currentObject(const XmlTag& tag) {
    if (!object_) tags_.fail(tag.line, "<" + tag.name + "> outside an <object>");
    return *object_;
  }

  void startObject(const XmlTag& tag) {
    const int id = static_cast<int>(integer(tag, "id", INT32_MAX));
    if (model_.objects.count(id)) tags_.fail(tag.line, "<object>: a second object with id " + std::to_string(id));
    object_ = &model_.objects[id];
    const std::string* name = tag.attribute("name");
    object_->name = name && !name->empty() ? *name : "object " + std::to_string(id);
    if (tag.selfClosing) object_ = nullptr;
  }

  void addTriangle(const XmlTag& tag) {
    ModelObject& object = currentObject(tag);
    if (static_cast<int64_t>(object.mesh.triangles.size()) >= MeshLimits::kMaxTriangles) {
      tags_.tooLarge(tag.line, "<triangle>: the object has more than " + std::to_string(MeshLimits::kMaxTriangles) + " triangles (the limit)");
    }
    // Vertex indices are checked against the object's vertices (listed before its triangles).
    const int64_t last = static_cast<int64_t>(object.mesh.vertices.size()) - 1;
    if (last < 0) tags_.fail(tag.line, "<triangle> before any <vertex> of its object");
    object.mesh.triangles.push_back({static_cast<int>(integer(tag, "v1", last)), static_cast<int>(integer(tag, "v2", last)),
                                     static_cast<int>(integer(tag, "v3", last))});
  }

  // A component or build item: its object and transform (an external model part, the production
  // extension's p:path, is not read).
  Component reference(const XmlTag& tag) {
    Component component;
    component.line = tag.line;
    component.objectId = static_cast<int>(integer(tag, "objectid", INT32_MAX));
    if (tag.attribute("path")) tags_.fail(tag.line, "<" + tag.name + ">: objects in other model parts (p:path) are not read");
    if (const std::string* transform = tag.attribute("transform")) {
      const char* at = transform->c_str();
      for (double& value : component.transform) {
        char* end = nullptr;
        value = std::strtod(at, &end);
        if (end == at || !std::isfinite(value)) tags_.fail(tag.line, "<" + tag.name + ">: transform '" + *transform + "' is not 12 finite numbers");
        at = end;
      }
      while (*at == ' ' || *at == '\t' || *at == '\r' || *at == '\n') ++at;
      if (*at != '\0') tags_.fail(tag.line, "<" + tag.name + ">: transform '" + *transform + "' has more than 12 numbers");
    }
    return component;
  }

  XmlTags tags_;
  Model model_;
  ModelObject* object_ = nullptr;
};

// The meshes of `item`'s object and of its components (walked with an explicit stack), each
// under its transform, as one mesh; a mirroring transform keeps the triangles facing outward.
TriangleMesh flattened(const Model& model, const Component& item, const XmlTags& tags) {
  TriangleMesh part;
  struct Pending {
    Component reference;
    int depth;
  };
  std::vector<Pending> stack{{item, 0}};
  size_t placed = 0;
  while (!stack.empty()) {
    if (++placed > kMaxPlacedObjects) {
      tags.tooLarge(item.line, "<item>: its components place more than " + std::to_string(kMaxPlacedObjects) + " objects");
    }
    const Pending pending = stack.back();
    stack.pop_back();
    const auto found = model.objects.find(pending.reference.objectId);
    if (found == model.objects.end()) tags.fail(pending.reference.line, "no object with id " + std::to_string(pending.reference.objectId));
    if (pending.depth > kMaxComponentDepth) tags.fail(pending.reference.line, "components nest more than " + std::to_string(kMaxComponentDepth) + " deep (a cycle?)");
    const ModelObject& object = found->second;
    const Transform& transform = pending.reference.transform;
    const int first = static_cast<int>(part.vertices.size());
    for (const auto& vertex : object.mesh.vertices) part.vertices.push_back(applied(transform, vertex));
    const bool mirrored = determinant(transform) < 0;
    for (const auto& t : object.mesh.triangles) {
      part.triangles.push_back(mirrored ? std::array<int, 3>{first + t[0], first + t[2], first + t[1]}
                                        : std::array<int, 3>{first + t[0], first + t[1], first + t[2]});
    }
    if (static_cast<int64_t>(part.triangles.size()) > MeshLimits::kMaxTriangles) {
      tags.tooLarge(item.line, "<item>: more than " + std::to_string(MeshLimits::kMaxTriangles) + " triangles (the limit)");
    }
    for (const Component& component : object.components) {
      stack.push_back({{component.objectId, composed(component.transform, transform), component.line}, pending.depth + 1});
    }
  }
  return part;
}

// The model part the package's relationships name (section 2.1.1), else the usual one.
std::string modelPath(const ZipArchive& archive, const std::string& source) {
  const std::string relationships = "_rels/.rels";
  if (!archive.has(relationships)) return kDefaultModelPath;
  const std::string text = archive.read(relationships);
  XmlTags tags(text, source + ": " + relationships);
  XmlTag tag;
  while (tags.next(&tag)) {
    const std::string* type = tag.attribute("Type");
    const std::string* target = tag.attribute("Target");
    if (tag.name == "Relationship" && type && target && *type == kModelRelationship) {
      return !target->empty() && target->front() == '/' ? target->substr(1) : *target;
    }
  }
  return kDefaultModelPath;
}

}  // namespace

std::vector<MeshPart> readThreeMfParts(const std::string& bytes, const std::string& source) {
  const ZipArchive archive(bytes, source);
  const std::string path = modelPath(archive, source);
  const std::string text = archive.read(path);
  const std::string where = source + ": " + path;
  const Model model = ModelReader(text, where).read();
  const XmlTags tags(text, where);  // for messages about the build
  if (model.items.empty()) throwBadInput(where, "the model's <build> has no <item>: nothing to check");
  std::vector<MeshPart> parts;
  for (const Component& item : model.items) {
    const Transform inMillimetres = composed(item.transform, {model.millimetres, 0, 0, 0, model.millimetres, 0, 0, 0, model.millimetres, 0, 0, 0});
    TriangleMesh mesh = flattened(model, {item.objectId, inMillimetres, item.line}, tags);
    if (mesh.triangles.empty()) tags.fail(item.line, "<item>: object " + std::to_string(item.objectId) + " has no triangles");
    parts.push_back({0, model.objects.at(item.objectId).name, source, std::move(mesh)});
  }
  return parts;
}

}  // namespace desia
