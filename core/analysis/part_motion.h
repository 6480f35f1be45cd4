// SPDX-License-Identifier: GPL-3.0-or-later
// Small pieces shared by the interlocking tests and disassembly planning.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "analysis/vec3.h"
#include "desia/analysis.h"
#include "desia/model.h"
#include "desia/tolerances.h"

namespace desia {

// Can `part` translate along `d` without pushing into a part still present (infinitesimally)?
// `present` may be null: every part is present.
inline bool isPartFreeAlong(const Assembly& assembly, const std::vector<bool>* present, int part, const Vec3& d) {
  for (const Contact& contact : assembly.contacts) {
    if (present && (!(*present)[contact.a] || !(*present)[contact.b])) continue;
    if (contact.a == part && dot(d, contact.normal) > tolerance::kDirection) return false;
    if (contact.b == part && dot(d, contact.normal) < -tolerance::kDirection) return false;
  }
  return true;
}

// The positive verdicts, worded the same for both tests.
inline InterlockingResult interlockingResult(const Assembly& assembly, int key, std::vector<Vec3> keyDirections) {
  InterlockingResult result;
  result.verdict = Verdict::Interlocking;
  result.key = key;
  result.keyDirections = std::move(keyDirections);
  std::ostringstream reason;
  reason << "only the key (part " << assembly.parts[key].id << ") can move, along";
  for (const Vec3& d : result.keyDirections) reason << ' ' << directionLabel(d);
  result.reason = reason.str();
  return result;
}

inline InterlockingResult deadlockedResult(const std::string& reason) {
  InterlockingResult result;
  result.verdict = Verdict::Deadlocked;
  result.reason = reason;
  return result;
}

}  // namespace desia
