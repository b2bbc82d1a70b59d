# FindOpenCVSplit: OpenCV from Debian's split development packages (libopencv-core-dev,
# -imgproc-dev, -imgcodecs-dev, -calib3d-dev, -features2d-dev). Those ship headers and libraries
# but no OpenCVConfig.cmake and no opencv4.pc (both come only with libopencv-dev, which pulls a
# desktop stack), so this module finds them by hand.
#
# find_package(OpenCVSplit REQUIRED COMPONENTS core imgproc imgcodecs ...) provides one imported
# target OpenCV::<component> per component (each carries the include directory; the others
# link OpenCV::core, which is always found), and OpenCVSplit_INCLUDE_DIR.
include(FindPackageHandleStandardArgs)

# Every other module needs core.
list(PREPEND OpenCVSplit_FIND_COMPONENTS core)
list(REMOVE_DUPLICATES OpenCVSplit_FIND_COMPONENTS)
set(OpenCVSplit_FIND_REQUIRED_core TRUE)

find_path(OpenCVSplit_INCLUDE_DIR NAMES opencv2/core.hpp PATH_SUFFIXES opencv4)

set(_opencv_split_required OpenCVSplit_INCLUDE_DIR)
foreach(_component IN LISTS OpenCVSplit_FIND_COMPONENTS)
  find_library(OpenCVSplit_${_component}_LIBRARY NAMES opencv_${_component})
  if(OpenCVSplit_${_component}_LIBRARY)
    set(OpenCVSplit_${_component}_FOUND TRUE)
  endif()
  if(OpenCVSplit_FIND_REQUIRED_${_component})
    list(APPEND _opencv_split_required OpenCVSplit_${_component}_LIBRARY)
  endif()
endforeach()

find_package_handle_standard_args(OpenCVSplit REQUIRED_VARS ${_opencv_split_required} HANDLE_COMPONENTS)

if(OpenCVSplit_FOUND)
  foreach(_component IN LISTS OpenCVSplit_FIND_COMPONENTS)
    if(OpenCVSplit_${_component}_FOUND AND NOT TARGET OpenCV::${_component})
      add_library(OpenCV::${_component} UNKNOWN IMPORTED)
      # Imported include directories are system directories for their users: OpenCV's headers
      # warn under C++20 (-Wdeprecated-enum-enum-conversion), and warnings are errors here.
      set_target_properties(OpenCV::${_component} PROPERTIES
        IMPORTED_LOCATION "${OpenCVSplit_${_component}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${OpenCVSplit_INCLUDE_DIR}")
      if(NOT _component STREQUAL "core")
        set_property(TARGET OpenCV::${_component} APPEND PROPERTY INTERFACE_LINK_LIBRARIES OpenCV::core)
      endif()
    endif()
  endforeach()
endif()
mark_as_advanced(OpenCVSplit_INCLUDE_DIR)
