!> The channel filter of SAE J211-1 (March 1995, Appendix C; ISO 6487
!! gives the same filter): a two-pole low-pass Butterworth, designed by the
!! bilinear transform, run over the data forward and then backward, so that
!! the result has no phase shift and four poles in all. Its channel
!! frequency class (CFC 1000, 600, 180, 60) sets the design frequency.
!! The report (1974) predates the standard; docs/injury.md says what is
!! filtered, where the start-up comes from and how the filter is tested.
!!
!! J211-1 Appendix C, per class and sampling interval T (s):
!!
!!     omega_d = 2 pi CFC 2.0775
!!     omega_a = sin(omega_d T/2) / cos(omega_d T/2)
!!     a0 = omega_a^2 / (1 + sqrt2 omega_a + omega_a^2),  a1 = 2 a0,  a2 = a0
!!     b1 = -2 (omega_a^2 - 1) / (1 + sqrt2 omega_a + omega_a^2)
!!     b2 = (-1 + sqrt2 omega_a - omega_a^2) / (1 + sqrt2 omega_a + omega_a^2)
!!     Y(t) = a0 X(t) + a1 X(t-1) + a2 X(t-2) + b1 Y(t-1) + b2 Y(t-2)
!!
!! Start-up (J211-1 asks for pre-event data, at least 10 ms, so that the
!! filter starts settled): a simulation has no data before its start, so
!! each end of the record is extended by its point reflection (x(-k) =
!! 2 x(0) - x(k); likewise after the end), which continues the signal's
!! value and slope, over 10 ms or, where longer, the time the filter's
!! start transient takes to fall to 1e-13 of itself (its poles' radius
!! sqrt(-b2) per sample: 50 ms at CFC 60, 17 ms at CFC 180; a record
!! shorter than that is carried on beyond its reflection by its mean
!! slope), and each pass
!! starts in the steady state of the first value it meets. A constant or a
!! ramp then passes unchanged from the first sample to the last
!! (test_channel_filter), where a zero start would ring from a step of the
!! signal's whole initial level.
module channel_filter
   use kinds, only: wp, pi
   implicit none
   private

   public :: cfc_coefficients_t, cfc_coefficients, cfc_filter, cfc_gain, cfc_padding

   !> J211-1's design-frequency factor: omega_d = 2 pi CFC 2.0775.
   real(wp), parameter :: design_factor = 2.0775_wp
   !> The start-up padding at each end (s): J211-1's 10 ms of pre-event data.
   real(wp), parameter :: cfc_padding = 0.010_wp

   !> The two-pole section's coefficients (J211-1 Appendix C).
   type :: cfc_coefficients_t
      real(wp) :: a0 = 0.0_wp, a1 = 0.0_wp, a2 = 0.0_wp, b1 = 0.0_wp, b2 = 0.0_wp
      real(wp) :: omega_a = 0.0_wp   !< the prewarped design frequency tan(omega_d T/2)
   end type cfc_coefficients_t

contains

   !> The coefficients for channel class cfc (Hz) at sampling interval dt (s).
   pure function cfc_coefficients(cfc, dt) result(k)
      real(wp), intent(in) :: cfc, dt
      type(cfc_coefficients_t) :: k
      real(wp) :: wd, wa, den
      wd = 2.0_wp*pi*cfc*design_factor                    ! J211-1 App. C, omega_d
      wa = sin(wd*dt/2.0_wp)/cos(wd*dt/2.0_wp)            ! omega_a
      den = 1.0_wp + sqrt(2.0_wp)*wa + wa*wa
      k%a0 = wa*wa/den
      k%a1 = 2.0_wp*k%a0
      k%a2 = k%a0
      k%b1 = -2.0_wp*(wa*wa - 1.0_wp)/den
      k%b2 = (-1.0_wp + sqrt(2.0_wp)*wa - wa*wa)/den
      k%omega_a = wa
   end function cfc_coefficients

   !> The amplitude gain of the forward-and-backward filter at frequency f
   !! (Hz), in closed form: the bilinear transform maps the two-pole
   !! Butterworth's |H|^2 = 1/(1 + (Omega/omega_a)^4) to Omega = tan(pi f T),
   !! and the two passes multiply H by its conjugate (no phase).
   pure real(wp) function cfc_gain(cfc, dt, f) result(gain)
      real(wp), intent(in) :: cfc, dt, f
      type(cfc_coefficients_t) :: k
      k = cfc_coefficients(cfc, dt)
      gain = 1.0_wp/(1.0_wp + (tan(pi*f*dt)/k%omega_a)**4)
   end function cfc_gain

   !> x filtered at class cfc (Hz), sampled every dt (s), into y (the same
   !! size): forward, then backward, over the record extended at both ends
   !! by its point reflection (cfc_padding; the module's header). padding
   !! (s): the extension exactly that long instead (test_channel_filter's
   !! J211 minimum of 10 ms, where the settled start shows).
   pure subroutine cfc_filter(x, cfc, dt, y, padding)
      real(wp), intent(in) :: x(:), cfc, dt
      real(wp), intent(out) :: y(:)
      real(wp), intent(in), optional :: padding
      type(cfc_coefficients_t) :: k
      real(wp), allocatable :: w(:)
      real(wp) :: slope
      integer :: n, n_pad, i
      n = size(x)
      if (n == 0) return
      if (n == 1) then
         y = x
         return
      end if
      k = cfc_coefficients(cfc, dt)
      ! J211-1's 10 ms, or the samples in which the transient falls to 1e-13
      n_pad = max(1, nint(cfc_padding/dt), ceiling(log(1.0e-13_wp)/log(sqrt(-k%b2))))
      if (present(padding)) n_pad = max(1, nint(padding/dt))
      allocate (w(1 - n_pad:n + n_pad))
      w(1:n) = x
      slope = (x(n) - x(1))/real(n - 1, wp)
      do i = 1, n_pad
         if (i <= n - 1) then
            w(1 - i) = 2.0_wp*x(1) - x(1 + i)
            w(n + i) = 2.0_wp*x(n) - x(n - i)
         else
            ! (a record shorter than the padding: its mean slope carried on)
            w(1 - i) = w(2 - i) - slope
            w(n + i) = w(n + i - 1) + slope
         end if
      end do
      call pass(w, 1)
      call pass(w, -1)
      y = w(1:n)
   contains
      !> One pass of the two-pole section over w, forward (dir 1) or
      !! backward (-1), in place, starting settled at its first value.
      pure subroutine pass(w, dir)
         real(wp), intent(inout) :: w(:)
         integer, intent(in) :: dir
         real(wp) :: x1, x2, y1, y2, x0, y0
         integer :: j, first, last
         if (dir > 0) then
            first = 1
            last = size(w)
         else
            first = size(w)
            last = 1
         end if
         x1 = w(first)
         x2 = x1
         y1 = x1
         y2 = x1
         do j = first, last, dir
            x0 = w(j)
            y0 = k%a0*x0 + k%a1*x1 + k%a2*x2 + k%b1*y1 + k%b2*y2   ! J211-1 App. C
            x2 = x1
            x1 = x0
            y2 = y1
            y1 = y0
            w(j) = y0
         end do
      end subroutine pass
   end subroutine cfc_filter
end module channel_filter
