# SPDX-License-Identifier: GPL-3.0-or-later
# zlib 1.2.13 (inflate, for the ZIP container of 3MF files) compiled from Debian's source package
# for WebAssembly, as GLPK and Clipper are: natively the core links Debian's zlib1g-dev.
# scripts/setup.sh unpacks the sources into third_party/zlib-1.2.13.dfsg. Only what inflate needs
# is compiled (no deflate, no gz* file functions).
set(DESIA_ZLIB_SOURCE_DIR ${CMAKE_SOURCE_DIR}/third_party/zlib-1.2.13.dfsg CACHE PATH "zlib 1.2.13 source tree")
if(NOT EXISTS ${DESIA_ZLIB_SOURCE_DIR}/inflate.c)
  message(FATAL_ERROR "zlib sources not found in ${DESIA_ZLIB_SOURCE_DIR}: run scripts/setup.sh first")
endif()
# The core includes <zlib.h>: a folder that holds only zlib's two headers keeps the host's
# /usr/include away from Emscripten (toolchain.md item 2).
set(zlib_include_dir ${CMAKE_BINARY_DIR}/zlib-include)
file(MAKE_DIRECTORY ${zlib_include_dir})
foreach(header zlib.h zconf.h)
  file(CREATE_LINK ${DESIA_ZLIB_SOURCE_DIR}/${header} ${zlib_include_dir}/${header} SYMBOLIC)
endforeach()
set(zlib_sources "")
foreach(source adler32.c crc32.c inffast.c inflate.c inftrees.c zutil.c)
  list(APPEND zlib_sources ${DESIA_ZLIB_SOURCE_DIR}/${source})
endforeach()
add_library(desia_zlib STATIC ${zlib_sources})
target_include_directories(desia_zlib PUBLIC ${zlib_include_dir} PRIVATE ${DESIA_ZLIB_SOURCE_DIR})
target_compile_options(desia_zlib PRIVATE -w -O2)
