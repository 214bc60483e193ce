!> The channel-class filter of SAE J211-1 (ISO 6487): a two-pole
!! Butterworth low-pass run forward and then backward over a uniformly
!! sampled channel (phaseless, four poles in all), with the design
!! frequency of its channel frequency class (CFC). A small copy for the
!! input layer (the ISO-MME pulse, *PULSEMME): the output layer's own J211
!! module (c6_output, issue 18 section 1) cannot be used from c1_input; the
!! two are to be merged.
module cfc_filter
   use kinds, only: wp, pi
   implicit none
   private

   public :: cfc_filtered, cfc_pad_time

   !> J211-1's start-up treatment: the channel is extended at each end by
   !! at least 10 ms of samples before it is filtered, and the extension is
   !! dropped afterwards.
   real(wp), parameter :: cfc_pad_time = 0.010_wp

contains

   !> x filtered with channel class cfc (Hz; 60, 180, 600, 1000) at sampling
   !! interval dt (s). Each end is extended by cfc_pad_time of samples (at
   !! most n - 1) reflected through the end value (x(1 - k) = 2 x(1) - x(1 + k)),
   !! which keeps the level and slope at the end, so that a channel that does
   !! not start at rest gets no start-up transient; the recursion then starts
   !! at rest on the extension's first two samples (y = x).
   pure function cfc_filtered(x, dt, cfc) result(y)
      real(wp), intent(in) :: x(:), dt, cfc
      real(wp) :: y(size(x))
      real(wp), allocatable :: ext(:)
      real(wp) :: wd, wa, den, a0, a1, a2, b1, b2
      integer :: n, n_pad, k

      n = size(x)
      if (n < 3) then
         y = x
         return
      end if
      ! SAE J211-1 (1995) Appendix C: the design frequency and the two-pole
      ! coefficients (bilinear transform with prewarping)
      wd = 2.0_wp*pi*cfc*2.0775_wp
      wa = tan(wd*dt/2.0_wp)
      den = 1.0_wp + sqrt(2.0_wp)*wa + wa**2
      a0 = wa**2/den
      a1 = 2.0_wp*a0
      a2 = a0
      b1 = -2.0_wp*(wa**2 - 1.0_wp)/den
      b2 = (-1.0_wp + sqrt(2.0_wp)*wa - wa**2)/den

      n_pad = min(n - 1, max(2, ceiling(cfc_pad_time/dt - 1.0e-9_wp)))
      allocate (ext(n + 2*n_pad))
      ext(n_pad + 1:n_pad + n) = x
      do k = 1, n_pad
         ext(n_pad + 1 - k) = 2.0_wp*x(1) - x(1 + k)
         ext(n_pad + n + k) = 2.0_wp*x(n) - x(n - k)
      end do
      call pass(ext)
      ext = ext(size(ext):1:-1)
      call pass(ext)
      ext = ext(size(ext):1:-1)
      y = ext(n_pad + 1:n_pad + n)
   contains
      !> One forward pass of the two-pole recursion, in place.
      pure subroutine pass(s)
         real(wp), intent(inout) :: s(:)
         real(wp) :: out(size(s))
         integer :: i
         out(1:2) = s(1:2)
         do i = 3, size(s)
            out(i) = a0*s(i) + a1*s(i - 1) + a2*s(i - 2) + b1*out(i - 1) + b2*out(i - 2)
         end do
         s = out
      end subroutine pass
   end function cfc_filtered
end module cfc_filter
