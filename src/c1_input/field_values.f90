!> One field's text checked and converted against its specification in the
!! card table: syntax, valid range, deck unit to internal unit. Used for
!! every source of field values that is not a card image (the CSV pulse
!! file), so that a value means the same and is checked the same wherever
!! it comes from.
module field_values
   use kinds, only: wp
   use strings, only: itoa, num, upper, read_real, read_int
   use deck_cards, only: field_spec_t, kind_real, kind_int, kind_word, kind_text
   implicit none
   private

   public :: convert_field_text, field_expectation, word_position

contains

   !> Convert the (non-blank, trimmed) text of field f; ok false when it is
   !! not valid, and expected then says what the field accepts.
   subroutine convert_field_text(f, raw, x, ok, expected)
      type(field_spec_t), intent(in) :: f
      character(len=*), intent(in) :: raw
      real(wp), intent(out) :: x
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: expected
      integer :: n
      expected = field_expectation(f)
      x = 0.0_wp
      select case (f%kind)
      case (kind_int)
         call read_int(raw, n, ok)
         if (ok) ok = .not. (real(n, wp) < f%low .or. real(n, wp) > f%high)
         if (ok) x = real(n, wp)
      case (kind_real)
         call read_real(raw, x, ok)
         if (ok) ok = .not. (x < f%low .or. x > f%high .or. (f%low_open .and. .not. x > f%low))
         if (ok) then
            x = x*f%scale
         else
            x = 0.0_wp
         end if
      case (kind_word)
         n = word_position(f%words, upper(raw))
         ok = n > 0
         x = real(n, wp)
      case default
         ok = .true.
      end select
   end subroutine convert_field_text

   !> What a field accepts, in words, for error messages.
   function field_expectation(f) result(s)
      type(field_spec_t), intent(in) :: f
      character(len=:), allocatable :: s
      character(len=:), allocatable :: unit
      unit = ''
      if (f%unit /= '-' .and. f%unit /= ' ') unit = ' ('//trim(f%unit)//')'
      select case (f%kind)
      case (kind_text)
         s = 'text'
      case (kind_word)
         s = 'one of '//trim(f%words)
      case (kind_int)
         s = 'an integer from '//itoa(nint(f%low))//' to '//itoa(nint(f%high))
      case default
         if (f%low > -huge(1.0_wp) .and. f%high < huge(1.0_wp)) then
            if (f%low_open) then
               s = 'a number > '//num(f%low)//' and <= '//num(f%high)//unit
            else
               s = 'a number from '//num(f%low)//' to '//num(f%high)//unit
            end if
         else if (f%low > -huge(1.0_wp)) then
            if (f%low_open) then
               s = 'a number > '//num(f%low)//unit
            else
               s = 'a number >= '//num(f%low)//unit
            end if
         else
            s = 'a number'//unit
         end if
      end select
   end function field_expectation

   !> Position of word w in the '|'-separated list, or 0.
   pure integer function word_position(list, w)
      character(len=*), intent(in) :: list, w
      integer :: start, k, bar
      word_position = 0
      start = 1
      k = 0
      do
         k = k + 1
         bar = index(list(start:), '|')
         if (bar == 0) then
            if (trim(list(start:)) == w) word_position = k
            return
         end if
         if (list(start:start + bar - 2) == w) then
            word_position = k
            return
         end if
         start = start + bar
      end do
   end function word_position
end module field_values
