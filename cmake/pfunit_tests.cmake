# Test programs written as pFUnit test modules (.pf files).
#
#   hsri2d_add_pf_test(NAME <name> SOURCES <file.pf>...
#                      [LINK <target>...] [LABELS <label>...]
#                      [WORKING_DIRECTORY <dir>])
#
# builds the executable <name> from the .pf files (one module per file, named
# after it), links it with the LINK targets and registers the CTest test
# <name>, run in WORKING_DIRECTORY (default: the current binary directory).
#
# With a pFUnit that find_package(PFUNIT) finds (for instance with
# -DCMAKE_PREFIX_PATH=/path/to/pfunit/installed), pFUnit's own
# add_pfunit_ctest builds the tests. Otherwise the same .pf files go through
# the stand-in tools/pfunit_lite/pfproc.py and link funit_lite, built from
# tests/funit_lite/funit.F90 (see tests/funit_lite/README.md).
#
# -DHSRI2D_REQUIRE_PFUNIT=ON makes a missing pFUnit an error instead (CI's
# third build tree: it must never fall back to the stand-in unnoticed).
#
# The project's flags (hsri2d_set_flags, compilers.cmake) apply when defined.
include_guard(DIRECTORY)

option(HSRI2D_REQUIRE_PFUNIT "Fail when pFUnit is not found instead of using the pfunit_lite stand-in" OFF)
if(HSRI2D_REQUIRE_PFUNIT)
  find_package(PFUNIT REQUIRED)
else()
  find_package(PFUNIT QUIET)
endif()
if(PFUNIT_FOUND)
  message(STATUS "Tests: pFUnit ${PFUNIT_VERSION} found, the .pf tests use it")
else()
  message(STATUS "Tests: pFUnit not found, the .pf tests use the pfunit_lite stand-in")
  find_package(Python3 COMPONENTS Interpreter REQUIRED)
endif()

cmake_path(SET HSRI2D_PFPROC NORMALIZE "${CMAKE_CURRENT_LIST_DIR}/../tools/pfunit_lite/pfproc.py")
cmake_path(SET HSRI2D_FUNIT_LITE_SOURCE NORMALIZE "${CMAKE_CURRENT_LIST_DIR}/../tests/funit_lite/funit.F90")

function(hsri2d_add_pf_test)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;WORKING_DIRECTORY" "SOURCES;LINK;LABELS")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_NAME OR NOT arg_SOURCES)
    message(FATAL_ERROR "hsri2d_add_pf_test(NAME <name> SOURCES <file.pf>... [LINK <target>...] "
                        "[LABELS <label>...] [WORKING_DIRECTORY <dir>]), got: ${ARGV}")
  endif()
  set(workdir "${CMAKE_CURRENT_BINARY_DIR}")
  if(arg_WORKING_DIRECTORY)
    set(workdir "${arg_WORKING_DIRECTORY}")
  endif()

  foreach(source IN LISTS arg_SOURCES)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
    set_property(GLOBAL APPEND PROPERTY HSRI2D_PF_SOURCES "${source}")
  endforeach()
  if(PFUNIT_FOUND)
    _hsri2d_pf_test_pfunit(${arg_NAME} "${arg_SOURCES}" "${arg_LINK}")
  else()
    _hsri2d_pf_test_lite(${arg_NAME} "${arg_SOURCES}" "${arg_LINK}")
  endif()
  # Set here rather than passed to add_pfunit_ctest: older pFUnit versions
  # know neither LABELS nor WORKING_DIRECTORY.
  set_tests_properties(${arg_NAME} PROPERTIES
    LABELS "${arg_LABELS}" WORKING_DIRECTORY "${workdir}")
endfunction()

