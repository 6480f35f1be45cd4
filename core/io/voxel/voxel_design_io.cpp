// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/design_io.h"

#include <nlohmann/json.hpp>

#include "desia/document.h"
#include "desia/error.h"
#include "desia/formats.h"
#include "io/design_json.h"
#include "io/json_input.h"

namespace desia {
namespace {

using nlohmann::json;

std::vector<std::vector<int64_t>> groupsFromJson(const json& list, const VoxelGrid& shape, const std::string& source) {
  if (!list.is_array()) throwBadInput(source, "groups: expected [[[x, y, z], ...], ...]");
  std::vector<std::vector<int64_t>> groups;
  for (size_t g = 0; g < list.size(); ++g) {
    const std::string where = "groups[" + std::to_string(g) + "]";
    const json& group = list[g];
    if (!group.is_array() || group.empty()) throwBadInput(source, where + ": expected a non-empty list of [x, y, z]");
    std::vector<int64_t> voxels;
    for (const json& voxel : group) {
      if (!voxel.is_array() || voxel.size() != 3 || !voxel[0].is_number_integer() || !voxel[1].is_number_integer() ||
          !voxel[2].is_number_integer()) {
        throwBadInput(source, where + ": " + voxel.dump() + " is not [x, y, z]");
      }
      const int64_t x = voxel[0].get<int64_t>(), y = voxel[1].get<int64_t>(), z = voxel[2].get<int64_t>();
      const bool inGrid = x >= 0 && y >= 0 && z >= 0 && x < shape.nx() && y < shape.ny() && z < shape.nz();
      if (!inGrid || shape.label(int(x), int(y), int(z)) == 0) throwBadInput(source, where + ": voxel " + voxel.dump() + " is not in the shape");
      voxels.push_back(shape.index(int(x), int(y), int(z)));
    }
    groups.push_back(std::move(voxels));
  }
  return groups;
}

}  // namespace

Int3 parseAxisDirection(const std::string& text, const std::string& what) {
  static const std::pair<const char*, Int3> kNames[] = {{"+x", {1, 0, 0}}, {"-x", {-1, 0, 0}}, {"+y", {0, 1, 0}},
                                                        {"-y", {0, -1, 0}}, {"+z", {0, 0, 1}}, {"-z", {0, 0, -1}}};
  for (const auto& [name, direction] : kNames) {
    if (text == name) return direction;
  }
  throwBadInput("", what + " must be +x, -x, +y, -y, +z or -z, got '" + text + "'");
}

std::vector<std::vector<int64_t>> parseVoxelGroupsJson(const std::string& text, const VoxelGrid& shape,
                                                       const std::string& source) {
  const json root = parseJsonText(text, source);
  if (!root.is_object() || !root.contains("groups")) throwBadInput(source, "expected {\"groups\": [[[x, y, z], ...], ...]}");
  return groupsFromJson(root["groups"], shape, source);
}

VoxelDesignOptions parseDesignOptionsJson(const std::string& text, const VoxelGrid& shape) {
  const json root = parseJsonText(text, "design options");
  if (!root.is_object()) throwBadInput("", "design options must be an object");
  VoxelDesignOptions options;
  if (!root.contains("parts")) throwBadInput("", "design option 'parts' is required");
  for (const auto& [key, value] : root.items()) {
    if (key == "parts") options.parts = static_cast<int>(integerOption(value, "parts", 1, 1000000));
    else if (key == "seed") options.seed = static_cast<uint64_t>(integerOption(value, "seed", 0, int64_t(1) << 52));
    else if (key == "candidates") options.candidates = static_cast<int>(integerOption(value, "candidates", 1, 10000));
    else if (key == "rank") options.ranking = parseCandidateRanking(stringOption(value, "rank"));
    else if (key == "mode") options.mode = parseDesignMode(stringOption(value, "mode"));
    else if (key == "minPartSize") options.minPartSize = static_cast<int>(integerOption(value, "minPartSize", 0, 1000000));
    else if (key == "maxPartSize") options.maxPartSize = static_cast<int>(integerOption(value, "maxPartSize", 0, 1000000));
    else if (key == "evenParts") {
      if (!value.is_boolean()) throwBadInput("", "design option 'evenParts' must be true or false, got " + value.dump());
      options.evenParts = value.get<bool>();
    }
    else if (key == "nodeLimit") options.limits.nodeLimit = integerOption(value, "nodeLimit", 0, int64_t(1) << 52);
    else if (key == "keyDirection") options.keyDirection = parseAxisDirection(stringOption(value, "keyDirection"));
    else if (key == "groups") options.groups = groupsFromJson(value, shape, "design options");
    else if (key == "timeLimit") {
      if (!value.is_number() || !(value.get<double>() >= 0)) throwBadInput("", "design option 'timeLimit' must be seconds >= 0, got " + value.dump());
      options.limits.timeLimitSeconds = value.get<double>();
    } else {
      throwBadInput("", "unknown design option '" + key +
                            "' (expected parts, seed, candidates, rank, mode, minPartSize, maxPartSize, evenParts, "
                            "nodeLimit, keyDirection, groups or timeLimit)");
    }
  }
  return options;
}

std::string designProgressToJson(const DesignProgress& progress) {
  return json{{"nodesVisited", progress.nodes},
              {"depth", progress.depth},
              {"bestDepth", progress.bestDepth},
              {"targetParts", progress.targetParts},
              {"elapsedSeconds", progress.seconds}}
      .dump();
}

DesignLimits parseDesignLimitsJson(const std::string& text) {
  const json root = parseJsonText(text, "finish options");
  if (!root.is_object()) throwBadInput("", "finish options must be an object");
  DesignLimits limits;
  for (const auto& [key, value] : root.items()) {
    if (key == "nodeLimit") {
      limits.nodeLimit = integerOption(value, "nodeLimit", 0, int64_t(1) << 52);
    } else if (key == "timeLimit") {
      if (!value.is_number() || !(value.get<double>() >= 0)) throwBadInput("", "finish option 'timeLimit' must be seconds >= 0, got " + value.dump());
      limits.timeLimitSeconds = value.get<double>();
    } else {
      throwBadInput("", "unknown finish option '" + key + "' (expected timeLimit or nodeLimit)");
    }
  }
  return limits;
}

std::string designResultToJson(const VoxelDesignResult& result, int indent) {
  json root;
  root["status"] = designStatusName(result.status);
  root["message"] = result.message;
  json progress = json::parse(designProgressToJson(result.progress));
  progress.erase("elapsedSeconds");  // timing differs between runs; keep results reproducible
  root["progress"] = progress;
  root["seed"] = result.seed;
  if (result.status == DesignStatus::Success) {
    const AssemblyDocument document = documentFromVoxels(result.puzzle);
    root["partSizes"] = {{"min", result.partSizes.min}, {"max", result.partSizes.max}, {"mean", result.partSizes.mean}};
    root["puz"] = formatPuz(result.puzzle);
    root["document"] = json::parse(documentToJson(document, -1));
    root["verification"] = json::parse(checkReportToJson(document, result.verification, -1));
  } else {
    root["partSizes"] = nullptr;
    root["puz"] = nullptr;
    root["document"] = nullptr;
    root["verification"] = nullptr;
  }
  return root.dump(indent);
}

}  // namespace desia
