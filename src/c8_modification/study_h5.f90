!> A study's table in an HDF5 file (report C.8; docs/modification.md,
!! "Outputs"): the base deck as /input/deck, and under /study one row per
!! run - /study/run, /study/status (1 completed, 2 ended by an end test,
!! 3 failed, 4 invalid), /study/meets_limits (1 or 0), /study/t_end,
!! /study/values (a column per varied field, deck units) and
!! /study/criteria (a column per criterion; NaN for a run without them).
!! The reasons are in results.csv and the listing. Written under a
!! temporary name and put in place at the end (output_files), as a run's;
!! row by row, so that no row is held in memory.
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

   public :: study_h5_t

   !> The file being written, row by row (no row is held).
   type :: study_h5_t
      private
      type(output_file_t) :: target
      type(history_file_t) :: h5
      integer :: id_run = 0, id_status = 0, id_meets = 0, id_t = 0, id_x = 0, id_c = 0
      integer :: n_crit = 0
   contains
      procedure :: open => study_h5_open
      procedure :: add => study_h5_add
      procedure :: close => study_h5_close
   end type study_h5_t

contains

   !> Create the file at path (under a temporary name): the root
   !! attributes, /input/deck (deck_lines), the /study datasets' columns.
   subroutine study_h5_open(this, path, title, deck_lines, var_columns, var_units, crit_columns, crit_units, err)
      class(study_h5_t), intent(inout) :: this
      character(len=*), intent(in) :: path, title
      character(len=*), intent(in) :: deck_lines(:)
      type(string_t), intent(in) :: var_columns(:), var_units(:), crit_columns(:), crit_units(:)
      type(error_t), intent(inout) :: err
      this%n_crit = size(crit_columns)
      call this%target%reserve(path, 'HDF5 file', err)
      if (err%failed()) return
      call this%h5%open(this%target%writing_path(), title, deck_lines, err)
      if (.not. err%failed()) call this%h5%add_series('study/run', ['run'], ['-'], 'the run''s number', &
         this%id_run, err)
      if (.not. err%failed()) call this%h5%add_series('study/status', ['status'], ['-'], &
         '1 completed, 2 ended by an end test (C.7), 3 failed numerically, 4 invalid deck', this%id_status, err)
      if (.not. err%failed()) call this%h5%add_series('study/meets_limits', ['meets_limits'], ['-'], &
         '1 when every criterion with a limit is within it', this%id_meets, err)
      if (.not. err%failed()) call this%h5%add_series('study/t_end', ['t_end'], ['s'], 'when the run ended', &
         this%id_t, err)
      if (.not. err%failed() .and. size(var_columns) > 0) call this%h5%add_series('study/values', &
         names(var_columns), names(var_units), 'the varied fields'' values as run (deck units)', this%id_x, err, &
         rank=2)
      if (.not. err%failed() .and. size(crit_columns) > 0) call this%h5%add_series('study/criteria', &
         names(crit_columns), names(crit_units), 'the criteria of each run (NaN: a run without them)', this%id_c, &
         err, rank=2)
   end subroutine study_h5_open

   !> One run's row.
   subroutine study_h5_add(this, row, err)
      class(study_h5_t), intent(inout) :: this
      type(run_row_t), intent(in) :: row
      type(error_t), intent(inout) :: err
      real(wp) :: c(this%n_crit)
      if (err%failed()) return
      call this%h5%append(this%id_run, [real(row%run, wp)], err)
      call this%h5%append(this%id_status, [real(row%status, wp)], err)
      call this%h5%append(this%id_meets, [merge(1.0_wp, 0.0_wp, row%meets)], err)
      call this%h5%append(this%id_t, [row%t_end], err)
      if (this%id_x > 0) call this%h5%append(this%id_x, row%x, err)
      if (this%id_c > 0) then
         c = ieee_value(1.0_wp, ieee_quiet_nan)
         if (allocated(row%crit)) c = row%crit
         call this%h5%append(this%id_c, c, err)
      end if
   end subroutine study_h5_add

   !> Close the file and put it in place of its target (removed on a failure).
   subroutine study_h5_close(this, err)
      class(study_h5_t), intent(inout) :: this
      type(error_t), intent(inout) :: err
      if (this%h5%is_open()) call this%h5%close(err)
      call deliver_outputs(err, this%target)
   end subroutine study_h5_close
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
