# docs/deck-format.md must be exactly what `hsri2d --deck-format` prints.
execute_process(COMMAND ${EXE} --deck-format RESULT_VARIABLE rc OUTPUT_VARIABLE out)
file(READ ${DOC} doc)
if(NOT rc EQUAL 0 OR NOT out STREQUAL doc)
  message(FATAL_ERROR "docs/deck-format.md differs from `hsri2d --deck-format`; "
                      "regenerate it: hsri2d --deck-format > docs/deck-format.md")
endif()
