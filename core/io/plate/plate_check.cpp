// SPDX-License-Identifier: GPL-3.0-or-later
// `desia check` of a plate design result: the plan verified again as the designer verified it.
#include "io/plate/plate_check.h"

#include <map>

#include "desia/plate.h"

namespace desia {
namespace {

// The plates in the order the plan takes them out (matched by id, whatever the file's order).
std::vector<Plate> platesInRemovalOrder(const std::vector<Plate>& plates, const PlateResultPlan& plan) {
  std::map<int, const Plate*> byId;
  for (const Plate& plate : plates) byId[plate.id] = &plate;
  std::vector<Plate> ordered;
  for (int id : plan.removalOrder) ordered.push_back(*byId.at(id));  // one plate per part: read so
  return ordered;
}

// The document's given contacts (a planned result's joint model) with part k = the k-th to leave.
Assembly modelInRemovalOrder(const Assembly& assembly, const PlateResultPlan& plan) {
  std::vector<int> position(assembly.parts.size(), 0);
  Assembly model;
  for (size_t k = 0; k < plan.removalOrder.size(); ++k) {
    const int index = assembly.indexOfId(plan.removalOrder[k]);
    position[static_cast<size_t>(index)] = static_cast<int>(k);
    model.parts.push_back(assembly.parts[static_cast<size_t>(index)]);
  }
  for (const Contact& contact : assembly.contacts) {
    model.contacts.push_back({position[static_cast<size_t>(contact.a)], position[static_cast<size_t>(contact.b)],
                              contact.normal, contact.area});
  }
  return model;
}

// A plate result: the plan verified as the designer verified it (verifyJointedPlates or
// verifyPlannedPlates), and the verdict reported on the contacts that verification judged.
}  // namespace

CheckReport checkPlateResult(const AssemblyDocument& document, const CheckOptions& options) {
  const PlateResultPlan& plan = *document.plateResult;
  const std::vector<Plate> plates = platesInRemovalOrder(document.plates, plan);
  const bool planned = plan.jointGeometry == "planned";
  const PlateRemovalVerification verification =
      planned ? verifyPlannedPlates(modelInRemovalOrder(document.assembly, plan), plates, plan.directions,
                                    document.plateOptions)
              : verifyJointedPlates(plates, plan.directions, document.plateOptions);
  AssemblyDocument judged = document;
  judged.assembly = verification.assembly;
  CheckReport report = checkAssembly(judged, options);
  ShapeRemovalCheck check;
  check.checked =
      planned ? "nothing is cut (joints \"planned\"): the plan tested on the joint model's contacts (dbg and lp, key "
                "= part " + std::to_string(plan.removalOrder.front()) + "), and the plates as given swept along their "
                "directions in the planned order, plates that cross excepted; it holds only once the joints are made "
                "as the model describes"
              : "contacts recomputed from the jointed plates (dbg and lp, key = part " +
                    std::to_string(plan.removalOrder.front()) +
                    "), and each plate swept along its direction in the planned order";
  check.failure = verification.failure;
  if (check.failure.empty() && !document.fabricationPlates.empty()) {
    check.failure = fabricationPlatesFailure(document.plates, document.fabricationPlates, plan.clearance,
                                             document.plateOptions);
    check.checked += "; fabricationPlates within the clearance of the verified plates";
  }
  report.shapeRemoval = check;
  return report;
}

}  // namespace desia
