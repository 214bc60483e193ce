!> Report C.4.c, joint friction: the Coulomb torque J-hat = C'_i sgn(alpha-
!! dot_m - alpha-dot_i) once the relative rate reaches xi_i, zero below it
!! (the dead band; docs/errata.md D-4). The work each joint dissipates,
!! C'_i |relative rate|, is integrated with the motion (an auxiliary
!! quantity per joint; erratum E-64), so the energy balance of C.6 closes to
!! the integration error.
!!
!! Each joint's sliding direction (-1, 0, +1: sgn of the relative rate
!! beyond the dead band) is memory, decided on accepted steps with a
!! restart when it changes (D-4a), as the seat's hip decides its own
!! (D-19): within a step the torque does not jump.
!! Decided at every evaluation, a torque that switches at |rate| = xi
!! inside trial steps made an adaptive stepper resolve every crossing:
!! Dormand-Prince took 1.5 million steps, down to 1e-10 s, for the belted
!! sled deck, and 475 with the direction held.
module joint_friction
   use kinds, only: wp
   use model, only: n_dof, n_joint, joint_partner
   use effect_base, only: effect_t, body_state_t, slide_t
   use effect_events, only: accept_result_t
   use effect_energies, only: energy_dissipated, n_energy_kinds
   use dead_band, only: slip_of, edge_at, edge_range, slip_released
   use output_series, only: output_series_t
   use joint_coupling, only: per_joint_series, joint_list_text
   implicit none
   private

   public :: joint_friction_t, joint_friction_effect

   type, extends(effect_t) :: joint_friction_t
      integer, allocatable :: joints(:)          !< joints with C' > 0
      real(wp) :: c_friction(n_joint) = 0.0_wp
      real(wp) :: xi(n_joint) = 0.0_wp
      !> each joint's sliding direction, sgn(alpha-dot_i - alpha-dot_m) beyond
      !! the dead band, else 0 (memory: decided in accept, D-4a)
      integer :: slip(n_joint) = 0
      !> each joint held on an edge of its dead band (issue 15, D-4b): 0
      !! not, +1 at w = +xi, -1 at w = -xi (both at w = 0 when xi = 0)
      integer :: edge(n_joint) = 0
   contains
      procedure :: add_forces => friction_add_forces
      procedure :: accept => friction_accept
      procedure :: switches => friction_switches
      procedure :: slides => friction_slides
      procedure :: release => friction_release
      procedure :: energy => friction_energy
      procedure :: outputs => friction_outputs
      procedure :: output_values => friction_output_values
      procedure :: describe => friction_describe
   end type joint_friction_t

