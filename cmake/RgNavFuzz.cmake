# The fuzz build (RGNAV_FUZZ=ON, clang): every core library is compiled with coverage
# instrumentation for libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer (any report
# aborts, so libFuzzer records it as a crash); core/ is excluded from `all`, so only the libraries
# the fuzz targets of tests/fuzz link are built.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "RGNAV_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++), not ${CMAKE_CXX_COMPILER_ID}")
endif()
# -O1 with line tables, as libFuzzer's documentation suggests: it builds in half the time of -O3
# (the suite builds this too) and reports still name file and line.
set(CMAKE_CXX_FLAGS_RELEASE "-O1 -DNDEBUG")
add_compile_options(-gline-tables-only -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined
                    -fno-sanitize-recover=all)
add_link_options(-fsanitize=address,undefined)
add_subdirectory(${CMAKE_SOURCE_DIR}/core ${CMAKE_BINARY_DIR}/core EXCLUDE_FROM_ALL)
add_subdirectory(${CMAKE_SOURCE_DIR}/tests/fuzz ${CMAKE_BINARY_DIR}/tests/fuzz)
