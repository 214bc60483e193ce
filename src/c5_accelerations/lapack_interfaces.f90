!> Explicit interfaces to the LAPACK and BLAS routines hsri2d calls, so
!! that every call is checked at compile time. LAPACK's info stays at this
!! interface: its one caller (body_matrix's body_accelerations) maps a
!! non-zero info to its outcome there (A not positive definite, an outcome
!! of the right-hand side's evaluation; docs/architecture.md, "Errors").
module lapack_interfaces
   implicit none
   private

   public :: dpotf2, dtrsv

   integer, parameter :: real64_kind = kind(1.0d0)

   ! Declared pure as fortran-lang/stdlib does: the routines have no side
   ! effects for valid arguments, and hsri2d passes only valid ones.
   interface
      !> LAPACK: Cholesky factorization A = L L**T, unblocked.
      pure subroutine dpotf2(uplo, n, a, lda, info)
         import :: real64_kind
         character(len=1), intent(in) :: uplo
         integer, intent(in) :: n, lda
         real(real64_kind), intent(inout) :: a(lda, *)
         integer, intent(out) :: info
      end subroutine dpotf2

      !> BLAS: solve a triangular system in place (what LAPACK's dpotrs does
      !! for one right-hand side).
      pure subroutine dtrsv(uplo, trans, diag, n, a, lda, x, incx)
         import :: real64_kind
         character(len=1), intent(in) :: uplo, trans, diag
         integer, intent(in) :: n, lda, incx
         real(real64_kind), intent(in) :: a(lda, *)
         real(real64_kind), intent(inout) :: x(*)
      end subroutine dtrsv
   end interface
end module lapack_interfaces
