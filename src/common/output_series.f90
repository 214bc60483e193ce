!> The description of one output variable series: a group of columns
!! written together at every print time (one HDF5 dataset, one listing
!! table). Producers - the C.6 calculations and each effect - declare their
!! series with these; the output registry collects them.
module output_series
   use kinds, only: wp
   implicit none
   private

   public :: output_column_t, output_series_t, series_new, column
   public :: max_listing_columns

   !> A listing line holds the time and at most this many values (132 columns).
   integer, parameter :: max_listing_columns = 11

   !> One column: its name, its unit in the HDF5 file (the internal unit),
   !! and the unit and scale of the listing (listing value = scale * value).
   type :: output_column_t
      character(len=16) :: name = ' '
      character(len=12) :: unit = ' '
      character(len=12) :: listing_unit = ' '
      real(wp) :: listing_scale = 1.0_wp
   end type output_column_t

   !> One series. name is its path in the HDF5 file (e.g. "body/z");
   !! producer and item say who fills it (set by the registry).
   type :: output_series_t
      character(len=:), allocatable :: name
      character(len=:), allocatable :: title         !< the listing table's heading
      character(len=:), allocatable :: description   !< HDF5 attribute and docs
      integer :: nout = 1                            !< printed when NOUT >= this
      type(output_column_t), allocatable :: col(:)
      integer :: producer = 0                        !< 0: C.6; k > 0: effect k of the occupant
      integer :: item = 0                            !< which of the producer's series
      integer :: occupant = 1
      logical :: generalized_force = .false.         !< the producer's contribution to b
      integer :: offset = 0                          !< first value - 1 in a frame
      !> for a series that sums parts of its producer (the energy summary:
      !! part n_energy_kinds*(k-1)+kind is effect k's energy of that kind),
      !! the column each part adds to, 0 for none: resolved once, when the
      !! series is declared, so that a frame compares no names
      integer, allocatable :: sum_column(:)
   end type output_series_t

contains

   !> A series without columns yet.
   pure function series_new(name, title, description, nout) result(s)
      character(len=*), intent(in) :: name, title, description
      integer, intent(in) :: nout
      type(output_series_t) :: s
      s%name = name
      s%title = title
      s%description = description
      s%nout = nout
      allocate (s%col(0))
   end function series_new

   !> A column; the listing shows value*scale in listing_unit (default: as stored).
   pure function column(name, unit, listing_unit, listing_scale) result(c)
      character(len=*), intent(in) :: name, unit
      character(len=*), intent(in), optional :: listing_unit
      real(wp), intent(in), optional :: listing_scale
      type(output_column_t) :: c
      c%name = name
      c%unit = unit
      c%listing_unit = unit
      if (present(listing_unit)) c%listing_unit = listing_unit
      if (present(listing_scale)) c%listing_scale = listing_scale
   end function column
end module output_series
