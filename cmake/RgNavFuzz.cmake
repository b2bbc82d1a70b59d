# The fuzz build (RGNAV_FUZZ=ON, clang): every core library is compiled with coverage
# instrumentation for libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer (any report
# aborts, so libFuzzer records it as a crash); core/ is excluded from `all`, so only the libraries
# the fuzz targets of tests/fuzz link are built.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "RGNAV_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++), not ${CMAKE_CXX_COMPILER_ID}")
endif()
add_compile_options(-g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined
                    -fno-sanitize-recover=all)
add_link_options(-fsanitize=address,undefined)
add_subdirectory(${CMAKE_SOURCE_DIR}/core ${CMAKE_BINARY_DIR}/core EXCLUDE_FROM_ALL)
add_subdirectory(${CMAKE_SOURCE_DIR}/tests/fuzz ${CMAKE_BINARY_DIR}/tests/fuzz)
