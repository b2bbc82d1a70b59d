# Fails if any file under core/ mentions omniORB or CORBA: algorithms stay free of middleware
# (DESIGN.md, layers). Run with: cmake -DCORE_DIR=<dir> -P CheckCoreIsCorbaFree.cmake
file(GLOB_RECURSE files "${CORE_DIR}/*")
set(offenders "")
foreach(f ${files})
  file(STRINGS "${f}" hits REGEX "omniORB|CORBA")
  if(hits)
    list(APPEND offenders "${f}")
  endif()
endforeach()
if(offenders)
  list(JOIN offenders "\n  " text)
  message(FATAL_ERROR "core/ must not mention omniORB or CORBA; found in:\n  ${text}")
endif()
