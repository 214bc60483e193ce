!> The injury criteria a crash engineer of today judges a run by, from the
!! channels filtered as SAE J211-1 specifies (channel_filter), and the
!! summary's table "FMVSS 208 (50th male)" (49 CFR 571.208 S6): criterion,
!! value, limit, time, pass or fail (issue 18; docs/injury.md). The report
!! (1974) predates both.
!!
!! The channels (channel_record, 10 kHz; the head's 20 kHz) are filled at the run's accepted
!! steps; at its end each is filtered at its class and the criteria are
!! taken from the filtered samples:
!!
!! - head: acceleration vector (g), CFC 1000: HIC15, HIC36 (every window
!!   of the grid, acceleration_criteria), GSI;
!! - chest: acceleration vector (g), CFC 180: the cumulative 3 ms clip
!!   (FMVSS 208 S6.3), GSI;
!! - neck (where kept): axial force (N, + tension) and flexion/extension
!!   moment (N m, + flexion) at the neck joint, CFC 600: Nij (S6.6(a)) and
!!   the peaks of tension and compression (S6.6(b));
!! - femur (where kept): the thigh's axial force (N, + compression), CFC
!!   600 (S6.5);
!! - chest deflection (where an effect deflects the chest's material 12):
!!   mm, CFC 180 (S6.4), and the viscous
!!   criterion VC = max of 1.3 V(t) D(t)/0.229 m (deflection rate times
!!   the deflection over the 50th male's chest depth; no FMVSS 208 limit).
!!
!! - belts (where an HDF5 file or an ISO-MME data set is written): each
!!   belt section's tension (N), CFC 60, for those outputs only (no
!!   criterion reads it).
!!
!! A channel the model does not give is "not available" (NaN in HDF5,
!! "n/a" in the listing), never a made-up number. The components are the
!! vectors' in the ground frame of z; the resultant is taken after
!! filtering each component, as J211-1 does for a triaxial accelerometer.
module fmvss_table
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: wp, g_std, pound_force_n
   use model, only: fmvss_limits_t
   use channel_record, only: channel_record_t
   use channel_filter, only: cfc_filter
   use body_state, only: body_state_t
   use occupant, only: occupant_t
   use output_series, only: output_series_t
   use vehicle_motion, only: vehicle_motion_t, vehicle_state_at
   use acceleration_criteria, only: acceleration_criteria_t, hic_result_t, criteria_new
   implicit none
   private

   public :: fmvss_channels_t, fmvss_row_t, fmvss_rows, fmvss_n_rows, nij_of, belt_channel_t
   public :: fmvss_belts_reserve, fmvss_belts_sample, vehicle_channel
   public :: cfc_head, cfc_chest, cfc_neck, cfc_femur, cfc_deflection, cfc_belt, cfc_vehicle
   public :: r_hic15, r_hic36, r_head_gsi, r_clip3ms, r_chest_gsi, r_chest_deflection, r_vc, r_nij, &
      r_neck_tension, r_neck_compression, r_femur

   !> The table's rows, in order.
   integer, parameter :: r_hic15 = 1, r_hic36 = 2, r_head_gsi = 3, r_clip3ms = 4, r_chest_gsi = 5, &
      r_chest_deflection = 6, r_vc = 7, r_nij = 8, r_neck_tension = 9, r_neck_compression = 10, r_femur = 11, &
      fmvss_n_rows = 11

   !> The channel classes of SAE J211-1 (Hz) FMVSS 208 and Part 572 name.
   real(wp), parameter :: cfc_head = 1000.0_wp, cfc_chest = 180.0_wp, cfc_neck = 600.0_wp, cfc_femur = 600.0_wp, &
      cfc_deflection = 180.0_wp
   !> SAE J211-1 Appendix E's classes of a seat belt's load and of a
   !! vehicle's structural acceleration (integrated to its velocity and
   !! displacement): CFC 60.
   real(wp), parameter :: cfc_belt = 60.0_wp, cfc_vehicle = 60.0_wp
   !> The most columns of a belt effect's force series (its sections).
   integer, parameter :: max_belt_columns = 8

   !> Nij's critical intercepts, FMVSS 208 S6.6(a) (50th male, in-position):
   !! tension, compression (N), flexion, extension (N m).
   real(wp), parameter :: fzc_tension = 6806.0_wp, fzc_compression = 6160.0_wp, &
      myc_flexion = 310.0_wp, myc_extension = 135.0_wp
   !> VC's chest depth (m) and scale factor (Lau and Viano; the 50th male).
   real(wp), parameter :: vc_depth = 0.229_wp, vc_scale = 1.3_wp

   !> One belt section's tension (N), sampled at the accepted steps.
   type :: belt_channel_t
      character(len=24) :: effect_name = ' '         !< the belt effect's (lap_belt, torso_belt)
      character(len=16) :: section = ' '             !< the section's label (lap, lap_a, torso2, ...)
      integer :: effect = 0                          !< its index in the occupant's effects
      integer :: item = 0                            !< its effect's 'force' series
      integer :: column = 0, n_columns = 0           !< the section's column of it, and its width
      type(channel_record_t) :: rec
   end type belt_channel_t

   !> An occupant's channels, sampled at its accepted steps.
   type :: fmvss_channels_t
      !> the table is made (a run whose outputs go somewhere: run_loop)
      logical :: kept = .false.
      type(channel_record_t) :: head, chest          !< acceleration vectors (g)
      logical :: neck_kept = .false., femur_kept = .false., deflection_kept = .false.
      type(channel_record_t) :: neck                 !< axial force (N, + tension), moment (N m, + flexion)
      type(channel_record_t) :: femur                !< axial force (N, + compression)
      type(channel_record_t) :: deflection           !< chest deflection (mm)
      !> each belt section's tension, kept where an output takes it (HDF5,
      !! ISO-MME: fmvss_belts_reserve)
      logical :: belts_kept = .false.
      type(belt_channel_t), allocatable :: belts(:)
   end type fmvss_channels_t

   !> One row of the table.
   type :: fmvss_row_t
      character(len=24) :: name = ' '                !< HDF5 column
      character(len=28) :: label = ' '               !< the listing's
      character(len=8) :: unit = ' '
      character(len=8) :: channel = ' '              !< the filter class, 'CFC 1000'
      logical :: available = .false.                 !< the model gives it
      real(wp) :: value = 0.0_wp
      real(wp) :: t = 0.0_wp, t_end = 0.0_wp         !< when (HIC: its window)
      logical :: window = .false.                    !< t to t_end is a window (HIC's)
      logical :: has_limit = .false.
      real(wp) :: limit = 0.0_wp
      logical :: has_unfiltered = .false.
      real(wp) :: unfiltered = 0.0_wp                !< the accepted steps' unfiltered value
   end type fmvss_row_t

contains

   !> The table from an occupant's channels, its limits and the unfiltered
   !! criteria of its accepted steps (head_u, chest_u), which stand beside
   !! the filtered ones.
   function fmvss_rows(ch, lim, head_u, chest_u) result(rows)
      type(fmvss_channels_t), intent(in) :: ch
      type(fmvss_limits_t), intent(in) :: lim
      type(acceleration_criteria_t), intent(in) :: head_u, chest_u
      type(fmvss_row_t) :: rows(fmvss_n_rows)
      type(acceleration_criteria_t) :: head_f, chest_f
      type(hic_result_t) :: hic
      real(wp), allocatable :: f(:, :), t(:)
      real(wp) :: nan
      nan = ieee_value(0.0_wp, ieee_quiet_nan)
      rows(r_hic15) = row('head_hic15', 'HIC15 (head)', '1', 'CFC 1000')
      rows(r_hic36) = row('head_hic36', 'HIC36 (head)', '1', 'CFC 1000')
      rows(r_head_gsi) = row('head_gsi', 'GSI (head)', '1', 'CFC 1000')
      rows(r_clip3ms) = row('chest_clip3ms', 'chest 3 ms clip', 'g', 'CFC 180')
      rows(r_chest_gsi) = row('chest_gsi', 'GSI (chest)', '1', 'CFC 180')
      rows(r_chest_deflection) = row('chest_deflection', 'chest deflection', 'mm', 'CFC 180')
      rows(r_vc) = row('chest_vc', 'viscous criterion VC', 'm/s', 'CFC 180')
      rows(r_nij) = row('neck_nij', 'Nij (neck)', '1', 'CFC 600')
      rows(r_neck_tension) = row('neck_tension', 'neck tension', 'N', 'CFC 600')
      rows(r_neck_compression) = row('neck_compression', 'neck compression', 'N', 'CFC 600')
      rows(r_femur) = row('femur_compression', 'femur compression', 'N', 'CFC 600')
      call limit(r_hic15, lim%hic15)
      call limit(r_clip3ms, lim%clip3ms)
      call limit(r_chest_deflection, lim%chest_deflection)
      call limit(r_nij, lim%nij)
      call limit(r_neck_tension, lim%neck_tension)
      call limit(r_neck_compression, lim%neck_compression)
      call limit(r_femur, lim%femur)
      hic = head_u%hic15()
      call unfiltered(r_hic15, hic%value)
      hic = head_u%hic36()
      call unfiltered(r_hic36, hic%value)
      call unfiltered(r_head_gsi, head_u%gsi)
      call unfiltered(r_clip3ms, chest_u%clip3ms())
      call unfiltered(r_chest_gsi, chest_u%gsi)

      ! the head: HIC15, HIC36 and GSI of the filtered resultant, linear
      ! between the grid's points, the windows' ends on them
      if (ch%head%n > 0) then
         call filtered(ch%head, cfc_head, f, t)
         head_f = criteria_new(h=ch%head%h)
         call resultant_criteria(head_f, t, f)
         hic = head_f%hic15()
         call found(r_hic15, hic%value, hic%t1, hic%t2)
         hic = head_f%hic36()
         call found(r_hic36, hic%value, hic%t1, hic%t2)
         rows(r_hic15:r_hic36)%window = .true.
         call found(r_head_gsi, head_f%gsi, nan, nan)
      end if
      ! the chest: its 3 ms clip and GSI
      if (ch%chest%n > 0) then
         call filtered(ch%chest, cfc_chest, f, t)
         chest_f = criteria_new(h=ch%chest%h, with_hic=.false.)
         call resultant_criteria(chest_f, t, f)
         call found(r_clip3ms, chest_f%clip3ms(), nan, nan)
         call found(r_chest_gsi, chest_f%gsi, nan, nan)
      end if
      ! the neck: Nij and the axial force's peaks
      if (ch%neck_kept .and. ch%neck%n > 0) then
         call filtered(ch%neck, cfc_neck, f, t)
         block
            integer :: k
            real(wp) :: nij_k(size(t))
            do k = 1, size(t)
               nij_k(k) = nij_of(f(1, k), f(2, k))
            end do
            call peak(r_nij, nij_k, t)
            ! (a peak of tension or compression is at least 0: none, when the
            ! neck is only pressed or only pulled)
            call peak(r_neck_tension, max(f(1, :), 0.0_wp), t)
            call peak(r_neck_compression, max(-f(1, :), 0.0_wp), t)
         end block
      end if
      ! the femur: its largest compression
      if (ch%femur_kept .and. ch%femur%n > 0) then
         call filtered(ch%femur, cfc_femur, f, t)
         call peak(r_femur, max(f(1, :), 0.0_wp), t)
      end if
      ! the chest's deflection and VC (its rate by central differences of
      ! the filtered deflection, in m/s; VC in m/s)
      if (ch%deflection_kept .and. ch%deflection%n > 0) then
         call filtered(ch%deflection, cfc_deflection, f, t)
         call peak(r_chest_deflection, f(1, :), t)
         block
            integer :: k, n
            real(wp) :: vc(size(t))
            n = size(t)
            vc = 0.0_wp
            do k = 1, n
               if (n < 2) exit
               ! the deflection's rate (m/s) by central differences, one-sided at the ends
               vc(k) = (f(1, min(k + 1, n)) - f(1, max(k - 1, 1)))/(t(min(k + 1, n)) - t(max(k - 1, 1)))/1000.0_wp
               vc(k) = vc_scale*vc(k)*(f(1, k)/1000.0_wp)/vc_depth
            end do
            call peak(r_vc, vc, t)
         end block
      end if
   contains
      pure function row(name, label, unit, channel) result(r)
         character(len=*), intent(in) :: name, label, unit, channel
         type(fmvss_row_t) :: r
         r%name = name
         r%label = label
         r%unit = unit
         r%channel = channel
         r%value = nan
         r%t = nan
         r%t_end = nan
      end function row
      subroutine limit(i, value)
         integer, intent(in) :: i
         real(wp), intent(in) :: value
         rows(i)%has_limit = .true.
         rows(i)%limit = value
      end subroutine limit
      subroutine unfiltered(i, value)
         integer, intent(in) :: i
         real(wp), intent(in) :: value
         rows(i)%has_unfiltered = .true.
         rows(i)%unfiltered = value
      end subroutine unfiltered
      subroutine found(i, value, t1, t2)
         integer, intent(in) :: i
         real(wp), intent(in) :: value, t1, t2
         rows(i)%available = .true.
         rows(i)%value = value
         rows(i)%t = t1
         rows(i)%t_end = t2
      end subroutine found
      !> the largest of x and its time
      subroutine peak(i, x, t)
         integer, intent(in) :: i
         real(wp), intent(in) :: x(:), t(:)
         integer :: k
         k = maxloc(x, 1)
         call found(i, x(k), t(k), t(k))
      end subroutine peak
   end function fmvss_rows

   !> Nij (FMVSS 208 S6.6(a)) of an axial force fz (N, + tension) and a
   !! flexion/extension moment my (N m, + flexion) at one time: Fz/Fzc +
   !! My/Myc with the intercepts of the load's own signs (one of NTF, NTE,
   !! NCF, NCE at each time).
   pure real(wp) function nij_of(fz, my) result(nij)
      real(wp), intent(in) :: fz, my
      real(wp) :: fzc, myc
      fzc = merge(fzc_tension, fzc_compression, fz >= 0.0_wp)
      myc = merge(myc_flexion, myc_extension, my >= 0.0_wp)
      nij = abs(fz)/fzc + abs(my)/myc
   end function nij_of

   !> The channels of occupant occ's belt sections (the effects whose
   !! series include a 'force' of their sections' tensions: lap_belt,
   !! torso_belt), with room for a run of duration (s).
   subroutine fmvss_belts_reserve(ch, occ, duration)
      type(fmvss_channels_t), intent(inout) :: ch
      type(occupant_t), intent(in) :: occ
      real(wp), intent(in) :: duration
      type(output_series_t), allocatable :: series(:)
      type(belt_channel_t), allocatable :: belts(:)
      integer :: k, j, c
      allocate (belts(0))
      do k = 1, size(occ%effects)
         associate (e => occ%effects(k)%e)
            if (e%name /= 'lap_belt' .and. e%name /= 'torso_belt') cycle
            series = e%outputs()
            do j = 1, size(series)
               if (series(j)%name /= 'force' .or. size(series(j)%col) > max_belt_columns) cycle
               do c = 1, size(series(j)%col)
                  belts = [belts, belt_channel_t(effect_name=e%name, section=series(j)%col(c)%name, effect=k, &
                                                 item=j, column=c, n_columns=size(series(j)%col))]
               end do
            end do
         end associate
      end do
      do k = 1, size(belts)
         call belts(k)%rec%reserve(1, duration)
      end do
      call move_alloc(belts, ch%belts)
      ch%belts_kept = .true.
   end subroutine fmvss_belts_reserve

   !> The belt sections' tensions (N) at the accepted point t, the state st
   !! (of y), with the memory the step was taken with (as a print time's
   !! frame shows them); a second call at one time (a jump) keeps the jump.
   !! Allocates nothing.
   pure subroutine fmvss_belts_sample(ch, occ, st, y, t)
      type(fmvss_channels_t), intent(inout) :: ch
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: y(:), t
      real(wp) :: v(max_belt_columns)
      integer :: k, xo, ao, last
      last = 0
      do k = 1, size(ch%belts)
         associate (b => ch%belts(k))
            ! (one evaluation of an effect serves each of its sections)
            if (b%effect /= last) then
               xo = occ%extra_offset(b%effect)
               ao = occ%aux_offset(b%effect)
               associate (e => occ%effects(b%effect)%e)
                  call e%output_values(b%item, st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), &
                                       v(1:b%n_columns))
               end associate
               last = b%effect
            end if
            call b%rec%add(t, [pound_force_n*v(b%column)])
         end associate
      end do
   end subroutine fmvss_belts_sample

   !> The vehicle's x and y accelerations (g; the program's axes: x
   !! forward, y up) at the grid points of rec, from its motion vm, exact
   !! (its tables are linear in time): (2, rec%n).
   pure function vehicle_channel(vm, rec) result(a)
      type(vehicle_motion_t), intent(in) :: vm
      type(channel_record_t), intent(in) :: rec
      real(wp) :: a(2, rec%n)
      real(wp) :: t(rec%n)
      integer :: k
      t = rec%times()
      do k = 1, rec%n
         associate (vs => vehicle_state_at(vm, t(k)))
            a(:, k) = vs%acc(1:2)/g_std
         end associate
      end do
   end function vehicle_channel

   !> The record's samples filtered at class cfc: f (n_comp, n), at times t.
   pure subroutine filtered(rec, cfc, f, t)
      type(channel_record_t), intent(in) :: rec
      real(wp), intent(in) :: cfc
      real(wp), allocatable, intent(out) :: f(:, :), t(:)
      integer :: i
      allocate (f(rec%n_comp, rec%n))
      do i = 1, rec%n_comp
         call cfc_filter(rec%values(i, 0:rec%n - 1), cfc, rec%h, f(i, :))
      end do
      t = rec%times()
   end subroutine filtered

   !> The criteria of the resultant of the filtered components f at the
   !! grid's times t (linear between them).
   pure subroutine resultant_criteria(c, t, f)
      type(acceleration_criteria_t), intent(inout) :: c
      real(wp), intent(in) :: t(:), f(:, :)
      integer :: k
      do k = 1, size(t)
         call c%add(t(k), norm2(f(:, k)))
      end do
   end subroutine resultant_criteria
end module fmvss_table
