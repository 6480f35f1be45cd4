# SPDX-License-Identifier: GPL-3.0-or-later
# Clipper 6.4.2 (2D polygon booleans: plate contacts, cuts, exports) compiled from Debian's source
# package, natively and for WebAssembly alike. scripts/setup.sh unpacks the sources into
# third_party/polyclipping-6.4.2.
#
# Why not Debian's libpolyclipping natively: Clipper orders its local minima and intersections
# with std::sort on y alone, and libstdc++ (native) and libc++ (Emscripten) leave ties in
# different orders, so the same input gave polygons in another order or starting at another
# vertex: plate documents whose holes and contacts came in another order, exported plate meshes
# with other triangles (issue 26; the golden corpus' WebAssembly comparison). std::stable_sort's
# result is defined by the comparison and the input alone, so the build compiles a copy of
# clipper.cpp, made in the build tree, whose two std::sort calls are std::stable_sort; nothing
# else changes. Both builds then run the same algorithm on the same IEEE doubles.
set(DESIA_CLIPPER_SOURCE_DIR ${CMAKE_SOURCE_DIR}/third_party/polyclipping-6.4.2 CACHE PATH "Clipper 6.4.2 source tree")
if(NOT EXISTS ${DESIA_CLIPPER_SOURCE_DIR}/cpp/clipper.cpp)
  message(FATAL_ERROR "Clipper sources not found in ${DESIA_CLIPPER_SOURCE_DIR}: run scripts/setup.sh first")
endif()
set(clipper_original ${DESIA_CLIPPER_SOURCE_DIR}/cpp/clipper.cpp)
set(clipper_stable ${CMAKE_BINARY_DIR}/clipper-stable/clipper.cpp)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${clipper_original})
file(READ ${clipper_original} clipper_text)
string(REGEX MATCHALL "std::sort\\(" clipper_sorts "${clipper_text}")
list(LENGTH clipper_sorts clipper_sort_count)
if(NOT clipper_sort_count EQUAL 2)
  message(FATAL_ERROR "${clipper_original}: expected Clipper 6.4.2's two std::sort calls, found ${clipper_sort_count}")
endif()
string(REPLACE "std::sort(" "std::stable_sort(" clipper_text "${clipper_text}")
file(WRITE ${clipper_stable}.new "${clipper_text}")
configure_file(${clipper_stable}.new ${clipper_stable} COPYONLY)  # rewritten only when it changes
# The core includes <polyclipping/clipper.hpp> as Debian installs it: a folder that holds only
# that name (it also keeps the host's /usr/include away from Emscripten, toolchain.md item 2).
set(clipper_include_dir ${CMAKE_BINARY_DIR}/clipper-include)
file(MAKE_DIRECTORY ${clipper_include_dir})
file(CREATE_LINK ${DESIA_CLIPPER_SOURCE_DIR}/cpp ${clipper_include_dir}/polyclipping SYMBOLIC)
add_library(desia_clipper STATIC ${clipper_stable})
target_include_directories(desia_clipper BEFORE PUBLIC ${clipper_include_dir} PRIVATE ${DESIA_CLIPPER_SOURCE_DIR}/cpp)
target_compile_options(desia_clipper PRIVATE -w -O2 -ffp-contract=off)
if(EMSCRIPTEN)
  target_compile_options(desia_clipper PRIVATE -fwasm-exceptions)
endif()
