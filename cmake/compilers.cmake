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

# Applied to a target's own sources only (not to generated or third-party code).
function(hsri2d_set_flags target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:Fortran>:${HSRI2D_FORTRAN_FLAGS}>)
endfunction()
