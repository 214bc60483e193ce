# Run a shipped deck and compare its listing with the archived one, number
# by number within stated tolerances (tools/listdiff: numdiff, relative
# 1e-6, absolute 1e-9, the version and dates masked). The listings are
# archived from the Debug build the tests use; a Release build reproduces most of them but not all (unbelted_driver,
# lap_belt, free_fall, interior_driver differ in printed last digits:
# docs/validation.md, "Reproducing an archived run"), so compare with the
# Debug build.
# The deck is named relative to its directory so that the listing, which
# names its decks, does not depend on where the source tree lies.
# OVERRIDE (optional): a deck read after DECK (tests/listings/printer_plot.deck), the run made
# in its directory with DECK named relative to it, as tools/regenerate-listings runs it.
file(MAKE_DIRECTORY ${WORK})
if(DEFINED OVERRIDE AND NOT OVERRIDE STREQUAL "")
  get_filename_component(deck_dir ${OVERRIDE} DIRECTORY)
  file(RELATIVE_PATH deck_name ${deck_dir} ${DECK})
  get_filename_component(override_name ${OVERRIDE} NAME)
  set(decks ${deck_name} ${override_name})
else()
  get_filename_component(deck_dir ${DECK} DIRECTORY)
  get_filename_component(deck_name ${DECK} NAME)
  set(decks ${deck_name})
endif()
execute_process(COMMAND ${EXE} ${decks} -o ${WORK}/actual.lst WORKING_DIRECTORY ${deck_dir}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hsri2d ${DECK} failed with status ${rc}:\n${err}")
endif()
# tools/listdiff: numdiff with the project's tolerances, the version and any date masked
execute_process(COMMAND ${CMAKE_COMMAND} -E env NUMDIFF=${NUMDIFF} ${LISTDIFF} ${EXPECTED} ${WORK}/actual.lst
                RESULT_VARIABLE same OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the listing of ${DECK} differs from ${EXPECTED}:\n${out}\n"
                      "If the change is intended: tools/regenerate-listings")
endif()
