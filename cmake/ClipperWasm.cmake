# SPDX-License-Identifier: GPL-3.0-or-later
# Clipper 6.4.2 (2D polygon booleans, used for plate contacts) compiled from Debian's source
# package for WebAssembly, as GLPK is: the host's libpolyclipping cannot be linked into wasm.
# scripts/setup.sh unpacks the sources into third_party/polyclipping-6.4.2.
set(DESIA_CLIPPER_SOURCE_DIR ${CMAKE_SOURCE_DIR}/third_party/polyclipping-6.4.2 CACHE PATH "Clipper 6.4.2 source tree")
if(NOT EXISTS ${DESIA_CLIPPER_SOURCE_DIR}/cpp/clipper.cpp)
  message(FATAL_ERROR "Clipper sources not found in ${DESIA_CLIPPER_SOURCE_DIR}: run scripts/setup.sh first")
endif()
# The core includes <polyclipping/clipper.hpp> as Debian installs it: a folder that holds only
# that name keeps the host's /usr/include away from Emscripten (toolchain.md item 2).
set(clipper_include_dir ${CMAKE_BINARY_DIR}/clipper-include)
file(MAKE_DIRECTORY ${clipper_include_dir})
file(CREATE_LINK ${DESIA_CLIPPER_SOURCE_DIR}/cpp ${clipper_include_dir}/polyclipping SYMBOLIC)
add_library(desia_clipper STATIC ${DESIA_CLIPPER_SOURCE_DIR}/cpp/clipper.cpp)
target_include_directories(desia_clipper PUBLIC ${clipper_include_dir} PRIVATE ${DESIA_CLIPPER_SOURCE_DIR}/cpp)
target_compile_options(desia_clipper PRIVATE -w -O2 -ffp-contract=off -fwasm-exceptions)
