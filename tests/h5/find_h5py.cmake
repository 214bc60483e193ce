# HSRI2D_H5PY_PYTHON: a Python interpreter that can import h5py, for the
# tests that read HDF5 files with it (labelled python). The interpreter
# find_package(Python3) found may lack h5py (a pyenv, for instance) while
# the system's has it (Debian: python3-h5py); empty when none has it.
include_guard(GLOBAL)
# hsri2d_find_python(VAR MODULES DOC): VAR (a cache entry) set to the first of
# the Python found by find_package and the system's that imports MODULES
# (a comma-separated list), unless it is set already.
function(hsri2d_find_python var modules doc)
  set(${var} "" CACHE FILEPATH "${doc}")
  if(${var})
    return()
  endif()
  foreach(candidate IN ITEMS "${Python3_EXECUTABLE}" /usr/bin/python3)
    if(candidate AND EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import ${modules}"
                      RESULT_VARIABLE missing OUTPUT_QUIET ERROR_QUIET)
      if(missing EQUAL 0)
        set(${var} "${candidate}" CACHE FILEPATH "${doc}" FORCE)
        return()
      endif()
    endif()
  endforeach()
endfunction()

hsri2d_find_python(HSRI2D_H5PY_PYTHON "h5py" "Python interpreter with h5py (found when empty)")
if(HSRI2D_H5PY_PYTHON)
  message(STATUS "Tests: h5py found with ${HSRI2D_H5PY_PYTHON}")
else()
  message(STATUS "Tests: no Python with h5py (Debian: python3-h5py); the h5py tests are skipped")
endif()

# hsri2d_add_h5py_test(NAME name SCRIPT file ARGS ...): the test, or, without
# h5py, a test that reports itself skipped (status 77).
function(hsri2d_add_h5py_test)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;SCRIPT" "ARGS;LABELS")
  if(HSRI2D_H5PY_PYTHON)
    add_test(NAME ${arg_NAME} COMMAND "${HSRI2D_H5PY_PYTHON}" "${arg_SCRIPT}" ${arg_ARGS})
  else()
    add_test(NAME ${arg_NAME} COMMAND ${CMAKE_COMMAND} -E echo "h5py not found (Debian: python3-h5py): skipped")
    set_tests_properties(${arg_NAME} PROPERTIES DISABLED TRUE)
  endif()
  set_tests_properties(${arg_NAME} PROPERTIES LABELS "python;${arg_LABELS}" TIMEOUT 120)
endfunction()

# HSRI2D_PLOT_PYTHON: an interpreter that can import h5py and matplotlib, for
# tools/plot's tests (issue 18). tools/setup installs python3-matplotlib, so a
# machine without it fails those tests, saying what to install.
hsri2d_find_python(HSRI2D_PLOT_PYTHON "h5py, matplotlib, numpy"
                   "Python interpreter with h5py and matplotlib (found when empty)")

# hsri2d_add_plot_test(NAME name SCRIPT file ARGS ...): a test run by that interpreter,
# or one that fails saying python3-matplotlib is missing.
function(hsri2d_add_plot_test)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;SCRIPT" "ARGS;LABELS")
  if(HSRI2D_PLOT_PYTHON)
    add_test(NAME ${arg_NAME} COMMAND "${HSRI2D_PLOT_PYTHON}" "${arg_SCRIPT}" ${arg_ARGS})
  else()
    add_test(NAME ${arg_NAME} COMMAND ${CMAKE_COMMAND} -E false)
    message(STATUS "Tests: no Python with h5py and matplotlib (Debian: python3-h5py python3-matplotlib; "
                   "tools/setup installs them): ${arg_NAME} will fail")
  endif()
  set_tests_properties(${arg_NAME} PROPERTIES LABELS "python;${arg_LABELS}" TIMEOUT 300)
endfunction()
