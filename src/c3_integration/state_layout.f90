!> Where everything lives in the state vector y that the integrators of
!! C.3 advance: assigned once, when the scene is built, so that no code
!! slices y with literal indices. Each occupant reserves its generalized
!! coordinates z and rates z', and each of its effects its extra degrees of
!! freedom (coordinates then rates) and its auxiliary quantities (work
!! integrals).
module state_layout
   implicit none
   private

   public :: state_slot_t, state_layout_t

   !> A named range y(first : first + size - 1).
   type :: state_slot_t
      character(len=48) :: name = ' '
      integer :: first = 1
      integer :: size = 0
   end type state_slot_t

   type :: state_layout_t
      integer :: n = 0                        !< length of y
      type(state_slot_t), allocatable :: slot(:)
   contains
      procedure :: reserve => layout_reserve
   end type state_layout_t

contains

   !> Reserve n entries named name; offset is the index before the first
   !! (so the range is offset+1 : offset+n).
   subroutine layout_reserve(this, name, n, offset)
      class(state_layout_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      integer, intent(out) :: offset
      type(state_slot_t), allocatable :: longer(:)
      if (.not. allocated(this%slot)) allocate (this%slot(0))
      offset = this%n
      allocate (longer(size(this%slot) + 1))
      longer(1:size(this%slot)) = this%slot
      longer(size(longer)) = state_slot_t(name, offset + 1, n)
      call move_alloc(longer, this%slot)
      this%n = this%n + n
   end subroutine layout_reserve
end module state_layout
