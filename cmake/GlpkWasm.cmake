# SPDX-License-Identifier: GPL-3.0-or-later
# GLPK 5.0 compiled from Debian's source package for WebAssembly (the host libglpk cannot be
# linked into wasm). scripts/setup.sh unpacks the sources into third_party/glpk-5.0. The library
# lives in the build tree, so it is compiled once per build folder (about 35 s on 2 cores).
set(DESIA_GLPK_SOURCE_DIR ${CMAKE_SOURCE_DIR}/third_party/glpk-5.0 CACHE PATH "GLPK 5.0 source tree")
if(NOT EXISTS ${DESIA_GLPK_SOURCE_DIR}/src/Makefile.am)
  message(FATAL_ERROR "GLPK sources not found in ${DESIA_GLPK_SOURCE_DIR}: run scripts/setup.sh first")
endif()

# The library's files are exactly those listed in src/Makefile.am (libglpk_la_SOURCES); this
# leaves out src/proxy/main.c, a stand-alone program.
file(STRINGS ${DESIA_GLPK_SOURCE_DIR}/src/Makefile.am glpk_makefile_lines)
set(glpk_relative_sources "")
set(in_sources_block FALSE)
foreach(line IN LISTS glpk_makefile_lines)
  if(line MATCHES "^libglpk_la_SOURCES[ \t]*=")
    set(in_sources_block TRUE)
    string(REGEX REPLACE "^libglpk_la_SOURCES[ \t]*=" "" line "${line}")
  elseif(NOT in_sources_block)
    continue()
  endif()
  set(continues FALSE)
  if(line MATCHES "\\\\[ \t]*$")
    set(continues TRUE)
    string(REGEX REPLACE "\\\\[ \t]*$" "" line "${line}")
  endif()
  separate_arguments(words UNIX_COMMAND "${line}")
  list(APPEND glpk_relative_sources ${words})
  if(NOT continues)
    break()
  endif()
endforeach()
set(glpk_sources "")
foreach(source IN LISTS glpk_relative_sources)
  list(APPEND glpk_sources ${DESIA_GLPK_SOURCE_DIR}/src/${source})
endforeach()
list(LENGTH glpk_sources glpk_source_count)
if(glpk_source_count LESS 100)
  message(FATAL_ERROR "could not read GLPK's source list from src/Makefile.am (found ${glpk_source_count} files)")
endif()

file(GLOB glpk_include_dirs LIST_DIRECTORIES true ${DESIA_GLPK_SOURCE_DIR}/src/*)
list(FILTER glpk_include_dirs EXCLUDE REGEX "\\.(am|in|h)$")
set(glpk_config_dir ${CMAKE_BINARY_DIR}/glpk-config)
# file(CONFIGURE) writes only when the content changes, so reconfiguring does not rebuild GLPK.
file(CONFIGURE OUTPUT ${glpk_config_dir}/config.h CONTENT "/* GLPK configuration for WebAssembly: no optional features. */\n")

add_library(desia_glpk STATIC ${glpk_sources})
target_include_directories(desia_glpk PRIVATE ${glpk_config_dir} ${DESIA_GLPK_SOURCE_DIR}/src ${glpk_include_dirs})
target_include_directories(desia_glpk INTERFACE ${DESIA_GLPK_SOURCE_DIR}/src)
target_compile_definitions(desia_glpk PRIVATE HAVE_CONFIG_H)
target_compile_options(desia_glpk PRIVATE -w -O2 -ffp-contract=off)
