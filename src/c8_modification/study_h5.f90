!> A study's table in an HDF5 file (report C.8; docs/modification.md,
!! "Outputs"): the base deck as /input/deck, and under /study one row per
!! run - /study/run, /study/status (1 completed, 2 ended by an end test,
!! 3 failed, 4 invalid), /study/meets_limits (1 or 0), /study/t_end,
!! /study/values (a column per varied field, deck units) and
!! /study/criteria (a column per criterion; NaN for a run without them).
!! The reasons are in results.csv and the listing. Written under a
!! temporary name and put in place at the end (output_files), as a run's.
module study_h5
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp
   use error_handling, only: error_t
   use text_io, only: string_t
   use history_h5, only: history_file_t
   use output_files, only: output_file_t, deliver_outputs
   use study_table, only: run_row_t
   implicit none
   private

   public :: write_study_h5

contains

   !> The rows (those with have) to the HDF5 file at path.
   subroutine write_study_h5(path, title, deck_lines, var_columns, var_units, crit_columns, crit_units, rows, have, &
                             err)
      character(len=*), intent(in) :: path, title
      character(len=*), intent(in) :: deck_lines(:)
      type(string_t), intent(in) :: var_columns(:), var_units(:), crit_columns(:), crit_units(:)
      type(run_row_t), intent(in) :: rows(:)
      logical, intent(in) :: have(:)
      type(error_t), intent(inout) :: err
      type(output_file_t) :: target
      type(history_file_t) :: h5
      integer :: id_run, id_status, id_meets, id_t, id_x, id_c, r
      real(wp), allocatable :: c(:)
      call target%reserve(path, 'HDF5 file', err)
      if (err%failed()) return
      call h5%open(target%writing_path(), title, deck_lines, err)
      id_x = 0
      id_c = 0
      if (.not. err%failed()) call h5%add_series('study/run', ['run'], ['-'], 'the run''s number', id_run, err)
      if (.not. err%failed()) call h5%add_series('study/status', ['status'], ['-'], &
         '1 completed, 2 ended by an end test (C.7), 3 failed numerically, 4 invalid deck', id_status, err)
      if (.not. err%failed()) call h5%add_series('study/meets_limits', ['meets_limits'], ['-'], &
         '1 when every criterion with a limit is within it', id_meets, err)
      if (.not. err%failed()) call h5%add_series('study/t_end', ['t_end'], ['s'], 'when the run ended', id_t, err)
      if (.not. err%failed() .and. size(var_columns) > 0) call h5%add_series('study/values', names(var_columns), &
         names(var_units), 'the varied fields'' values as run (deck units)', id_x, err, rank=2)
      if (.not. err%failed() .and. size(crit_columns) > 0) call h5%add_series('study/criteria', names(crit_columns), &
         names(crit_units), 'the criteria of each run (NaN: a run without them)', id_c, err, rank=2)
      allocate (c(size(crit_columns)))
      do r = 1, size(rows)
         if (err%failed()) exit
         if (.not. have(r)) cycle
         call h5%append(id_run, [real(rows(r)%run, wp)], err)
         call h5%append(id_status, [real(rows(r)%status, wp)], err)
         call h5%append(id_meets, [merge(1.0_wp, 0.0_wp, rows(r)%meets)], err)
         call h5%append(id_t, [rows(r)%t_end], err)
         if (id_x > 0) call h5%append(id_x, rows(r)%x, err)
         if (id_c > 0) then
            c = ieee_value(1.0_wp, ieee_quiet_nan)
            if (allocated(rows(r)%crit)) c = rows(r)%crit
            call h5%append(id_c, c, err)
         end if
      end do
      call h5%close(err)
      call deliver_outputs(err, target)
   end subroutine write_study_h5

   !> Names as fixed-length strings (history_file_t's columns).
   function names(list) result(out)
      type(string_t), intent(in) :: list(:)
      character(len=:), allocatable :: out(:)
      integer :: k, n
      n = 1
      do k = 1, size(list)
         n = max(n, len(list(k)%s))
      end do
      allocate (character(len=n) :: out(size(list)))
      do k = 1, size(list)
         out(k) = list(k)%s
      end do
   end function names
end module study_h5
