!> The right-hand side integrated by C.3: the state y = (z, z', W) holds the
!! ten generalized coordinates, their rates and, for each joint with
!! friction, the work dissipated there (an exact integral of the friction
!! power, for the energy accounting of C.6). f = (z', z'', P) with z''
!! from A z'' = b (C.4, C.5).
module equations_of_motion
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp, i8
   use model, only: model_t, n_dof, n_seg
   use preliminary, only: body_constants_t
   use generalized_forces, only: scene_t, force_counts_t, generalized_force_vector
   use body_matrix, only: body_accelerations, body_structure_matches, solver_structured, solver_dense
   use ode_system, only: ode_system_t
   implicit none
   private

   public :: body_system_t, body_system_init, state_size, rhs_status_text
   public :: rhs_not_positive_definite, rhs_not_finite, rhs_diverged

   integer, parameter :: rhs_not_positive_definite = 1
   integer, parameter :: rhs_not_finite = 2
   integer, parameter :: rhs_diverged = 3

   !> Bounds of any physical state (rad, in, rad/s, in/s). A state beyond
   !! them means the integration has diverged; stopping there, before any
   !! arithmetic can overflow, lets the run end with a message (and keeps
   !! Debug builds, which trap overflow, from crashing).
   real(wp), parameter :: max_angle = 1.0e4_wp, max_position = 1.0e7_wp
   real(wp), parameter :: max_rate = 1.0e6_wp, max_speed = 1.0e8_wp

   !> The body in its scene. Read-only during a run except the counters.
   type, extends(ode_system_t) :: body_system_t
      type(model_t) :: m
      type(body_constants_t) :: bc
      type(scene_t) :: scene
      type(force_counts_t) :: counts
      integer(i8) :: evaluations = 0
      real(wp) :: last_t = 0.0_wp       !< time of the last evaluation (for messages)
      !> how A z'' = b is solved (C.5): figure 27's structured Cholesky, or
      !! LAPACK for bodies coupled otherwise (body_matrix)
      integer :: solver = solver_structured
   contains
      procedure :: rhs => body_rhs
   end type body_system_t

contains

   subroutine body_system_init(sys, m, bc, scene)
      type(body_system_t), intent(out) :: sys
      type(model_t), intent(in) :: m
      type(body_constants_t), intent(in) :: bc
      type(scene_t), intent(in) :: scene
      sys%m = m
      sys%bc = bc
      sys%scene = scene
      if (.not. body_structure_matches(bc)) sys%solver = solver_dense
   end subroutine body_system_init

   !> Length of y for a scene: z, z' and one work integral per friction joint.
   pure integer function state_size(scene)
      type(scene_t), intent(in) :: scene
      state_size = 2*n_dof + scene%n_aux
   end function state_size

   subroutine body_rhs(this, t, y, dydt, status)
      class(body_system_t), intent(inout) :: this
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: status
      real(wp) :: c(n_seg), s(n_seg), b(n_dof), zdd(n_dof)
      integer :: info

      this%evaluations = this%evaluations + 1
      this%last_t = t
      if (.not. physical(y)) then
         dydt = 0.0_wp
         status = rhs_diverged
         return
      end if
      c = cos(y(1:n_seg))
      s = sin(y(1:n_seg))
      call generalized_force_vector(this%scene, this%m, this%bc, c, s, y(1:n_dof), &
                                    y(n_dof + 1:2*n_dof), b, dydt(2*n_dof + 1:), this%counts)
      call body_accelerations(this%bc, c, s, b, zdd, info, this%solver)
      dydt(1:n_dof) = y(n_dof + 1:2*n_dof)
      dydt(n_dof + 1:2*n_dof) = zdd
      if (info /= 0) then
         status = rhs_not_positive_definite
      else if (.not. all(ieee_is_finite(zdd))) then
         status = rhs_not_finite
      else
         status = 0
      end if
   end subroutine body_rhs

   !> Finite, and within the bounds of any physical state.
   pure logical function physical(y)
      real(wp), intent(in) :: y(:)
      physical = all(ieee_is_finite(y))
      if (.not. physical) return
      physical = all(abs(y(1:n_seg)) <= max_angle) .and. all(abs(y(n_seg + 1:n_dof)) <= max_position) &
                 .and. all(abs(y(n_dof + 1:n_dof + n_seg)) <= max_rate) &
                 .and. all(abs(y(n_dof + n_seg + 1:2*n_dof)) <= max_speed)
   end function physical

   pure function rhs_status_text(status) result(text)
      integer, intent(in) :: status
      character(len=:), allocatable :: text
      select case (status)
      case (rhs_not_positive_definite)
         text = 'the body matrix A (figure 27) is not positive definite (a Cholesky pivot is not positive and finite)'
      case (rhs_not_finite)
         text = 'the accelerations are not finite'
      case (rhs_diverged)
         text = 'the state left every physical range (|angle| > 1e4 rad, |rate| > 1e6 rad/s, ' &
                //'|hip| > 1e7 in or |hip speed| > 1e8 in/s): the integration diverged; try a smaller DT'
      case default
         text = 'unknown right-hand-side failure'
      end select
   end function rhs_status_text
end module equations_of_motion
