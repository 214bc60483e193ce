!> A sliding constraint (issue 15; errata D-4b, D-19a): where a friction
!! force is discontinuous across a surface of the state - its sliding
!! velocity v at an edge of the dead band, +-xi - and points into the
!! surface from both sides, the motion slides on it (Filippov). A
!! generalized force lambda*d then keeps v constant:
!!
!!    v  = d.z'  + offset      (offset: the part the vehicle's motion gives)
!!    v' = d.z'' + bias = 0    (bias: the frame's and the geometry's terms)
!!
!! with lambda in [lo, hi], the range the law's force spans across the
!! surface. The occupant's solve finds lambda (c5, sliding_constraints);
!! its power lambda*d.z' is lambda*v (the friction's work, -lambda*v
!! dissipated) plus -lambda*offset (supplied by the vehicle).
module sliding_surface
   use kinds, only: wp
   use model, only: n_dof
   implicit none
   private

   public :: slide_t

   type :: slide_t
      logical :: active = .false.
      real(wp) :: d(n_dof) = 0.0_wp         !< v = d.z' + offset
      real(wp) :: offset = 0.0_wp           !< (in/s or rad/s)
      real(wp) :: bias = 0.0_wp             !< v' = d.z'' + bias
      real(wp) :: lo = 0.0_wp, hi = 0.0_wp  !< the multiplier's range (lb or in*lb)
      !> the effect's auxiliary quantities (0: none) that integrate the
      !! friction's dissipated power, -lambda*v, and the vehicle's supplied
      !! power, -lambda*offset
      integer :: aux_dissipated = 0, aux_supplied = 0
   end type slide_t
end module sliding_surface
