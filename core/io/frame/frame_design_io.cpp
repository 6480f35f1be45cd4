// SPDX-License-Identifier: GPL-3.0-or-later
// The frame designer's options and result as JSON, for the WebAssembly module.
#include "desia/design_io.h"

#include <nlohmann/json.hpp>

#include "desia/document.h"
#include "desia/error.h"
#include "io/design_json.h"
#include "io/json_input.h"

namespace desia {

using nlohmann::json;

FramePackageOptions parseFrameDesignOptionsJson(const std::string& text) {
  const json root = parseJsonText(text, "design options");
  if (!root.is_object()) throwBadInput("", "design options must be an object");
  FramePackageOptions options;
  for (const auto& [name, value] : root.items()) {
    if (name == "seed") {
      options.design.seed = static_cast<uint64_t>(integerOption(value, name, 0, int64_t(1) << 62));
    } else if (name == "candidates") {
      options.design.candidates = static_cast<int>(integerOption(value, name, 1, 10000));
    } else if (name == "nodeLimit") {
      options.design.limits.nodeLimit = integerOption(value, name, 1, int64_t(1) << 50);
    } else if (name == "timeLimit") {
      options.design.limits.timeLimitSeconds = numberOption(value, name, 0, 1e7, " (seconds, 0 = none)");
    } else if (name == "jointSize") {
      // Like --joint-size: the edge of a joint cube in the frame's units.
      if (!value.is_number() || !(value.get<double>() > 0 && value.get<double>() <= 1e9)) {
        throwBadInput(
            "", "design option 'jointSize' must be a number above 0 and up to 1e9 (model units), got " + value.dump());
      }
      options.jointSize = value.get<double>();
    } else {
      throwBadInput("", "unknown design option '" + name +
                            "' for designFrame (expected seed, candidates, nodeLimit, timeLimit or jointSize)");
    }
  }
  return options;
}

std::string frameDesignResultToJson(const FrameDocument& input, const FrameDesignResult& result) {
  json root = designOutcomeJson(result.status, result.message, result.progress);
  if (result.status == DesignStatus::Success) {
    // The same text `desia design frame` writes (before its final newline), checked as written.
    const std::string text = frameResultToJson(input.layout, result, input.name);
    const AssemblyDocument written = parseAssemblyText(text, "result");
    root["document"] = json::parse(text);
    root["verification"] = json::parse(checkReportToJson(written, checkDocument(written), -1));
  }
  return root.dump();
}

std::string frameSessionStateToJson(const FrameDocument& input, const FrameDesignSession& session) {
  const Frame& frame = input.layout.frame;
  json steps = json::array();
  for (const FrameDesignStep& step : session.steps()) {
    steps.push_back({{"beam", frame.beams[step.beam].id}, {"direction", vectorJson(step.direction)}});
  }
  json document = json::parse(session.complete() ? frameResultToJson(input.layout, session.result(), input.name, -1)
                                                 : frameDocumentToJson(input, -1));
  const json root =
      sessionStateJson(std::move(steps), session.targetBeams(), session.complete(), session.result().message, document);
  return root.dump();
}

std::string frameStepToJson(const FrameDocument& input, const FrameDesignStep& step) {
  const Frame& frame = input.layout.frame;
  json joints = json::array();
  for (int end = 0; end < 2; ++end) {
    joints.push_back({{"joint", frame.joints[frame.beams[step.beam].joints[end]].id}, {"voxels", step.voxels[end]}});
  }
  return json{{"beam", frame.beams[step.beam].id}, {"direction", vectorJson(step.direction)}, {"joints", joints}}
      .dump();
}

}  // namespace desia
