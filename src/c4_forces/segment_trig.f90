!> The cosines and sines of the eight segment angles (section B), the same
!! bits in every build.
!!
!! The Release build vectorizes cos and sin of an array of known length
!! and calls the vector library (libmvec), whose results differ from the
!! scalar cos and sin in their last bits; the Debug build, at -O0, called
!! the scalar ones, and the runs of the two builds (whose events fall on
!! accepted steps) parted in their late digits: seven archived listings
!! did not reproduce under Release. This one file is compiled with -O2 in
!! every build (src/CMakeLists.txt), so both take the vector library's
!! values and the listings of Release and Debug are the same bytes
!! (docs/validation.md, "Reproducing an archived run"). Scalar calls in
!! both would cost the body alone 13 % (docs/performance.md).
module segment_trig
   use kinds, only: wp
   use model, only: n_seg
   implicit none
   private

   public :: segment_cos_sin

contains

   !> c = cos(z), s = sin(z) for the n_seg angles.
   pure subroutine segment_cos_sin(z, c, s)
      real(wp), intent(in) :: z(n_seg)
      real(wp), intent(out) :: c(n_seg), s(n_seg)
      c = cos(z)
      s = sin(z)
   end subroutine segment_cos_sin
end module segment_trig
