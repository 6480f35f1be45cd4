// SPDX-License-Identifier: GPL-3.0-or-later
// The plate joint planner's options and result as JSON, for the WebAssembly module.
#include <nlohmann/json.hpp>

#include <optional>

#include "desia/design_io.h"
#include "desia/document.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "io/design_json.h"
#include "io/json_input.h"

namespace desia {

using nlohmann::json;

namespace {

// {"dovetail": {"slope": 0.2, "stop": 12}, "stepTenon": {"width": 0.25}}: desia::setJointSize each.
void setJointSizes(JointCutOptions& joints, const json& sizes) {
  if (!sizes.is_object()) throwBadInput("", "design option 'jointSizes' must be {family: {size: number}}, got " + sizes.dump());
  for (const auto& [family, fields] : sizes.items()) {
    if (!fields.is_object()) throwBadInput("", "jointSizes." + family + " must be {size: number}, got " + fields.dump());
    for (const auto& [field, value] : fields.items()) {
      if (!value.is_number()) throwBadInput("", "jointSizes." + family + "." + field + " must be a number, got " + value.dump());
      setJointSize(joints, family + "." + field, value.get<double>());
    }
  }
}

}  // namespace

PlateDesignOptions parsePlateDesignOptionsJson(const std::string& text) {
  const json root = parseJsonText(text, "design options");
  if (!root.is_object()) throwBadInput("", "design options must be an object");
  PlateDesignOptions options;
  options.realization = JointRealization::Auto;  // the package's default, as the CLI's
  for (const auto& [name, value] : root.items()) {
    if (name == "seed")
      options.seed = static_cast<uint64_t>(integerOption(value, name, 0, int64_t(1) << 62));
    else if (name == "candidates")
      options.candidates = static_cast<int>(integerOption(value, name, 1, 10000));
    else if (name == "nodeLimit")
      options.limits.nodeLimit = integerOption(value, name, 1, int64_t(1) << 50);
    else if (name == "timeLimit")
      options.limits.timeLimitSeconds = static_cast<double>(integerOption(value, name, 1, 10000000));
    else if (name == "joints")
      options.realization = parseJointRealization(value.is_string() ? value.get<std::string>() : value.dump());
    else if (name == "clearance")
      options.joints.clearance = numberOption(value, name, 0, 10, " (mm)");
    else if (name == "tenonWidth")
      options.joints.tenonWidth = numberOption(value, name, 1, 10000, " (mm)");
    else if (name == "tenonCount")
      options.joints.tenonCount = static_cast<int>(integerOption(value, name, 1, 20));
    else if (name == "jointSizes")
      setJointSizes(options.joints, value);
    else {
      throwBadInput("", "unknown design option '" + name +
                            "' for designPlate (expected seed, candidates, nodeLimit, timeLimit, joints, clearance, "
                            "tenonWidth, tenonCount or jointSizes)");
    }
  }
  return options;
}

std::string plateDesignResultToJson(const AssemblyDocument& input, const PlateDesignResult& result) {
  json root = designOutcomeJson(result.status, result.message, result.progress);
  if (result.status == DesignStatus::Success) {
    const std::string planText = plateDesignToJson(input, result, -1);
    const AssemblyDocument plan = parseJsonDocument(planText, "plan");
    CheckOptions options;
    options.method = CheckMethod::Both;
    const CheckReport report = checkDocument(plan, options);
    if (checkPassed(report)) {
      root["document"] = json::parse(planText);
      root["verification"] = json::parse(checkReportToJson(plan, report, -1));
    } else {  // never offered: what is returned is what `desia check` passes
      root["status"] = designStatusName(DesignStatus::NotFound);
      root["message"] = "the plan found did not verify: " +
                        (report.shapeRemoval && !report.shapeRemoval->failure.empty() ? report.shapeRemoval->failure
                                                                                      : report.result.reason);
    }
  }
  // A cut point: the repair the core proposes (bars that bypass it, Fig. 18) as a design to open.
  root["repair"] = nullptr;
  if (result.status == DesignStatus::CutPoint && !input.plates.empty()) {
    if (const std::optional<PlateRepair> repair = proposeCutPointRepair(input.plates, input.plateOptions)) {
      const AssemblyDocument repaired =
          documentFromPlates(repair->plates, input.plateOptions, "repair", input.name + " (repaired)");
      root["repair"] = {{"message", repair->message}, {"document", json::parse(documentToJson(repaired, -1))}};
    }
  }
  return root.dump();
}

namespace {

json stepJson(const AssemblyDocument& input, const PlateDesignStep& step) {
  json joints = json::array();
  for (const PlateJoint& joint : step.joints) {
    joints.push_back({{"mover", input.plates[joint.mover].id}, {"other", input.plates[joint.other].id},
                      {"type", jointTypeName(joint.type)}, {"direction", vectorJson(joint.direction)}});
  }
  return {{"plate", input.plates[step.plate].id}, {"direction", vectorJson(step.direction)}, {"joints", joints}};
}

}  // namespace

std::string plateSessionStateToJson(const AssemblyDocument& input, const PlateDesignSession& session) {
  json steps = json::array();
  for (const PlateDesignStep& step : session.steps()) {
    steps.push_back({{"plate", input.plates[step.plate].id}, {"direction", vectorJson(step.direction)}});
  }
  json document =
      json::parse(session.complete() ? plateDesignToJson(input, session.result(), -1) : documentToJson(input, -1));
  const json root =
      sessionStateJson(std::move(steps), session.targetPlates(), session.complete(), session.result().message, document);
  return root.dump();
}

std::string plateStepToJson(const AssemblyDocument& input, const PlateDesignStep& step) { return stepJson(input, step).dump(); }

}  // namespace desia
