!> Errors returned by library code (docs/architecture.md, "Errors"). Library
!! code never prints or stops the program: a procedure that can fail in a
!! way a user must hear of takes `type(error_t), intent(inout) :: err` as
!! its last argument and fills it where the failure is decided; its
!! callers add context (error_prefix, or a message of their own around it)
!! and pass it up; only the main program prints the message and chooses
!! the exit status from the error's category. An outcome that is not a
!! failure (a query, a trial the caller answers itself) is an answer, not
!! an error_t.
module error_handling
   implicit none
   private

   public :: error_t, error_set, error_append, error_prefix
   public :: exit_ok, exit_usage, exit_deck, exit_numerical, exit_io, exit_study
   public :: error_category_name

   !> Exit statuses (documented in README.md and docs/usage.md).
   integer, parameter :: exit_ok = 0
   integer, parameter :: exit_usage = 1       !< bad command line
   integer, parameter :: exit_deck = 2        !< the deck has errors
   integer, parameter :: exit_numerical = 3   !< the integration failed
   integer, parameter :: exit_io = 4          !< a file could not be read or written
   !> a study (C.8) has runs without a result (--collect), or every run failed
   integer, parameter :: exit_study = 5

   !> An error: its category (one of the exit_* values) and a message, which
   !! may hold several lines (one per problem found).
   type :: error_t
      integer :: code = exit_ok
      character(len=:), allocatable :: message
   contains
      procedure :: failed => error_failed
   end type error_t

contains

   !> True when an error has been recorded.
   pure logical function error_failed(this)
      class(error_t), intent(in) :: this
      error_failed = this%code /= exit_ok
   end function error_failed

   !> Record an error, replacing any earlier one.
   pure subroutine error_set(err, code, message)
      type(error_t), intent(inout) :: err
      integer, intent(in) :: code
      character(len=*), intent(in) :: message
      err%code = code
      err%message = message
   end subroutine error_set

   !> Add one more line to an error, keeping what is there (used to report
   !! every problem of a deck, not only the first).
   pure subroutine error_append(err, code, message)
      type(error_t), intent(inout) :: err
      integer, intent(in) :: code
      character(len=*), intent(in) :: message
      if (err%code == exit_ok .or. .not. allocated(err%message)) then
         err%code = code
         err%message = message
      else
         err%message = err%message//new_line('a')//message
      end if
   end subroutine error_append

   !> Give an error the context its caller knows (where, when), before its
   !! message: "integration stopped after t = 0.05 s: " and the stepper's
   !! why. Nothing when no error is recorded.
   pure subroutine error_prefix(err, context)
      type(error_t), intent(inout) :: err
      character(len=*), intent(in) :: context
      if (err%code == exit_ok .or. .not. allocated(err%message)) return
      err%message = context//err%message
   end subroutine error_prefix

   !> A short name for an error category, for the first line of a report.
   pure function error_category_name(code) result(name)
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      select case (code)
      case (exit_ok);        name = 'no error'
      case (exit_usage);     name = 'usage error'
      case (exit_deck);      name = 'deck error'
      case (exit_numerical); name = 'numerical failure'
      case (exit_io);        name = 'input/output error'
      case (exit_study);     name = 'study incomplete'
      case default;          name = 'error'
      end select
   end function error_category_name
end module error_handling
