!> Report C.4.a: the generalized forces quadratic in the angular rates
!! (centrifugal terms), already on the right-hand side of A z'' = b.
module centrifugal
   use kinds, only: wp
   use model, only: n_seg, n_dof, hip_x, hip_y
   use preliminary, only: body_constants_t, n_pairs
   use effect_base, only: effect_t, body_state_t
   implicit none
   private

   public :: centrifugal_forces, centrifugal_effect_t, centrifugal_effect

   !> C.4.a as an effect: every scene has it.
   type, extends(effect_t) :: centrifugal_effect_t
      type(body_constants_t) :: bc
   contains
      procedure :: add_forces => centrifugal_add_forces
   end type centrifugal_effect_t

contains

   function centrifugal_effect(bc) result(e)
      type(body_constants_t), intent(in) :: bc
      type(centrifugal_effect_t) :: e
      e%name = 'centrifugal'
      e%title = 'centrifugal terms (C.4.a)'
      e%bc = bc
   end function centrifugal_effect

   pure subroutine centrifugal_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(centrifugal_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      associate (u1 => size(extra) + size(aux), u2 => size(extra_rate) + size(aux_rate))
      end associate
      call centrifugal_forces(this%bc, st%c, st%s, st%zdot, b)
   end subroutine centrifugal_add_forces

   !> Add C_1..C_10 to b. C.4.a with A_ij = alpha-dot_j**2 sin(alpha_j - alpha_i)
   !! (erratum E-Cb: no divisor) and C_1 summed over j = 2..6 (erratum E-Ca);
   !! in general C_i = sum_j coupling(i,j) A_ij, the coupling being that of
   !! figure 27. sin(alpha_j - alpha_i) = s_j c_i - c_j s_i avoids more trig.
   pure subroutine centrifugal_forces(bc, c, s, zdot, b)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(n_seg), s(n_seg), zdot(n_dof)
      real(wp), intent(inout) :: b(n_dof)
      real(wp) :: w2(n_seg), sji
      integer :: p, i, j
      w2 = zdot(1:n_seg)**2
      ! each coupled pair (i, j) adds to C_i and, with the opposite sine, to C_j
      do p = 1, n_pairs
         i = bc%pair_i(p)
         j = bc%pair_j(p)
         sji = bc%pair_c(p)*(s(j)*c(i) - c(j)*s(i))
         b(i) = b(i) + sji*w2(j)
         b(j) = b(j) - sji*w2(i)
      end do
      ! C_9, C_10
      b(hip_x) = b(hip_x) + sum(bc%a(1:n_seg)*w2*c)
      b(hip_y) = b(hip_y) + sum(bc%a(1:n_seg)*w2*s)
   end subroutine centrifugal_forces
end module centrifugal
