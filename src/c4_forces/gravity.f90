!> Report C.4.b: the generalized gravity forces G_i = dV/dz_i, entering
!! b with a minus sign (b_i = C_i - G_i + ...).
module gravity
   use kinds, only: wp
   use model, only: n_seg, n_dof
   use preliminary, only: body_constants_t
   implicit none
   private

   public :: gravity_forces

contains

   !> Subtract G_i = g a_i cos(alpha_i) (i = 1..8), G_9 = 0, G_10 = g a_9.
   pure subroutine gravity_forces(bc, g, c, b)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: g, c(n_seg)
      real(wp), intent(inout) :: b(n_dof)
      b(1:n_seg) = b(1:n_seg) - g*bc%a(1:n_seg)*c
      b(10) = b(10) - g*bc%a(9)
   end subroutine gravity_forces
end module gravity