contains

   !> The friction of the joints with C' > 0; zdot0 (the initial rates,
   !! zero when absent) gives each joint's sliding direction at t = 0.
   function joint_friction_effect(c_friction, xi, zdot0) result(e)
      real(wp), intent(in) :: c_friction(n_joint), xi(n_joint)
      real(wp), intent(in), optional :: zdot0(n_dof)
      type(joint_friction_t) :: e
      integer :: i
      e%name = 'joint_friction'
      e%title = 'joint friction (C.4.c)'
      e%c_friction = c_friction
      e%xi = xi
      allocate (e%joints(count(c_friction > 0.0_wp)))
      e%joints(:) = pack([(i, i=1, n_joint)], c_friction > 0.0_wp)
      e%n_aux = size(e%joints)
      e%has_energy(energy_dissipated) = .true.
      e%has_memory = size(e%joints) > 0
      e%n_switch = 2*size(e%joints)
      e%n_slide = size(e%joints)
      if (present(zdot0)) e%slip = slips(e, zdot0)
   end function joint_friction_effect

   !> The sliding direction of every joint with friction at the rates zdot:
   !! C.4.c's torque is -C' times it, -C' sgn(w) once |w| reaches xi, none
   !! below - and none at w = 0 even when xi = 0 (Fortran's sign(C', 0) is
   !! +C': a torque without motion, outside the energy balance; slip_of).
   pure function slips(this, zdot) result(slip)
      class(joint_friction_t), intent(in) :: this
      real(wp), intent(in) :: zdot(n_dof)
      integer :: slip(n_joint)
      integer :: n, i
      slip = 0
      do n = 1, size(this%joints)
         i = this%joints(n)
         slip(i) = slip_of(this%xi(i), zdot(i) - zdot(joint_partner(i)))
      end do
   end function slips

   !> D-4a: the sliding directions at the accepted state; a change makes the
   !! right-hand side jump, and the stepper restarts.
   subroutine friction_accept(this, st, extra, aux, result)
      class(joint_friction_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      integer :: slip(n_joint)
      integer :: n, i, edge
      real(wp) :: w
      associate (u1 => size(extra) + size(aux))
      end associate
      slip = slips(this, st%zdot)
      do n = 1, size(this%joints)
         i = this%joints(n)
         if (this%edge(i) /= 0 .or. slip(i) == this%slip(i)) cycle
         result%restart = .true.
         w = st%zdot(i) - st%zdot(joint_partner(i))
         edge = edge_at(this%xi(i), w)
         if (edge /= 0) then
            ! on an edge of the dead band (a located switch): held there,
            ! the torque the motion needs found by the solve; the release
            ! decides the side it leaves by (D-4b)
            this%edge(i) = edge
            this%slip(i) = 0
         else
            this%slip(i) = slip(i)      ! (a switch not located: the direction at the accepted state)
         end if
      end do
   end subroutine friction_accept

   !> D-4b (issue 15): a joint held on an edge of its dead band slides
   !! there, its relative rate constant; the torque lies between the
   !! law's on the two sides: [-C', 0] at +xi, [0, C'] at -xi, [-C', C']
   !! at xi = 0 (Coulomb's sticking). Its power is dissipated (aux n).
   pure subroutine friction_slides(this, st, extra, aux, s)
      class(joint_friction_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(slide_t), intent(out) :: s(:)
      integer :: n, i
      associate (u1 => size(extra) + size(aux), u2 => st%t)
      end associate
      do n = 1, size(this%joints)
         i = this%joints(n)
         s(n)%active = this%edge(i) /= 0
         if (.not. s(n)%active) cycle
         ! the relative rate alpha-dot_i - alpha-dot_m: no offset, no bias
         s(n)%d(i) = 1.0_wp
         s(n)%d(joint_partner(i)) = -1.0_wp
         s(n)%aux_dissipated = n
         call edge_range(this%xi(i), this%edge(i), this%c_friction(i), s(n)%lo, s(n)%hi)
      end do
   end subroutine friction_slides

   !> Joint n leaves its edge: the torque the motion needed reached the
   !! law's on one side (D-4b): -C' (at_upper false) is sliding forward,
   !! +C' sliding backward, 0 the dead band.
   subroutine friction_release(this, k, at_upper)
      class(joint_friction_t), intent(inout) :: this
      integer, intent(in) :: k
      logical, intent(in) :: at_upper
      integer :: i
      i = this%joints(k)
      this%slip(i) = slip_released(this%xi(i), this%edge(i), at_upper)
      this%edge(i) = 0
   end subroutine friction_release

   !> Issue 15: each joint's sliding direction changes where its relative
   !! rate w crosses +xi or -xi (slip_of): w - xi and w + xi. (With xi = 0
   !! both are w, which changes sign where the direction reverses.)
   pure subroutine friction_switches(this, st, extra, aux, g)
      class(joint_friction_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      integer :: n, i
      real(wp) :: w
      associate (u1 => size(extra) + size(aux))
      end associate
      do n = 1, size(this%joints)
         i = this%joints(n)
         w = st%zdot(i) - st%zdot(joint_partner(i))
         g(2*n - 1) = w - this%xi(i)
         g(2*n) = w + this%xi(i)
         ! held on an edge: it leaves by its torque's range (the occupant's
         ! sliding switches), not by w, which stays on the edge
         if (this%edge(i) /= 0) g(2*n - 1:2*n) = 1.0_wp
      end do
   end subroutine friction_switches

   pure subroutine friction_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(joint_friction_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      integer :: n, i, m
      real(wp) :: w, tau
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate))
      end associate
      do n = 1, size(this%joints)
         i = this%joints(n)
         m = joint_partner(i)
         w = st%zdot(i) - st%zdot(m)
         ! the direction held since the last accepted step (D-4a); a joint
         ! held on an edge has slip 0 here, its torque the solve's (D-4b)
         tau = -this%c_friction(i)*real(this%slip(i), wp)
         b(i) = b(i) + tau
         b(m) = b(m) - tau
         aux_rate(n) = -tau*w      ! power dissipated (>= 0 but where the rate turns within a step)
      end do
   end subroutine friction_add_forces

   pure subroutine friction_energy(this, st, extra, aux, e)
      class(joint_friction_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      associate (u1 => this%name, u2 => st%t, u3 => size(extra))
      end associate
      e = 0.0_wp
      e(energy_dissipated) = sum(aux)
   end subroutine friction_energy

   function friction_outputs(this) result(series)
      class(joint_friction_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      associate (unused => this%name)
      end associate
      series = per_joint_series('work', 'JOINT FRICTION WORK DISSIPATED', &
                                'work dissipated by each joint''s friction since t = 0 (C.6, erratum E-64)')
   end function friction_outputs

   pure subroutine friction_output_values(this, item, st, extra, aux, values)
      class(joint_friction_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      integer :: n
      associate (u1 => item, u2 => st%t, u3 => size(extra))
      end associate
      values = 0.0_wp
      do n = 1, size(this%joints)
         values(this%joints(n)) = aux(n)
      end do
   end subroutine friction_output_values

   function friction_describe(this) result(text)
      class(joint_friction_t), intent(in) :: this
      character(len=:), allocatable :: text
      text = trim(this%title)//': '//joint_list_text(this%joints)
   end function friction_describe
end module joint_friction