# Every .pf file under `directory` must belong to a test program (so that
# none is left out of either build), except those under the `EXCEPT` folders.
function(hsri2d_check_pf_registered directory)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "EXCEPT")
  file(GLOB_RECURSE found CONFIGURE_DEPENDS "${directory}/*.pf")
  get_property(registered GLOBAL PROPERTY HSRI2D_PF_SOURCES)
  set(missing)
  foreach(file IN LISTS found)
    set(excepted FALSE)
    foreach(folder IN LISTS arg_EXCEPT)
      cmake_path(IS_PREFIX folder "${file}" NORMALIZE excepted)
      if(excepted)
        break()
      endif()
    endforeach()
    if(NOT excepted AND NOT file IN_LIST registered)
      list(APPEND missing "${file}")
    endif()
  endforeach()
  if(missing)
    list(JOIN missing "\n  " missing)
    message(FATAL_ERROR "These .pf files are in no test program (hsri2d_add_pf_test):\n  ${missing}")
  endif()
endfunction()

# Real pFUnit. The project's flags go on the sources made from the .pf files
# only: pFUnit's generated driver calls procedures without explicit
# interfaces, which -Wimplicit-interface would turn into errors.
function(_hsri2d_pf_test_pfunit name sources links)
  set(relative_sources)
  set(generated)
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
    cmake_path(RELATIVE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
               OUTPUT_VARIABLE relative)
    list(APPEND relative_sources "${relative}")
    # Where add_pfunit_sources writes the preprocessed file.
    cmake_path(REPLACE_EXTENSION relative LAST_ONLY ".F90" OUTPUT_VARIABLE f90)
    list(APPEND generated "${CMAKE_CURRENT_BINARY_DIR}/${f90}")
  endforeach()
  add_pfunit_ctest(${name} TEST_SOURCES ${relative_sources} LINK_LIBRARIES ${links})
  if(DEFINED HSRI2D_FORTRAN_FLAGS)
    set_source_files_properties(${generated} PROPERTIES COMPILE_OPTIONS "${HSRI2D_FORTRAN_FLAGS}")
  endif()
endfunction()

# Stand-in: pfproc.py writes one module per .pf file and a driver program.
function(_hsri2d_pf_test_lite name sources links)
  _hsri2d_funit_lite_library()
  set(gendir "${CMAKE_CURRENT_BINARY_DIR}/pfunit_lite/${name}")
  file(MAKE_DIRECTORY "${gendir}")
  set(pf_files)
  set(generated)
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
    cmake_path(GET source STEM stem)
    set(f90 "${gendir}/${stem}.F90")
    add_custom_command(
      OUTPUT "${f90}"
      COMMAND "${Python3_EXECUTABLE}" "${HSRI2D_PFPROC}" module "${source}" "${f90}"
      DEPENDS "${source}" "${HSRI2D_PFPROC}"
      COMMENT "pfunit_lite: preprocessing ${stem}.pf"
      VERBATIM)
    list(APPEND pf_files "${source}")
    list(APPEND generated "${f90}")
  endforeach()

  set(driver "${gendir}/${name}_driver.F90")
  add_custom_command(
    OUTPUT "${driver}"
    COMMAND "${Python3_EXECUTABLE}" "${HSRI2D_PFPROC}" driver "${driver}" ${pf_files}
    DEPENDS ${pf_files} "${HSRI2D_PFPROC}"
    COMMENT "pfunit_lite: writing the driver of ${name}"
    VERBATIM)

  add_executable(${name} ${generated} "${driver}")
  # Own module directory: two test programs may define modules of one name.
  set_target_properties(${name} PROPERTIES
    Fortran_MODULE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/mod/${name}")
  target_link_libraries(${name} PRIVATE funit_lite ${links})
  if(COMMAND hsri2d_set_flags)
    hsri2d_set_flags(${name})
  endif()
  add_test(NAME ${name} COMMAND ${name})
endfunction()

# The stand-in funit module, built once for all test programs.
function(_hsri2d_funit_lite_library)
  if(NOT TARGET funit_lite)
    add_library(funit_lite STATIC "${HSRI2D_FUNIT_LITE_SOURCE}")
    set(moddir "${CMAKE_BINARY_DIR}/mod/funit_lite")
    set_target_properties(funit_lite PROPERTIES Fortran_MODULE_DIRECTORY "${moddir}")
    target_include_directories(funit_lite PUBLIC "${moddir}")
    if(COMMAND hsri2d_set_flags)
      hsri2d_set_flags(funit_lite)
    endif()
  endif()
endfunction()
