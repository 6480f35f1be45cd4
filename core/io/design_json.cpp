// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/design_json.h"

#include <sstream>

#include "desia/error.h"

namespace desia {

using nlohmann::json;

int64_t integerOption(const json& value, const std::string& name, int64_t lo, int64_t hi) {
  if (!value.is_number_integer() || value.get<int64_t>() < lo || value.get<int64_t>() > hi) {
    throwBadInput("", "design option '" + name + "' must be an integer from " + std::to_string(lo) + " to " +
                          std::to_string(hi) + ", got " + value.dump());
  }
  return value.get<int64_t>();
}

double numberOption(const json& value, const std::string& name, double lo, double hi, const char* unit) {
  if (!value.is_number() || !(value.get<double>() >= lo && value.get<double>() <= hi)) {
    std::ostringstream range;
    range << lo << " to " << hi;
    throwBadInput("",
                  "design option '" + name + "' must be a number from " + range.str() + unit + ", got " + value.dump());
  }
  return value.get<double>();
}

std::string stringOption(const json& value, const std::string& name) {
  if (!value.is_string()) throwBadInput("", "design option '" + name + "' must be a string, got " + value.dump());
  return value.get<std::string>();
}

json vectorJson(const Vec3& v) { return json::array({v[0], v[1], v[2]}); }

json designOutcomeJson(DesignStatus status, const std::string& message, const DesignProgress& progress) {
  json root;
  root["status"] = designStatusName(status);
  root["message"] = message;
  root["progress"] = {
      {"nodesVisited", progress.nodes}, {"bestDepth", progress.bestDepth}, {"targetParts", progress.targetParts}};
  root["puz"] = nullptr;
  root["document"] = nullptr;
  root["verification"] = nullptr;
  return root;
}

json sessionStateJson(json steps, int targetParts, bool complete, const std::string& message, json document) {
  const int placed = static_cast<int>(steps.size()) + 1;
  return {{"partsPlaced", placed},       {"targetParts", targetParts}, {"complete", complete},
          {"message", message},          {"steps", std::move(steps)},  {"document", std::move(document)}};
}

}  // namespace desia
