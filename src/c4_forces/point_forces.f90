!> Forces from outside the body on its segments (gravity, seat, belts,
!! contacts), as the effects that apply them report them (point_forces):
!! for the joint reactions segment by segment (Newton-Euler, A-INJ) and
!! Table 5's force criteria.
module point_forces
   use kinds, only: wp
   implicit none
   private

   public :: point_force_t, point_force_list_t, point_force_add, point_force_reserve

   !> A force from outside the body (gravity, seat, belt, contact) on one
   !! segment, at a point of it: inertial components (lb) and position (in).
   !! Effects that apply such forces report them (`point_forces`), so that
   !! the joint reactions can be taken segment by segment (Newton-Euler,
   !! A-INJ), and each effect's list reproduces its generalized forces.
   type :: point_force_t
      integer :: segment = 0
      real(wp) :: point(2) = 0.0_wp
      real(wp) :: force(2) = 0.0_wp
      !> a load across the segment's bone (Table 5's shear fracture); not so
      !! gravity, spread over the segment, nor a force at a joint (the seat's
      !! hip force), which the joint passes on
      logical :: across_bone = .true.
      !> a contact's body point i, surface k and normal force P (Table 5's
      !! skull, back, rib, lower leg and face loads); 0 for other forces
      integer :: arc = 0, surface = 0
      real(wp) :: normal_force = 0.0_wp
   end type point_force_t

   !> The point forces of an occupant's effects at one state (f(1:n); it
   !! grows as forces are added, doubling, and keeps its storage when it is
   !! emptied (n = 0) and filled again: a list reserved before the step loop
   !! allocates nothing in it, docs/architecture.md).
   type :: point_force_list_t
      integer :: n = 0
      type(point_force_t), allocatable :: f(:)
   end type point_force_list_t

contains

   !> Room for at least n forces in the list (its forces kept).
   pure subroutine point_force_reserve(list, n)
      type(point_force_list_t), intent(inout) :: list
      integer, intent(in) :: n
      type(point_force_t), allocatable :: longer(:)
      if (allocated(list%f)) then
         if (size(list%f) >= n) return
      end if
      allocate (longer(max(n, 16)))
      if (list%n > 0) longer(1:list%n) = list%f(1:list%n)
      call move_alloc(longer, list%f)
   end subroutine point_force_reserve

   !> Append a force to a list.
   pure subroutine point_force_add(list, segment, point, force, across_bone, arc, surface, normal_force)
      type(point_force_list_t), intent(inout) :: list
      integer, intent(in) :: segment
      real(wp), intent(in) :: point(2), force(2)
      logical, intent(in), optional :: across_bone
      integer, intent(in), optional :: arc, surface
      real(wp), intent(in), optional :: normal_force
      if (.not. allocated(list%f)) then
         call point_force_reserve(list, 16)
      else if (list%n == size(list%f)) then
         call point_force_reserve(list, 2*size(list%f))
      end if
      list%n = list%n + 1
      list%f(list%n) = point_force_t(segment=segment, point=point, force=force)
      if (present(across_bone)) list%f(list%n)%across_bone = across_bone
      if (present(arc)) list%f(list%n)%arc = arc
      if (present(surface)) list%f(list%n)%surface = surface
      if (present(normal_force)) list%f(list%n)%normal_force = normal_force
   end subroutine point_force_add
end module point_forces
