# Build helpers shared by every folder: IDL stub libraries and CppUnit tests.

# rgnav_idl_library(<name> <file.idl> [DEPENDS <idl libs>...])
# Runs omniidl on idl/<file.idl> and builds the stubs into a static library <name>.
function(rgnav_idl_library name idlfile)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  get_filename_component(base ${idlfile} NAME_WE)
  set(outdir ${CMAKE_BINARY_DIR}/idl)
  set(src ${outdir}/${base}SK.cc)
  set(hdr ${outdir}/${base}.hh)
  add_custom_command(
    OUTPUT ${src} ${hdr}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${outdir}
    COMMAND omniidl -bcxx -Wbh=.hh -Wbs=SK.cc -I${CMAKE_SOURCE_DIR}/idl -C${outdir}
            ${CMAKE_SOURCE_DIR}/idl/${idlfile}
    DEPENDS ${CMAKE_SOURCE_DIR}/idl/${idlfile}
    COMMENT "omniidl ${idlfile}")
  add_library(${name} STATIC ${src})
  # Generated stubs are not ours to keep warning-free.
  target_compile_options(${name} PRIVATE -w)
  target_include_directories(${name} PUBLIC ${outdir})
  target_link_libraries(${name} PUBLIC PkgConfig::OMNIORB ${ARG_DEPENDS})
endfunction()

# Every test carries exactly one kind label, so that `rgctl test -L <kind>` runs one kind:
#   unit         one process, no servers, no large data (seconds)
#   integration  starts servers (omniNames, watchdog, modules) on free loopback ports
#   fault        kills and stops servers while they work (minutes)
#   eval         an evaluation program on real data, its figures checked against floors
#   bench        a benchmark program in a smoke run, its figures checked against floors
set(RGNAV_TEST_KINDS unit integration fault eval bench)

# rgnav_require_test_kind(<test> <labels>): a configure error unless exactly one kind is given.
function(rgnav_require_test_kind test labels)
  set(kinds "")
  foreach(label IN LISTS labels)
    if(label IN_LIST RGNAV_TEST_KINDS)
      list(APPEND kinds ${label})
    endif()
  endforeach()
  list(LENGTH kinds count)
  if(NOT count EQUAL 1)
    string(REPLACE ";" "|" choices "${RGNAV_TEST_KINDS}")
    message(FATAL_ERROR "test ${test} has the labels '${labels}': give it exactly one of ${choices}, e.g.\n"
      "  rgnav_add_test(${test} SOURCES ... LABELS unit)\n"
      "  rgnav_add_program_test(${test} LABELS eval MIN <key>=<floor> COMMAND <program> ...)\n"
      "(unit: one process, no servers; integration: starts servers; fault: kills servers; eval/bench: "
      "an evaluation or benchmark program whose figures are checked; see cmake/RgNav.cmake)")
  endif()
endfunction()

# rgnav_add_test(<name> SOURCES <files>... [LIBS <libs>...] LABELS <kind> [<labels>...] [TIMEOUT <s>])
# A CppUnit test executable registered with CTest; runs with the project root as working dir.
function(rgnav_add_test name)
  if(RGNAV_FUZZ)
    return()  # the fuzz build has no unit tests
  endif()
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  rgnav_require_test_kind(${name} "${ARG_LABELS}")
  add_executable(${name} ${ARG_SOURCES})
  set_property(TARGET ${name} PROPERTY RGNAV_TEST_CODE TRUE)
  target_link_libraries(${name} PRIVATE rgnav_testmain ${ARG_LIBS})
  add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  rgnav_test_environment(${name} ${ARG_TIMEOUT})
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
endfunction()

# rgnav_add_program_test(<name> LABELS <kind> [<labels>...] [TIMEOUT <s>] [MIN <key>=<floor>...]
#                        [MAX <key>=<ceiling>...] COMMAND <program or target> [<args>...])
# A program run as a test from the project root. With MIN/MAX it runs under
# tests/support/check_figures.py: it passes only if the program succeeds and the last line that
# prints each key has a value at least its floor (MIN) or at most its ceiling (MAX).
function(rgnav_add_program_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "LABELS;MIN;MAX;COMMAND" ${ARGN})
  rgnav_require_test_kind(${name} "${ARG_LABELS}")
  list(POP_FRONT ARG_COMMAND program)
  if(TARGET ${program})
    set(program $<TARGET_FILE:${program}>)
  endif()
  set(checks "")
  foreach(bound IN LISTS ARG_MIN)
    list(APPEND checks --min ${bound})
  endforeach()
  foreach(bound IN LISTS ARG_MAX)
    list(APPEND checks --max ${bound})
  endforeach()
  if(checks)
    set(program ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/support/check_figures.py ${checks} -- ${program})
  endif()
  add_test(NAME ${name} COMMAND ${program} ${ARG_COMMAND} WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  rgnav_test_environment(${name} ${ARG_TIMEOUT})
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
endfunction()

# rgnav_test_environment(<test> <timeout_s>): where a test finds the shared data, the built
# programs and the project root, and how long it may run.
function(rgnav_test_environment test timeout)
  if(RGNAV_FUZZ)
    return()
  endif()
  set_tests_properties(${test} PROPERTIES TIMEOUT ${timeout}
    ENVIRONMENT "RGNAV_SHARED=${RGNAV_SHARED_DIR};RGNAV_BIN=${CMAKE_BINARY_DIR}/bin;RGNAV_ROOT=${CMAKE_SOURCE_DIR};RGNAV_BUILT=1")
endfunction()
