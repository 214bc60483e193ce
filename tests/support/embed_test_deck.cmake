# Writes a Fortran module holding a deck's card images for the tests, as
# cmake/embed_deck.cmake does for the built-in default deck, under the
# module name NAME_deck and the function NAME_deck_lines:
#   cmake -DEMBED=cmake/embed_deck.cmake -DDECK=decks/body_only.deck -DNAME=body_only
#         -DOUT=body_only_deck.f90 -P embed_test_deck.cmake
cmake_policy(SET CMP0011 NEW)
set(target ${OUT})
set(OUT ${target}.default)
include(${EMBED})
file(READ ${OUT} text)
string(REPLACE "module default_deck" "module ${NAME}_deck" text "${text}")
string(REPLACE "default_deck_lines" "${NAME}_deck_lines" text "${text}")
string(REPLACE "the built-in default deck" "the deck ${NAME} (for the tests)" text "${text}")
file(WRITE ${target}.tmp "${text}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${target}.tmp ${target})
