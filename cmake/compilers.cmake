# Compiler flags per build type (gfortran). Release is for use; Debug, with
# run-time checks and floating-point traps, is what the test suite runs on.
if(NOT CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  message(WARNING "hsri2d is developed with gfortran; flags for "
                  "${CMAKE_Fortran_COMPILER_ID} are left at their defaults.")
  return()
endif()

set(HSRI2D_FORTRAN_FLAGS
  -std=f2008 -fimplicit-none -ffree-line-length-132
  -Wall -Wextra -Wimplicit-interface -Wno-maybe-uninitialized
  $<$<CONFIG:Debug>:-O0 -g -fcheck=all -fbacktrace
                    -ffpe-trap=invalid,zero,overflow -finit-real=snan
                    -finit-integer=-99999999 -finit-derived>
  $<$<CONFIG:Release>:-O2 -funroll-loops>
  $<$<BOOL:${HSRI2D_WERROR}>:-Werror>)

# Release links with link-time optimization: the kernels of C.4-C.5 live in
# modules of their own (one concept per module) and call each other across
# them in the hottest loops (a body point's joint chain, a loading curve's
# branch); only the link can inline those calls. Same results bit for bit
# (no reassociation is allowed), some 15 % less CPU for the interior decks
# (docs/performance.md).
option(HSRI2D_LTO "Link-time optimization for Release builds" ON)
if(HSRI2D_LTO AND (CMAKE_BUILD_TYPE STREQUAL "Release" OR CMAKE_CONFIGURATION_TYPES))
  include(CheckIPOSupported)
  check_ipo_supported(RESULT hsri2d_ipo_ok OUTPUT hsri2d_ipo_why LANGUAGES Fortran C)
  if(hsri2d_ipo_ok)
    set(CMAKE_INTERPROCEDURAL_OPTIMIZATION_RELEASE ON)
  else()
    message(STATUS "hsri2d: no link-time optimization: ${hsri2d_ipo_why}")
  endif()
endif()

# Applied to a target's own sources only (not to generated or third-party code).
function(hsri2d_set_flags target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:Fortran>:${HSRI2D_FORTRAN_FLAGS}>)
endfunction()
