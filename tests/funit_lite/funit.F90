!> pfunit_lite: a small stand-in for pFUnit's `funit` module, enough for the
!! subset of pFUnit that hsri2d's tests use (tests/funit_lite/README.md).
!! Test modules written for pFUnit `use funit` unchanged; the preprocessor
!! tools/pfunit_lite/pfproc.py turns each @assert line into a call of the
!! generic procedures below followed by `if (anyExceptions()) return`, and
!! writes a driver program that runs the tests through funit_run_test.
!!
!! Names, argument order and keywords follow pFUnit (expected, actual,
!! tolerance, message, location), so that a call that compiles here also
!! compiles there. As in pFUnit, a failed assertion is an exception recorded
!! by `throw`; the driver reports every exception left when a test ends.
module funit
   use, intrinsic :: iso_fortran_env, only: real64, int32, int64, output_unit
   implicit none
   private

   ! Assertions.
   public :: assertTrue, assertFalse, assertEqual, assertNotEqual, assertRelativelyEqual
   public :: assertLessThan, assertLessThanOrEqual, assertGreaterThan, assertGreaterThanOrEqual
   public :: assertExceptionRaised
   ! Exceptions.
   public :: SourceLocation, throw, catch, anyExceptions
   ! Used by the generated driver program only.
   public :: funit_test_proc, funit_run_test, funit_skip_test, funit_finish

   !> Where an assertion stands: the .pf file's name and line (component
   !! names as in pFUnit, for keyword constructors).
   type :: SourceLocation
      character(len=:), allocatable :: fileName
      integer :: lineNumber = 0
   end type SourceLocation

   !> A dummy of this type after `actual` makes later optional arguments
   !! keyword-only, as pFUnit requires for its integer and logical asserts.
   type :: keyword_enforcer
   end type keyword_enforcer

   !> One recorded exception (failed assertion or `throw`).
   type :: exception_t
      character(len=:), allocatable :: message
      character(len=:), allocatable :: file_name   ! '' when thrown without a location
      integer :: line_number = 0
   end type exception_t

   !> Interface of test, @before and @after procedures.
   abstract interface
      subroutine funit_test_proc()
      end subroutine funit_test_proc
   end interface

   ! Operators of the order assertions.
   integer, parameter :: op_lt = 1, op_le = 2, op_gt = 3, op_ge = 4
   character(len=*), parameter :: op_words(4) = [character(len=24) :: &
      'less than', 'less than or equal to', 'greater than', 'greater than or equal to']

   ! Harness state: the exceptions of the running test and the tallies.
   type(exception_t), allocatable :: exceptions(:)
   integer :: tests_run = 0, tests_failed = 0, tests_disabled = 0

   interface assertTrue
      module procedure assert_true_0, assert_true_1
   end interface assertTrue

   interface assertFalse
      module procedure assert_false_0, assert_false_1
   end interface assertFalse

   interface assertEqual
      module procedure equal_i_00, equal_i_01, equal_i_11, equal_i_02, equal_i_22
      module procedure equal_i8_00, equal_i8_01, equal_i8_11, equal_i48_00, equal_i48_01, equal_i48_11
      module procedure equal_r_00, equal_r_01, equal_r_11, equal_r_02, equal_r_22
      module procedure equal_r_00_tol, equal_r_01_tol, equal_r_11_tol, equal_r_02_tol, equal_r_22_tol
      module procedure equal_l_00, equal_l_11, equal_string
   end interface assertEqual

   interface assertNotEqual
      module procedure not_equal_i_00, not_equal_i_11, not_equal_i8_00, not_equal_i8_11
      module procedure not_equal_r_00, not_equal_r_11, not_equal_r_00_tol, not_equal_r_11_tol
   end interface assertNotEqual

   interface assertRelativelyEqual
      module procedure rel_equal_00, rel_equal_01, rel_equal_11, rel_equal_02, rel_equal_22
   end interface assertRelativelyEqual

   interface assertLessThan
      module procedure less_than_i_00, less_than_i_11, less_than_i8_00, less_than_i8_11
      module procedure less_than_r_00, less_than_r_11
   end interface assertLessThan

   interface assertLessThanOrEqual
      module procedure less_equal_i_00, less_equal_i_11, less_equal_i8_00, less_equal_i8_11
      module procedure less_equal_r_00, less_equal_r_11
   end interface assertLessThanOrEqual

   interface assertGreaterThan
      module procedure greater_than_i_00, greater_than_i_11, greater_than_i8_00, greater_than_i8_11
      module procedure greater_than_r_00, greater_than_r_11
   end interface assertGreaterThan

   interface assertGreaterThanOrEqual
      module procedure greater_equal_i_00, greater_equal_i_11, greater_equal_i8_00, greater_equal_i8_11
      module procedure greater_equal_r_00, greater_equal_r_11
   end interface assertGreaterThanOrEqual

   interface assertExceptionRaised
      module procedure exception_raised_any, exception_raised_message
   end interface assertExceptionRaised

   interface catch
      module procedure catch_any, catch_message
   end interface catch

   interface istr
      module procedure istr_32, istr_64
   end interface istr

