# probe.cmake: adds the target `cs184_probe` to a student's CS184 PathTracer
# tree, without changing a file of it.
#
#   cmake -S STUDENT -B BUILD -DCMAKE_PROJECT_INCLUDE=/path/probe.cmake \
#         -DCS184_PROBE_DRIVER=/path/driver.cpp <the course's flags>
#   cmake --build BUILD --target cs184_probe
#
# CMake includes this file after every project() call. It acts once, for the
# top-level project only: it defers (CMake 3.19+) a call to the end of the
# top-level CMakeLists.txt, when the student's `pathtracer` target is complete,
# and there adds an executable `cs184_probe` built from the driver plus every
# source of `pathtracer` except src/application/main.cpp (the driver has its
# own main), with `pathtracer`'s link libraries, link directories, include
# directories, compile definitions and options. Its build rpath is $ORIGIN
# plus the link directories, so a precompiled library the tree links from a
# folder of its own (the 3-2 starter's libs/x64_linux/libpt31.so) is found
# where it is, without copying it.

if(CMAKE_VERSION VERSION_LESS 3.19)
  message(FATAL_ERROR "cs184 probe: needs CMake 3.19 or newer (cmake_language DEFER).")
endif()

# Only the top-level project, and only once even if it calls project() twice.
if(NOT CMAKE_CURRENT_SOURCE_DIR STREQUAL CMAKE_SOURCE_DIR)
  return()
endif()
get_property(_cs184_probe_deferred GLOBAL PROPERTY CS184_PROBE_DEFERRED)
if(_cs184_probe_deferred)
  return()
endif()
set_property(GLOBAL PROPERTY CS184_PROBE_DEFERRED TRUE)

function(cs184_probe_add_target)
  if(NOT TARGET pathtracer)
    message(FATAL_ERROR
      "cs184 probe: this tree's CMakeLists.txt defines no target named "
      "`pathtracer` (the course's executable), so there is nothing to build "
      "the probe from.")
  endif()
  if(NOT CS184_PROBE_DRIVER OR NOT EXISTS "${CS184_PROBE_DRIVER}")
    message(FATAL_ERROR
      "cs184 probe: CS184_PROBE_DRIVER must name the driver's source file "
      "(got `${CS184_PROBE_DRIVER}`).")
  endif()

  get_target_property(src_dir pathtracer SOURCE_DIR)
  get_target_property(bin_dir pathtracer BINARY_DIR)

  # The sources, made absolute against the directory that defined the target
  # (the deferred call runs in the top-level directory, which may differ).
  get_target_property(sources pathtracer SOURCES)
  set(probe_sources "${CS184_PROBE_DRIVER}")
  foreach(s IN LISTS sources)
    if(s MATCHES "(^|/)src/application/main\\.cpp$")
      continue()
    endif()
    if(NOT IS_ABSOLUTE "${s}" AND NOT s MATCHES "^\\$<")
      if(EXISTS "${src_dir}/${s}")
        set(s "${src_dir}/${s}")
      else()
        set(s "${bin_dir}/${s}")
      endif()
    endif()
    list(APPEND probe_sources "${s}")
  endforeach()

  add_executable(cs184_probe ${probe_sources})

  foreach(prop LINK_LIBRARIES LINK_DIRECTORIES INCLUDE_DIRECTORIES
               COMPILE_DEFINITIONS COMPILE_OPTIONS)
    get_target_property(value pathtracer ${prop})
    if(value)
      set_property(TARGET cs184_probe PROPERTY ${prop} "${value}")
    endif()
  endforeach()

  # $ORIGIN, then every link directory (absolute).
  set(rpath "$ORIGIN")
  get_target_property(link_dirs pathtracer LINK_DIRECTORIES)
  if(link_dirs)
    foreach(d IN LISTS link_dirs)
      if(d MATCHES "^\\$<")
        continue()
      endif()
      if(NOT IS_ABSOLUTE "${d}")
        set(d "${src_dir}/${d}")
      endif()
      list(APPEND rpath "${d}")
    endforeach()
  endif()
  set_property(TARGET cs184_probe PROPERTY BUILD_RPATH "${rpath}")

  message(STATUS "cs184 probe: target cs184_probe added "
                 "(driver ${CS184_PROBE_DRIVER}, rpath ${rpath})")
endfunction()

cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}"
               CALL cs184_probe_add_target)
