!> A study's progress on standard error, where that is a terminal (the
!! program checks): one line, rewritten after each run (docs/modification.md).
!! A module procedure, not the program's internal one: passed as an argument,
!! an internal procedure would need a trampoline on an executable stack.
module study_progress
   use, intrinsic :: iso_fortran_env, only: error_unit
   use kinds, only: wp
   use strings, only: itoa
   implicit none
   private

   public :: show_progress

contains

   !> Runs done, failed, in all; the seconds so far (for the time to go).
   subroutine show_progress(done, bad, total, seconds)
      integer, intent(in) :: done, bad, total
      real(wp), intent(in) :: seconds
      integer :: ios
      character(len=:), allocatable :: eta
      eta = ''
      if (done > 0 .and. done < total) eta = ', about '//itoa(nint(seconds/done*(total - done)))//' s to go'
      ! iostat: a standard error that cannot be written must not end the study
      write (error_unit, '(a)', advance='no', iostat=ios) achar(13)//'hsri2d: study: '//itoa(done)//' of '// &
         itoa(total)//' runs done, '//itoa(bad)//' failed, '//itoa(total - done)//' remaining'//eta//'   '
   end subroutine show_progress
end module study_progress
