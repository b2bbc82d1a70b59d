# Test of CheckNoSimLinks.cmake, so the check cannot pass vacuously: configures a tiny project in
# WORK_DIR with LinkGraph.cmake and RgNav.cmake, in which a server reaches a simulator library
# through a private link of a core library and a client library is linked to the simulator from
# another folder, while a test, a *_testing helper and a tool may link it. The check must fail
# naming both offenders with their chains and nothing else.
# Run with: cmake -DCMAKE_DIR=<project>/cmake -DWORK_DIR=<empty dir> -P CheckNoSimLinks_test.cmake
cmake_minimum_required(VERSION 3.22)
set(src ${WORK_DIR}/src)
file(REMOVE_RECURSE ${WORK_DIR})

function(write path text)
  file(WRITE ${src}/${path} "${text}\n")
endfunction()
foreach(f core/sim/grid.cpp core/nav/nav.cpp core/nav/nav_test.cpp core/nav/helper.cpp servers/x/main.cpp
          clientlibs/client.cpp tools/tool.cpp)
  write(${f} "")
endforeach()
write(CMakeLists.txt "cmake_minimum_required(VERSION 3.22)
project(tiny CXX)
list(APPEND CMAKE_MODULE_PATH ${CMAKE_DIR})
include(RgNav)
include(LinkGraph)
add_subdirectory(core/sim)
add_subdirectory(core/nav)
add_subdirectory(servers/x)
add_subdirectory(clientlibs)
add_subdirectory(tools)
target_link_libraries(rgnav_client PUBLIC rgnav_sim_world)
rgnav_write_link_graph(\${CMAKE_BINARY_DIR}/link_graph.txt)")
write(core/sim/CMakeLists.txt "add_library(rgnav_sim_grid STATIC grid.cpp)
add_library(rgnav_sim_world STATIC grid.cpp)")
write(core/nav/CMakeLists.txt "add_library(rgnav_nav STATIC nav.cpp)
target_link_libraries(rgnav_nav PRIVATE rgnav_sim_grid)
add_library(rgnav_nav_testing STATIC helper.cpp)
target_link_libraries(rgnav_nav_testing PUBLIC rgnav_sim_world)
rgnav_add_test(nav_test SOURCES nav_test.cpp LIBS rgnav_nav_testing LABELS unit)")
write(servers/x/CMakeLists.txt "add_executable(rgnav-x main.cpp)
target_link_libraries(rgnav-x PRIVATE rgnav_nav)")
write(clientlibs/CMakeLists.txt "add_library(rgnav_client STATIC client.cpp)")
write(tools/CMakeLists.txt "add_executable(rgnav-tool tool.cpp)
target_link_libraries(rgnav-tool PRIVATE rgnav_sim_world)")

# Configures the tiny project and runs the check on its graph.
function(check_tiny out_result out_text)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${src} -B ${WORK_DIR}/build
                  RESULT_VARIABLE configured OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT configured EQUAL 0)
    message(FATAL_ERROR "The tiny project does not configure:\n${log}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -DGRAPH=${WORK_DIR}/build/link_graph.txt
                          -P ${CMAKE_DIR}/CheckNoSimLinks.cmake
                  RESULT_VARIABLE result OUTPUT_VARIABLE text ERROR_VARIABLE text)
  string(REGEX REPLACE "[ \n]+" " " text "${text}")
  set(${out_result} ${result} PARENT_SCOPE)
  set(${out_text} "${text}" PARENT_SCOPE)
endfunction()

check_tiny(result text)
if(result EQUAL 0)
  message(FATAL_ERROR "The check passed a project in which a server links the simulator:\n${text}")
endif()
foreach(expected "rgnav-x -> rgnav_nav -> rgnav_sim_grid (servers/x)"
                 "rgnav_nav -> rgnav_sim_grid (core/nav)"
                 "rgnav_client -> rgnav_sim_world (clientlibs)")
  string(FIND "${text}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "The check does not name '${expected}':\n${text}")
  endif()
endforeach()
foreach(allowed nav_test rgnav_nav_testing rgnav-tool)
  string(FIND "${text}" "${allowed}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "The check names '${allowed}', which may link the simulator:\n${text}")
  endif()
endforeach()

message(STATUS "The check names both offenders with their chains")
