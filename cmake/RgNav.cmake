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

# rgnav_add_test(<name> SOURCES <files>... [LIBS <libs>...] [LABELS <labels>...])
# A CppUnit test executable registered with CTest; runs with the project root as working dir.
function(rgnav_add_test name)
  if(RGNAV_FUZZ)
    return()  # the fuzz build has no unit tests
  endif()
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE rgnav_testmain ${ARG_LIBS})
  add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  rgnav_test_environment(${name} ${ARG_TIMEOUT})
  if(ARG_LABELS)
    set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
  endif()
endfunction()

# rgnav_test_environment(<test> <timeout_s>): where a test finds the shared data, the built
# programs and the project root, and how long it may run.
function(rgnav_test_environment test timeout)
  if(RGNAV_FUZZ)
    return()
  endif()
  set_tests_properties(${test} PROPERTIES TIMEOUT ${timeout}
    ENVIRONMENT "RGNAV_SHARED=${RGNAV_SHARED_DIR};RGNAV_BIN=${CMAKE_BINARY_DIR}/bin;RGNAV_ROOT=${CMAKE_SOURCE_DIR}")
endfunction()
