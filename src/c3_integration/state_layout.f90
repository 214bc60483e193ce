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
      !> part of an adaptive stepper's error norm (a search's starting
      !! value, which changes only the cost, is not: D-B7)
      logical :: error_controlled = .true.
   end type state_slot_t

   type :: state_layout_t
      integer :: n = 0                        !< length of y
      type(state_slot_t), allocatable :: slot(:)
   contains
      procedure :: reserve => layout_reserve
      procedure :: error_controlled => layout_error_controlled
   end type state_layout_t

contains

   !> Reserve n entries named name; offset is the index before the first
   !! (so the range is offset+1 : offset+n); error_controlled (default
   !! true) whether an adaptive stepper's error norm includes them.
   subroutine layout_reserve(this, name, n, offset, error_controlled)
      class(state_layout_t), intent(inout) :: this
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      integer, intent(out) :: offset
      logical, intent(in), optional :: error_controlled
      type(state_slot_t), allocatable :: longer(:)
      if (.not. allocated(this%slot)) allocate (this%slot(0))
      offset = this%n
      allocate (longer(size(this%slot) + 1))
      longer(1:size(this%slot)) = this%slot
      longer(size(longer)) = state_slot_t(name, offset + 1, n)
      if (present(error_controlled)) longer(size(longer))%error_controlled = error_controlled
      call move_alloc(longer, this%slot)
      this%n = this%n + n
   end subroutine layout_reserve

   !> For each entry of y, whether it is error-controlled.
   pure function layout_error_controlled(this) result(mask)
      class(state_layout_t), intent(in) :: this
      logical :: mask(this%n)
      integer :: k
      mask = .true.
      if (.not. allocated(this%slot)) return
      do k = 1, size(this%slot)
         associate (sl => this%slot(k))
            mask(sl%first:sl%first + sl%size - 1) = sl%error_controlled
         end associate
      end do
   end function layout_error_controlled
end module state_layout
