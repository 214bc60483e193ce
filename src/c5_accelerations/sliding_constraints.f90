!> Filippov's sliding (issue 15): where an effect's force is discontinuous
!! across a surface of the state and points into it from both sides (a
!! joint's friction at its relative rate +-xi, D-4a), the motion slides on
!! the surface. Each active sliding constraint k has a direction d_k in z
!! and a multiplier lambda_k (a generalized force lambda_k d_k) that keeps
!! its sliding velocity d_k.z' + offset_k constant (c4, sliding_surface):
!! with A z''_0 = b (C.5, all other forces),
!!
!!    z'' = z''_0 + A^-1 D lambda,   D^T z'' + bias = 0
!!    =>  (D^T A^-1 D) lambda = -D^T z''_0 - bias,
!!
!! D^T A^-1 D symmetric positive definite (A is, and the directions are
!! independent). The multiplier must lie in the range [lo, hi] the law's
!! force spans across the surface; where it leaves it, the motion leaves
!! the surface (a switch the driver locates: the multiplier minus lo and
!! hi minus the multiplier).
module sliding_constraints
   use kinds, only: wp
   use model, only: n_dof
   use preliminary, only: body_constants_t
   use body_matrix, only: body_accelerations
   use lapack_interfaces, only: dpotf2, dtrsv
   implicit none
   private

   public :: sliding_multipliers, max_slides

   !> The most sliding constraints an occupant may hold at once (a joint's
   !! friction each: 7; room for the seat's).
   integer, parameter :: max_slides = 12

contains

   !> The multipliers lambda (not clipped to their ranges) of the active
   !! constraints with directions d(:, 1:k) and biases bias(1:k), given
   !! z''_0 = A^-1 b, and A^-1 d in y_cols. info /= 0: A or D^T A^-1 D is
   !! not positive definite.
   pure subroutine sliding_multipliers(bc, c, s, solver, zdd0, d, bias, lam, y_cols, info)
      type(body_constants_t), intent(in) :: bc
      real(wp), intent(in) :: c(:), s(:)
      integer, intent(in) :: solver
      real(wp), intent(in) :: zdd0(n_dof), d(:, :), bias(:)
      real(wp), intent(out) :: lam(:), y_cols(:, :)
      integer, intent(out) :: info
      real(wp) :: m(max_slides, max_slides)     ! (no allocation: D^T A^-1 D in its corner)
      integer :: i, j, k
      k = size(lam)
      info = 0
      lam = 0.0_wp
      y_cols = 0.0_wp
      do j = 1, k
         call body_accelerations(bc, c, s, d(:, j), y_cols(:, j), info, solver)
         if (info /= 0) return
      end do
      do j = 1, k
         do i = j, k
            m(i, j) = dot_product(d(:, i), y_cols(:, j))
         end do
         lam(j) = -dot_product(d(:, j), zdd0) - bias(j)
      end do
      call dpotf2('L', k, m, max_slides, info)
      if (info /= 0) return
      call dtrsv('L', 'N', 'N', k, m, max_slides, lam, 1)
      call dtrsv('L', 'T', 'N', k, m, max_slides, lam, 1)
   end subroutine sliding_multipliers
end module sliding_constraints
