!> Report C.4.b: the generalized gravity forces G_i = dV/dz_i, entering
!! b with a minus sign (b_i = C_i - G_i + ...).
module gravity
   use kinds, only: wp
   use segment_trig, only: segment_cos_sin
   use model, only: n_seg, n_dof, hip_y
   use preliminary, only: body_constants_t
   use model, only: body_section_t
   use effect_base, only: effect_t, body_state_t
   use effect_energies, only: energy_stored, n_energy_kinds
   use point_forces, only: point_force_list_t, point_force_add
   use body_kinematics, only: link_cos_sin, cg_positions
   implicit none
   private

   public :: gravity_forces, gravity_effect_t, gravity_effect

   !> C.4.b as an effect, present when g > 0.
   type, extends(effect_t) :: gravity_effect_t
      type(body_constants_t) :: bc
      type(body_section_t) :: body          !< for the centres of gravity (point forces)
      real(wp) :: g = 0.0_wp
      real(wp) :: s0(n_seg) = 0.0_wp   !< sin(alpha_i) at t = 0
      real(wp) :: y0 = 0.0_wp          !< y_h at t = 0
   contains
      procedure :: add_forces => gravity_add_forces
      procedure :: energy => gravity_energy
      procedure :: point_forces => gravity_point_forces
      procedure :: frame_values => gravity_frame_values
   end type gravity_effect_t

contains

   !> z0: the initial generalized coordinates (the energy is measured from them).
   function gravity_effect(bc, body, g, z0) result(e)
      type(body_constants_t), intent(in) :: bc
      type(body_section_t), intent(in) :: body
      real(wp), intent(in) :: g, z0(n_dof)
      type(gravity_effect_t) :: e
      real(wp) :: c0(n_seg)
      e%name = 'gravity'
      e%title = 'gravity (C.4.b)'
      e%external = .true.
      e%bc = bc
      e%body = body
      e%g = g
      call segment_cos_sin(z0(1:n_seg), c0, e%s0)      ! (segment_trig: the same bits in every build)
      e%y0 = z0(hip_y)
      e%has_energy(energy_stored) = .true.
   end function gravity_effect

   pure subroutine gravity_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(gravity_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate) + size(aux_rate))
      end associate
      call gravity_forces(this%bc, this%g, st%c, b)
   end subroutine gravity_add_forces

   !> Subtract G_i = g a_i cos(alpha_i) (i = 1..8), G_9 = 0, G_10 = g a_9.
   pure subroutine gravity_forces(bc, g, c, b)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: g, c(n_seg)
      real(wp), intent(inout) :: b(n_dof)
      b(1:n_seg) = b(1:n_seg) - g*bc%a(1:n_seg)*c
      b(hip_y) = b(hip_y) - g*bc%a(9)
   end subroutine gravity_forces

   !> -m_i g (inertial vertical) at each centre of gravity (C.4.b).
   pure subroutine gravity_point_forces(this, st, extra, aux, list)
      class(gravity_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      real(wp) :: c(n_seg), s(n_seg), p(2, n_seg)
      integer :: i
      associate (u1 => size(extra) + size(aux))
      end associate
      ! (each angle's cosine and sine taken once and the chain walked once:
      ! the bits of segment_cg_state's, as gravity_frame_values; the FMVSS
      ! table's loads ask for these at every accepted step)
      call link_cos_sin(st%z(1:n_seg), c, s)
      p = cg_positions(this%body, st%z, c, s)
      ! C.4.b: the weight m_i g of each segment at its centre of gravity
      do i = 1, n_seg
         call point_force_add(list, i, p(:, i), [0.0_wp, -this%body%mass(i)*this%g], across_bone=.false.)
      end do
   end subroutine gravity_point_forces

   !> A print time's frame (effect_t's frame_values): the energy, G, and the
   !! point forces with the centres of gravity walked once (cg_positions,
   !! from each angle's cosine and sine taken once, the bits of
   !! segment_cg_state's): the same bits as gravity_energy,
   !! gravity_add_forces and gravity_point_forces. Gravity has no series of
   !! its own.
   pure subroutine gravity_frame_values(this, st, extra, aux, e, values, at, width, gf, b, pf, list, sums, b_sum)
      class(gravity_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      real(wp), intent(inout) :: values(:)
      integer, intent(in) :: at(:), width(:)
      logical, intent(in) :: gf, pf, sums
      real(wp), intent(inout) :: b(n_dof), b_sum(n_dof)
      type(point_force_list_t), intent(inout) :: list
      real(wp) :: c(n_seg), s(n_seg), p(2, n_seg)
      integer :: i
      associate (u1 => size(values) + size(at) + size(width))
      end associate
      call gravity_energy(this, st, extra, aux, e)
      if (gf) call gravity_forces(this%bc, this%g, st%c, b)
      if (pf) then
         call link_cos_sin(st%z(1:n_seg), c, s)
         p = cg_positions(this%body, st%z, c, s)
         ! C.4.b: the weight m_i g of each segment at its centre of gravity
         do i = 1, n_seg
            call point_force_add(list, i, p(:, i), [0.0_wp, -this%body%mass(i)*this%g], across_bone=.false.)
         end do
      end if
      if (sums) call gravity_forces(this%bc, this%g, st%c, b_sum)
   end subroutine gravity_frame_values

   !> The potential whose gradient is G (C.4.b): V = g (a_9 y_h + sum a_i sin
   !! alpha_i), which is g times the sum of m_i times the inertial height of
   !! each centre of gravity (erratum E-63), measured from t = 0.
   pure subroutine gravity_energy(this, st, extra, aux, e)
      class(gravity_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      associate (u1 => size(extra) + size(aux))
      end associate
      e = 0.0_wp
      e(energy_stored) = this%g*(this%bc%a(9)*(st%z(hip_y) - this%y0) + sum(this%bc%a(1:n_seg)*(st%s - this%s0)))
   end subroutine gravity_energy
end module gravity
