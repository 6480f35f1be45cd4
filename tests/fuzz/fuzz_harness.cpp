// SPDX-License-Identifier: GPL-3.0-or-later
// The libFuzzer entry point of every harness: tests/fuzz/CMakeLists.txt compiles this file once per
// target with DESIA_FUZZ_TARGET naming one function of fuzz_targets.h, so the harnesses differ only
// in the body they share with the regression replay.
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.h"

#ifndef DESIA_FUZZ_TARGET
#error "define DESIA_FUZZ_TARGET to one of the functions in fuzz_targets.h"
#endif

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  desia::fuzz::DESIA_FUZZ_TARGET(data, size);
  return 0;
}