contains

   ! ---------------------------------------------------------------------
   ! Exceptions
   ! ---------------------------------------------------------------------

   !> Record an exception; the test stops at its next assertion.
   subroutine throw(message, location)
      character(len=*), intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      type(exception_t), allocatable :: grown(:)
      integer :: n

      n = exception_count()
      allocate(grown(n + 1))
      if (n > 0) grown(1:n) = exceptions
      grown(n + 1)%message = message
      grown(n + 1)%file_name = ''
      if (present(location)) then
         if (allocated(location%fileName)) grown(n + 1)%file_name = location%fileName
         grown(n + 1)%line_number = location%lineNumber
      end if
      call move_alloc(grown, exceptions)
   end subroutine throw

   !> True while an exception is pending (every assertion is followed by
   !! `if (anyExceptions()) return`).
   logical function anyExceptions()
      anyExceptions = exception_count() > 0
   end function anyExceptions

   !> Remove the most recent exception, if any; true if there was one.
   logical function catch_any(preserve) result(found)
      logical, optional, intent(in) :: preserve
      integer :: n

      n = exception_count()
      found = n > 0
      if (found .and. .not. keep(preserve)) call remove_exception(n)
   end function catch_any

   !> Remove the first exception whose message is `message`; true if found.
   logical function catch_message(message, preserve) result(found)
      character(len=*), intent(in) :: message
      logical, optional, intent(in) :: preserve
      integer :: i

      found = .false.
      do i = 1, exception_count()
         if (exceptions(i)%message == message) then
            found = .true.
            if (.not. keep(preserve)) call remove_exception(i)
            return
         end if
      end do
   end function catch_message

   logical function keep(preserve)
      logical, optional, intent(in) :: preserve
      keep = .false.
      if (present(preserve)) keep = preserve
   end function keep

   integer function exception_count()
      exception_count = 0
      if (allocated(exceptions)) exception_count = size(exceptions)
   end function exception_count

   subroutine remove_exception(i)
      integer, intent(in) :: i
      type(exception_t), allocatable :: kept(:)
      integer :: n

      n = exception_count()
      allocate(kept(n - 1))
      kept(1:i - 1) = exceptions(1:i - 1)
      kept(i:n - 1) = exceptions(i + 1:n)
      call move_alloc(kept, exceptions)
   end subroutine remove_exception

   !> Throw an assertion failure: the user's message (if any) before the details.
   subroutine fail(details, message, location)
      character(len=*), intent(in) :: details
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(message)) then
         if (len_trim(message) > 0) then
            call throw(trim(message) // ': ' // details, location)
            return
         end if
      end if
      call throw(details, location)
   end subroutine fail

   ! ---------------------------------------------------------------------
   ! Driver support
   ! ---------------------------------------------------------------------

   !> Run one test as pFUnit does: @before; if that raised nothing, the test
   !! and then @after. Report each exception left as `file:line: test: message`.
   subroutine funit_run_test(file_name, line_number, test_name, test, before, after)
      character(len=*), intent(in) :: file_name, test_name
      integer, intent(in) :: line_number
      procedure(funit_test_proc) :: test
      procedure(funit_test_proc), optional :: before, after
      integer :: i

      if (allocated(exceptions)) deallocate(exceptions)
      tests_run = tests_run + 1
      if (present(before)) call before()
      if (.not. anyExceptions()) then
         call test()
         if (present(after)) call after()
      end if
      if (.not. anyExceptions()) return

      tests_failed = tests_failed + 1
      do i = 1, size(exceptions)
         associate (e => exceptions(i))
            ! Exceptions thrown without a location are reported at the test.
            if (len(e%file_name) > 0) then
               write(output_unit, '(a)') e%file_name // ':' // istr(e%line_number) // ': ' &
                  // test_name // ': ' // e%message
            else
               write(output_unit, '(a)') file_name // ':' // istr(line_number) // ': ' &
                  // test_name // ': ' // e%message
            end if
         end associate
      end do
      deallocate(exceptions)
   end subroutine funit_run_test

   !> Count a test marked @disable, without running it.
   subroutine funit_skip_test(file_name, line_number, test_name)
      character(len=*), intent(in) :: file_name, test_name
      integer, intent(in) :: line_number

      tests_disabled = tests_disabled + 1
      write(output_unit, '(a)') 'Disabled: ' // test_name // ' (' // file_name // ':' // istr(line_number) // ')'
   end subroutine funit_skip_test

   !> Print the summary line; exit status 1 if any test failed.
   subroutine funit_finish()
      character(len=:), allocatable :: disabled

      if (tests_failed == 0) then
         disabled = ''
         if (tests_disabled > 0) disabled = ', ' // istr(tests_disabled) // ' disabled'
         write(output_unit, '(a)') 'OK (' // istr(tests_run) // ' tests' // disabled // ')'
      else
         disabled = ''
         if (tests_disabled > 0) disabled = ', Disabled: ' // istr(tests_disabled)
         write(output_unit, '(a)') 'FAILURES!!! Tests run: ' // istr(tests_run) // ', Failures: ' &
            // istr(tests_failed) // disabled
         stop 1
      end if
   end subroutine funit_finish

   ! ---------------------------------------------------------------------
   ! Formatting
   ! ---------------------------------------------------------------------

   function istr_32(i) result(s)
      integer(int32), intent(in) :: i
      character(len=:), allocatable :: s
      s = istr_64(int(i, int64))
   end function istr_32

   function istr_64(i) result(s)
      integer(int64), intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buffer
      write(buffer, '(i0)') i
      s = trim(buffer)
   end function istr_64

   function rstr(x) result(s)
      real(real64), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=48) :: buffer
      write(buffer, '(g0)') x
      s = trim(adjustl(buffer))
   end function rstr

   function lstr(b) result(s)
      logical, intent(in) :: b
      character(len=:), allocatable :: s
      s = merge('.true. ', '.false.', b)
      s = trim(s)
   end function lstr

   !> ' at index [i]' or ' at index [i, j]' for element k (column-major) of an
   !! array of shape `shp`; '' for scalars.
   function at_index(k, shp) result(s)
      integer, intent(in) :: k, shp(:)
      character(len=:), allocatable :: s

      select case (size(shp))
      case (0)
         s = ''
      case (1)
         s = ' at index [' // istr(k) // ']'
      case default
         s = ' at index [' // istr(mod(k - 1, shp(1)) + 1) // ', ' // istr((k - 1)/shp(1) + 1) // ']'
      end select
   end function at_index

   function shape_str(shp) result(s)
      integer, intent(in) :: shp(:)
      character(len=:), allocatable :: s
      integer :: i
      s = '['
      do i = 1, size(shp)
         if (i > 1) s = s // ', '
         s = s // istr(shp(i))
      end do
      s = s // ']'
   end function shape_str

   !> False (and a failure thrown) when two array shapes differ.
   logical function conforms(shape_e, shape_a, message, location)
      integer, intent(in) :: shape_e(:), shape_a(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      conforms = all(shape_e == shape_a)   ! callers pass shapes of one rank
      if (.not. conforms) call fail('nonconforming arrays: expected shape ' // shape_str(shape_e) &
         // ' but found shape ' // shape_str(shape_a), message, location)
   end function conforms

   ! ---------------------------------------------------------------------
   ! Comparison kernels on flattened arrays; `shp` is the shape of actual,
   ! for the index in the message. They report the first failing element.
   ! ---------------------------------------------------------------------

   !> |e - a| <= tol, tested without `==` on reals and without forming
   !! inf - inf when both are the same infinity.
   elemental logical function within(e, a, tol)
      real(real64), intent(in) :: e, a, tol
      if (a < e .or. a > e) then
         within = abs(a - e) <= tol
      else
         within = .true.
      end if
   end function within

   subroutine check_equal_r(e, a, tol, shp, message, location)
      real(real64), intent(in) :: e(:), a(:), tol
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(a)
         if (within(e(k), a(k), tol)) cycle
         call fail('expected <' // rstr(e(k)) // '> but found <' // rstr(a(k)) // '>' // at_index(k, shp) &
            // '; |difference| ' // rstr(abs(a(k) - e(k))) // ' > tolerance ' // rstr(tol), message, location)
         return
      end do
   end subroutine check_equal_r

   !> Passes only if every element differs from expected by more than tol.
   subroutine check_not_equal_r(e, a, tol, shp, message, location)
      real(real64), intent(in) :: e(:), a(:), tol
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(a)
         if (.not. within(e(k), a(k), tol)) cycle
         call fail('expected a value other than <' // rstr(e(k)) // '> (tolerance ' // rstr(tol) &
            // ') but found <' // rstr(a(k)) // '>' // at_index(k, shp), message, location)
         return
      end do
   end subroutine check_not_equal_r

   !> |e - a| <= tol*|e|; as in pFUnit a zero expected value is a failure.
   subroutine check_rel_equal(e, a, tol, shp, message, location)
      real(real64), intent(in) :: e(:), a(:), tol
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(a)
         if (.not. (e(k) < 0.0_real64 .or. e(k) > 0.0_real64)) then
            call fail('expected value is zero' // at_index(k, shp) // ': relative tolerance undefined', &
               message, location)
            return
         end if
         if (within(e(k), a(k), tol*abs(e(k)))) cycle
         call fail('expected <' // rstr(e(k)) // '> but found <' // rstr(a(k)) // '>' // at_index(k, shp) &
            // '; relative difference ' // rstr(abs(a(k) - e(k))/abs(e(k))) // ' > tolerance ' // rstr(tol), &
            message, location)
         return
      end do
   end subroutine check_rel_equal

   subroutine check_order_r(op, lhs, rhs, shp, message, location)
      integer, intent(in) :: op
      real(real64), intent(in) :: lhs(:), rhs(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      logical :: ok
      integer :: k

      do k = 1, size(rhs)
         select case (op)
         case (op_lt)
            ok = lhs(k) < rhs(k)
         case (op_le)
            ok = lhs(k) <= rhs(k)
         case (op_gt)
            ok = lhs(k) > rhs(k)
         case default
            ok = lhs(k) >= rhs(k)
         end select
         if (ok) cycle
         call fail('expected <' // rstr(lhs(k)) // '> to be ' // trim(op_words(op)) // ' <' // rstr(rhs(k)) &
            // '>' // at_index(k, shp), message, location)
         return
      end do
   end subroutine check_order_r

   ! Integer kernels work in int64; default integers are converted.

   subroutine check_equal_i(e, a, shp, message, location)
      integer(int64), intent(in) :: e(:), a(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(a)
         if (e(k) == a(k)) cycle
         call fail('expected <' // istr(e(k)) // '> but found <' // istr(a(k)) // '>' // at_index(k, shp), &
            message, location)
         return
      end do
   end subroutine check_equal_i

   !> Passes only if every element differs from expected.
   subroutine check_not_equal_i(e, a, shp, message, location)
      integer(int64), intent(in) :: e(:), a(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(a)
         if (e(k) /= a(k)) cycle
         call fail('expected a value other than <' // istr(e(k)) // '>' // at_index(k, shp), message, location)
         return
      end do
   end subroutine check_not_equal_i

   subroutine check_order_i(op, lhs, rhs, shp, message, location)
      integer, intent(in) :: op
      integer(int64), intent(in) :: lhs(:), rhs(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      logical :: ok
      integer :: k

      do k = 1, size(rhs)
         select case (op)
         case (op_lt)
            ok = lhs(k) < rhs(k)
         case (op_le)
            ok = lhs(k) <= rhs(k)
         case (op_gt)
            ok = lhs(k) > rhs(k)
         case default
            ok = lhs(k) >= rhs(k)
         end select
         if (ok) cycle
         call fail('expected <' // istr(lhs(k)) // '> to be ' // trim(op_words(op)) // ' <' // istr(rhs(k)) &
            // '>' // at_index(k, shp), message, location)
         return
      end do
   end subroutine check_order_i

   ! ---------------------------------------------------------------------
   ! assertTrue, assertFalse
   ! ---------------------------------------------------------------------

   subroutine assert_true_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call assert_true_1([condition], message, location)
   end subroutine assert_true_0

   subroutine assert_true_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(condition)
         if (condition(k)) cycle
         if (size(condition) == 1) then
            call fail('expected .true. but found .false.', message, location)
         else
            call fail('expected .true. but found .false. at index [' // istr(k) // ']', message, location)
         end if
         return
      end do
   end subroutine assert_true_1

   subroutine assert_false_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (condition) call fail('expected .false. but found .true.', message, location)
   end subroutine assert_false_0

   subroutine assert_false_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(condition)
         if (.not. condition(k)) cycle
         call fail('expected .false. but found .true. at index [' // istr(k) // ']', message, location)
         return
      end do
   end subroutine assert_false_1

   ! ---------------------------------------------------------------------
   ! assertEqual, integer (message and location by keyword, as in pFUnit)
   ! ---------------------------------------------------------------------

   subroutine equal_i_00(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected, actual
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i(int([expected], int64), int([actual], int64), [integer ::], message, location)
   end subroutine equal_i_00

   subroutine equal_i_01(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected, actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i(spread(int(expected, int64), 1, size(actual)), int(actual, int64), shape(actual), &
         message, location)
   end subroutine equal_i_01

   subroutine equal_i_11(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected(:), actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_equal_i(int(expected, int64), int(actual, int64), shape(actual), message, location)
   end subroutine equal_i_11

   subroutine equal_i_02(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected, actual(:, :)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i(spread(int(expected, int64), 1, size(actual)), int(reshape(actual, [size(actual)]), int64), &
         shape(actual), message, location)
   end subroutine equal_i_02

   subroutine equal_i_22(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected(:, :), actual(:, :)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_equal_i(int(reshape(expected, [size(expected)]), int64), &
         int(reshape(actual, [size(actual)]), int64), shape(actual), message, location)
   end subroutine equal_i_22

   subroutine equal_i8_00(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected, actual
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i([expected], [actual], [integer ::], message, location)
   end subroutine equal_i8_00

   subroutine equal_i8_01(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected, actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i(spread(expected, 1, size(actual)), actual, shape(actual), message, location)
   end subroutine equal_i8_01

   subroutine equal_i8_11(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected(:), actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_equal_i(expected, actual, shape(actual), message, location)
   end subroutine equal_i8_11

   ! A default-integer expected with an int64 actual (pFUnit allows it).

   subroutine equal_i48_00(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected
      integer(int64), intent(in) :: actual
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i([int(expected, int64)], [actual], [integer ::], message, location)
   end subroutine equal_i48_00

   subroutine equal_i48_01(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected
      integer(int64), intent(in) :: actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_equal_i(spread(int(expected, int64), 1, size(actual)), actual, shape(actual), message, location)
   end subroutine equal_i48_01

   subroutine equal_i48_11(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected(:)
      integer(int64), intent(in) :: actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_equal_i(int(expected, int64), actual, shape(actual), message, location)
   end subroutine equal_i48_11

   ! ---------------------------------------------------------------------
   ! assertEqual, real(real64): with and without tolerance (default 0)
   ! ---------------------------------------------------------------------

   subroutine equal_r_00_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual, tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_equal_r([expected], [actual], tolerance, [integer ::], message, location)
   end subroutine equal_r_00_tol

   subroutine equal_r_01_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual(:), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_equal_r(spread(expected, 1, size(actual)), actual, tolerance, shape(actual), message, location)
   end subroutine equal_r_01_tol

   subroutine equal_r_11_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:), actual(:), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_equal_r(expected, actual, tolerance, shape(actual), message, location)
   end subroutine equal_r_11_tol

   subroutine equal_r_02_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual(:, :), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_equal_r(spread(expected, 1, size(actual)), reshape(actual, [size(actual)]), tolerance, &
         shape(actual), message, location)
   end subroutine equal_r_02_tol

   subroutine equal_r_22_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:, :), actual(:, :), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_equal_r(reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), tolerance, &
         shape(actual), message, location)
   end subroutine equal_r_22_tol

   subroutine equal_r_00(expected, actual, message, location)
      real(real64), intent(in) :: expected, actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call equal_r_00_tol(expected, actual, 0.0_real64, message, location)
   end subroutine equal_r_00

   subroutine equal_r_01(expected, actual, message, location)
      real(real64), intent(in) :: expected, actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call equal_r_01_tol(expected, actual, 0.0_real64, message, location)
   end subroutine equal_r_01

   subroutine equal_r_11(expected, actual, message, location)
      real(real64), intent(in) :: expected(:), actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call equal_r_11_tol(expected, actual, 0.0_real64, message, location)
   end subroutine equal_r_11

   subroutine equal_r_02(expected, actual, message, location)
      real(real64), intent(in) :: expected, actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call equal_r_02_tol(expected, actual, 0.0_real64, message, location)
   end subroutine equal_r_02

   subroutine equal_r_22(expected, actual, message, location)
      real(real64), intent(in) :: expected(:, :), actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call equal_r_22_tol(expected, actual, 0.0_real64, message, location)
   end subroutine equal_r_22

   ! ---------------------------------------------------------------------
   ! assertEqual, logical and character
   ! ---------------------------------------------------------------------

   subroutine equal_l_00(expected, actual, unused, message, location)
      logical, intent(in) :: expected, actual
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (expected .neqv. actual) &
         call fail('expected <' // lstr(expected) // '> but found <' // lstr(actual) // '>', message, location)
   end subroutine equal_l_00

   subroutine equal_l_11(expected, actual, unused, message, location)
      logical, intent(in) :: expected(:), actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      if (present(unused)) continue
      if (.not. conforms(shape(expected), shape(actual), message, location)) return
      do k = 1, size(actual)
         if (expected(k) .eqv. actual(k)) cycle
         call fail('expected <' // lstr(expected(k)) // '> but found <' // lstr(actual(k)) // '>' &
            // at_index(k, shape(actual)), message, location)
         return
      end do
   end subroutine equal_l_11

   !> Strings are equal when they match after removing leading and trailing
   !! blanks and tabs (pFUnit's default, whitespace=TRIM_ALL).
   subroutine equal_string(expected, found, message, location)
      character(len=*), intent(in) :: expected, found
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      character(len=:), allocatable :: e, f

      e = strip(expected)
      f = strip(found)
      ! Neither ends in a blank now, so blank padding cannot make them equal.
      if (e == f) return
      call fail('expected <"' // e // '"> but found <"' // f // '">', message, location)
   end subroutine equal_string

   function strip(s) result(t)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t
      integer :: first, last

      first = 1
      last = len(s)
      do while (first <= last)
         if (.not. blank(s(first:first))) exit
         first = first + 1
      end do
      do while (last >= first)
         if (.not. blank(s(last:last))) exit
         last = last - 1
      end do
      t = s(first:last)
   end function strip

   logical function blank(c)
      character, intent(in) :: c
      blank = c == ' ' .or. iachar(c) == 9
   end function blank

   ! ---------------------------------------------------------------------
   ! assertNotEqual: passes when every element differs
   ! ---------------------------------------------------------------------

   subroutine not_equal_i_00(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected, actual
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_not_equal_i(int([expected], int64), int([actual], int64), [integer ::], message, location)
   end subroutine not_equal_i_00

   subroutine not_equal_i_11(expected, actual, unused, message, location)
      integer(int32), intent(in) :: expected(:), actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_not_equal_i(int(expected, int64), int(actual, int64), shape(actual), message, location)
   end subroutine not_equal_i_11

   subroutine not_equal_i8_00(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected, actual
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_not_equal_i([expected], [actual], [integer ::], message, location)
   end subroutine not_equal_i8_00

   subroutine not_equal_i8_11(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected(:), actual(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_not_equal_i(expected, actual, shape(actual), message, location)
   end subroutine not_equal_i8_11

   subroutine not_equal_r_00_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual, tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_not_equal_r([expected], [actual], tolerance, [integer ::], message, location)
   end subroutine not_equal_r_00_tol

   subroutine not_equal_r_11_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:), actual(:), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_not_equal_r(expected, actual, tolerance, shape(actual), message, location)
   end subroutine not_equal_r_11_tol

   subroutine not_equal_r_00(expected, actual, message, location)
      real(real64), intent(in) :: expected, actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call not_equal_r_00_tol(expected, actual, 0.0_real64, message, location)
   end subroutine not_equal_r_00

   subroutine not_equal_r_11(expected, actual, message, location)
      real(real64), intent(in) :: expected(:), actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call not_equal_r_11_tol(expected, actual, 0.0_real64, message, location)
   end subroutine not_equal_r_11

   ! ---------------------------------------------------------------------
   ! assertRelativelyEqual (real64; the tolerance is required)
   ! ---------------------------------------------------------------------

   subroutine rel_equal_00(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual, tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_rel_equal([expected], [actual], tolerance, [integer ::], message, location)
   end subroutine rel_equal_00

   subroutine rel_equal_01(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual(:), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_rel_equal(spread(expected, 1, size(actual)), actual, tolerance, shape(actual), message, location)
   end subroutine rel_equal_01

   subroutine rel_equal_11(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:), actual(:), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_rel_equal(expected, actual, tolerance, shape(actual), message, location)
   end subroutine rel_equal_11

   subroutine rel_equal_02(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected, actual(:, :), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_rel_equal(spread(expected, 1, size(actual)), reshape(actual, [size(actual)]), tolerance, &
         shape(actual), message, location)
   end subroutine rel_equal_02

   subroutine rel_equal_22(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:, :), actual(:, :), tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(expected), shape(actual), message, location)) &
         call check_rel_equal(reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), tolerance, &
         shape(actual), message, location)
   end subroutine rel_equal_22

   ! ---------------------------------------------------------------------
   ! Order assertions: assertLessThan(lhs, rhs) passes when lhs < rhs, etc.
   ! ---------------------------------------------------------------------

   subroutine less_than_i_00(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_lt, int([lhs], int64), int([rhs], int64), [integer ::], message, location)
   end subroutine less_than_i_00

   subroutine less_than_i_11(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_lt, int(lhs, int64), int(rhs, int64), shape(rhs), message, location)
   end subroutine less_than_i_11

   subroutine less_than_i8_00(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_lt, [lhs], [rhs], [integer ::], message, location)
   end subroutine less_than_i8_00

   subroutine less_than_i8_11(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_lt, lhs, rhs, shape(rhs), message, location)
   end subroutine less_than_i8_11

   subroutine less_than_r_00(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs, rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_order_r(op_lt, [lhs], [rhs], [integer ::], message, location)
   end subroutine less_than_r_00

   subroutine less_than_r_11(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:), rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_r(op_lt, lhs, rhs, shape(rhs), message, location)
   end subroutine less_than_r_11

   subroutine less_equal_i_00(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_le, int([lhs], int64), int([rhs], int64), [integer ::], message, location)
   end subroutine less_equal_i_00

   subroutine less_equal_i_11(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_le, int(lhs, int64), int(rhs, int64), shape(rhs), message, location)
   end subroutine less_equal_i_11

   subroutine less_equal_i8_00(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_le, [lhs], [rhs], [integer ::], message, location)
   end subroutine less_equal_i8_00

   subroutine less_equal_i8_11(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_le, lhs, rhs, shape(rhs), message, location)
   end subroutine less_equal_i8_11

   subroutine less_equal_r_00(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs, rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_order_r(op_le, [lhs], [rhs], [integer ::], message, location)
   end subroutine less_equal_r_00

   subroutine less_equal_r_11(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:), rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_r(op_le, lhs, rhs, shape(rhs), message, location)
   end subroutine less_equal_r_11

   subroutine greater_than_i_00(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_gt, int([lhs], int64), int([rhs], int64), [integer ::], message, location)
   end subroutine greater_than_i_00

   subroutine greater_than_i_11(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_gt, int(lhs, int64), int(rhs, int64), shape(rhs), message, location)
   end subroutine greater_than_i_11

   subroutine greater_than_i8_00(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_gt, [lhs], [rhs], [integer ::], message, location)
   end subroutine greater_than_i8_00

   subroutine greater_than_i8_11(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_gt, lhs, rhs, shape(rhs), message, location)
   end subroutine greater_than_i8_11

   subroutine greater_than_r_00(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs, rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_order_r(op_gt, [lhs], [rhs], [integer ::], message, location)
   end subroutine greater_than_r_00

   subroutine greater_than_r_11(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:), rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_r(op_gt, lhs, rhs, shape(rhs), message, location)
   end subroutine greater_than_r_11

   subroutine greater_equal_i_00(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_ge, int([lhs], int64), int([rhs], int64), [integer ::], message, location)
   end subroutine greater_equal_i_00

   subroutine greater_equal_i_11(lhs, rhs, unused, message, location)
      integer(int32), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_ge, int(lhs, int64), int(rhs, int64), shape(rhs), message, location)
   end subroutine greater_equal_i_11

   subroutine greater_equal_i8_00(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs, rhs
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      call check_order_i(op_ge, [lhs], [rhs], [integer ::], message, location)
   end subroutine greater_equal_i8_00

   subroutine greater_equal_i8_11(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:), rhs(:)
      type(keyword_enforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (present(unused)) continue
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_i(op_ge, lhs, rhs, shape(rhs), message, location)
   end subroutine greater_equal_i8_11

   subroutine greater_equal_r_00(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs, rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call check_order_r(op_ge, [lhs], [rhs], [integer ::], message, location)
   end subroutine greater_equal_r_00

   subroutine greater_equal_r_11(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:), rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (conforms(shape(lhs), shape(rhs), message, location)) &
         call check_order_r(op_ge, lhs, rhs, shape(rhs), message, location)
   end subroutine greater_equal_r_11

   ! ---------------------------------------------------------------------
   ! assertExceptionRaised: catches (removes) the exception it expects
   ! ---------------------------------------------------------------------

   subroutine exception_raised_any(location)
      type(SourceLocation), optional, intent(in) :: location
      if (.not. catch_any()) call throw('expected an exception to be thrown, but none was', location)
   end subroutine exception_raised_any

   subroutine exception_raised_message(message, location)
      character(len=*), intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (.not. catch_message(message)) &
         call throw('expected an exception <' // trim(message) // '> to be thrown, but it was not', location)
   end subroutine exception_raised_message

end module funit
