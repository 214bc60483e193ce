# Writes a Fortran module holding a deck's card images, so that the default
# deck is built into the program and runs from any directory.
#   cmake -DDECK=decks/default.deck -DOUT=default_deck.f90 -P embed_deck.cmake
cmake_policy(SET CMP0007 NEW)
file(READ "${DECK}" text)
string(REPLACE "\r" "" text "${text}")
# file(STRINGS) would drop blank lines; split by hand, keeping them
string(REPLACE ";" "@SEMICOLON@" text "${text}")
string(REPLACE "\n" ";" lines "${text}")
list(LENGTH lines n)
if(n GREATER 0)
  list(GET lines -1 last)
  if(last STREQUAL "")
    list(REMOVE_AT lines -1)
  endif()
endif()
set(body "")
set(count 0)
foreach(line IN LISTS lines)
  math(EXPR count "${count} + 1")
  string(REPLACE "@SEMICOLON@" ";" line "${line}")
  string(REPLACE "'" "''" line "${line}")
  string(APPEND body "      lines(${count})%s = '${line}'\n")
endforeach()
file(WRITE "${OUT}.tmp"
"!> Generated from ${DECK} by cmake/embed_deck.cmake; do not edit.
module default_deck
   use text_io, only: string_t
   implicit none
   private
   public :: default_deck_lines
contains
   !> The card images of the built-in default deck.
   function default_deck_lines() result(lines)
      type(string_t), allocatable :: lines(:)
      allocate (lines(${count}))
${body}   end function default_deck_lines
end module default_deck
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUT}.tmp" "${OUT}")
file(REMOVE "${OUT}.tmp")
