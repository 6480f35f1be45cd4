// SPDX-License-Identifier: GPL-3.0-or-later
#include "desia/error.h"

namespace desia {

void throwBadInput(const std::string& where, const std::string& what) {
  throw Error(ErrorCode::BadInput, where.empty() ? what : where + ": " + what);
}

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::BadInput: return "bad-input";
    case ErrorCode::TooLarge: return "too-large";
    case ErrorCode::Unsupported: return "unsupported";
    case ErrorCode::Internal: return "internal";
    case ErrorCode::KindNotBuilt: return "kind-not-built";
  }
  return "internal";
}

}  // namespace desia
