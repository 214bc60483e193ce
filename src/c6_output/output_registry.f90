!> The one table of output variables: every series a run writes, with its
!! columns, units, listing scale, description, NOUT level and producer. It
!! drives the listing's time-history tables, the HDF5 series and their
!! attributes, and the HDF5 section of docs/usage.md (`hsri2d --outputs`),
!! so they cannot disagree. A frame holds the values of every series at one
!! print time, series after series.
module output_registry
   use kinds, only: wp
   use output_series, only: output_series_t, output_column_t
   implicit none
   private

   public :: output_registry_t, output_frame_t

   type :: output_registry_t
      type(output_series_t), allocatable :: series(:)
      integer :: n_values = 0            !< length of a frame
      !> the series of each producer (output_producers' registry_index,
      !! once the series are declared; an append clears it): series_of(j,
      !! p, o) the index of item j of producer p of occupant o, 0 where the
      !! registry has none; value_at(j, p, o) where its values start in a
      !! frame (their offset; -1: none), value_count(j, p, o) how many
      integer, allocatable :: series_of(:, :, :), value_at(:, :, :), value_count(:, :, :)
   contains
      procedure :: add => registry_add
      procedure :: find => registry_find
      procedure :: count => registry_count
   end type output_registry_t

   !> The values of every series at one time.
   type :: output_frame_t
      real(wp) :: t = 0.0_wp
      real(wp), allocatable :: v(:)
      !> false for the frame a run that failed at its first evaluation
      !! passes to begin: no value is known
      logical :: valid = .true.
   end type output_frame_t

contains

   !> Append a series; its values follow those already registered. The
   !! series already there are moved, not copied: their allocatable parts
   !! change hands (a copy of every series at every append made building the
   !! registry quadratic, some 6 million instructions for the 120 series of
   !! an interior deck).
   subroutine registry_add(this, s)
      class(output_registry_t), intent(inout) :: this
      type(output_series_t), intent(in) :: s
      type(output_series_t), allocatable :: longer(:)
      integer :: k
      if (.not. allocated(this%series)) allocate (this%series(0))
      ! (the index is no longer the whole registry's)
      if (allocated(this%series_of)) deallocate (this%series_of, this%value_at, this%value_count)
      allocate (longer(size(this%series) + 1))
      do k = 1, size(this%series)
         call series_move(this%series(k), longer(k))
      end do
      longer(size(longer)) = s
      longer(size(longer))%offset = this%n_values
      this%n_values = this%n_values + size(s%col)
      call move_alloc(longer, this%series)
   end subroutine registry_add

   !> to = from, the allocatable parts moved (from is left without them):
   !! they are taken out, the rest assigned (every other component, whatever
   !! the type gains later), and they are put back into to.
   pure subroutine series_move(from, to)
      type(output_series_t), intent(inout) :: from
      type(output_series_t), intent(inout) :: to
      character(len=:), allocatable :: name, title, description
      type(output_column_t), allocatable :: col(:)
      integer, allocatable :: sum_column(:)
      call move_alloc(from%name, name)
      call move_alloc(from%title, title)
      call move_alloc(from%description, description)
      call move_alloc(from%col, col)
      call move_alloc(from%sum_column, sum_column)
      to = from
      call move_alloc(name, to%name)
      call move_alloc(title, to%title)
      call move_alloc(description, to%description)
      call move_alloc(col, to%col)
      call move_alloc(sum_column, to%sum_column)
   end subroutine series_move

   !> The index of the series called name, or 0.
   pure integer function registry_find(this, name) result(k)
      class(output_registry_t), intent(in) :: this
      character(len=*), intent(in) :: name
      do k = 1, size(this%series)
         if (this%series(k)%name == name) return
      end do
      k = 0
   end function registry_find

   pure integer function registry_count(this)
      class(output_registry_t), intent(in) :: this
      registry_count = 0
      if (allocated(this%series)) registry_count = size(this%series)
   end function registry_count
end module output_registry
