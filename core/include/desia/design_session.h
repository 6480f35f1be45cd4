// SPDX-License-Identifier: GPL-3.0-or-later
// One interactive design session for every kind of assembly (paper Algorithm 1 walked by hand, as
// the original tool's GUI: "Generate Next Part", "Child Index", "Go Back", then "finish
// automatically"), speaking the package's JSON: what the bindings bind once. The kind comes from
// the input: a voxel shape, a plate design (plates, no contacts) or a frame (JSON, .fpuz, OBJ).
#pragma once

#include <memory>
#include <string>

#include "desia/design_search.h"

namespace desia {

class DesignSession {
 public:
  virtual ~DesignSession() = default;

  // {"partsPlaced", "targetParts", "complete", "document", ...}: the current node (kind-specific
  // fields beside these, see docs/javascript-api.md).
  virtual std::string stateJson() const = 0;
  virtual int childCount() = 0;                     // ranked children of the current node
  virtual std::string previewJson(int child) = 0;   // the n-th child (0 = best), without moving
  virtual void choose(int child) = 0;               // move to it; BadInput when out of range
  virtual bool next() = 0;                          // move to the best child; false when none
  virtual bool back() = 0;                          // move to the parent; false at the root
  // The designer's search below the current node (the session does not move): the same result
  // JSON as a whole design of this kind.
  virtual std::string finishJson(const DesignLimits& limits) = 0;
  virtual std::string checkJson() const = 0;        // the check report of the current node
};

// Throws BadInput when `text` is none of the three kinds or fails to parse (named by `source`).
std::unique_ptr<DesignSession> openDesignSession(const std::string& text, const std::string& optionsJson,
                                                 const std::string& source);

}  // namespace desia
