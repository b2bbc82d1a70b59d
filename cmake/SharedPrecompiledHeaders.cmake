# rgnav_share_precompiled_headers(): every C++ target of the project compiles with one of two
# precompiled headers: the standard library, Eigen and OpenCV's core and imgproc (products), and
# the same plus CppUnit (tests, RGNAV_TEST_CODE). Parsing those headers is a large part of the
# compile time of a typical file here (with the precompiled header a file takes 25-50 % less
# CPU), so a clean build on a CI machine's two cores stays short as the project grows. The
# precompiled header never holds omniORB: core/ stays free of middleware. Each file still
# includes what it uses (the fuzz build, which has none, compiles the core libraries it needs
# without it). Call at the end of the top-level CMakeLists.txt, once every target exists (after
# LinkGraph.cmake, whose target collection it uses).
set(RGNAV_PCH_HEADERS
  <algorithm> <array> <chrono> <cmath> <cstdint> <functional> <map> <memory> <mutex> <optional>
  <set> <sstream> <string> <unordered_map> <utility> <vector>
  <Eigen/Core> <Eigen/Geometry> <opencv2/core.hpp> <opencv2/imgproc.hpp>)

# The include directories the shared headers need (Eigen's, OpenCV's), without linking anything.
function(_rgnav_pch_include_directories target)
  target_include_directories(${target} SYSTEM PRIVATE
    $<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>
    $<TARGET_PROPERTY:OpenCV::core,INTERFACE_INCLUDE_DIRECTORIES>)
endfunction()

function(rgnav_share_precompiled_headers)
  set(stub ${CMAKE_BINARY_DIR}/precompiled_headers.cpp)
  file(WRITE ${stub} "// The translation unit that precompiles the shared headers.\n")
  add_library(rgnav_pch OBJECT ${stub})
  target_precompile_headers(rgnav_pch PRIVATE ${RGNAV_PCH_HEADERS})
  _rgnav_pch_include_directories(rgnav_pch)
  add_library(rgnav_test_pch OBJECT ${stub})
  target_precompile_headers(rgnav_test_pch PRIVATE ${RGNAV_PCH_HEADERS} <cppunit/extensions/HelperMacros.h>)
  _rgnav_pch_include_directories(rgnav_test_pch)
  target_include_directories(rgnav_test_pch SYSTEM PRIVATE
    $<TARGET_PROPERTY:PkgConfig::CPPUNIT,INTERFACE_INCLUDE_DIRECTORIES>)

  _rgnav_collect_targets(${CMAKE_SOURCE_DIR} targets)
  foreach(t ${targets})
    if(t STREQUAL rgnav_pch OR t STREQUAL rgnav_test_pch)
      continue()
    endif()
    get_target_property(type ${t} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      continue()
    endif()
    get_target_property(is_test ${t} RGNAV_TEST_CODE)
    if(is_test)
      target_precompile_headers(${t} REUSE_FROM rgnav_test_pch)
    else()
      target_precompile_headers(${t} REUSE_FROM rgnav_pch)
    endif()
    _rgnav_pch_include_directories(${t})
  endforeach()
endfunction()
