!> Who fills the output registry: for each occupant the C.6 calculations
!! (output_calc), the energy summary, and each effect - its own series and
!! its contribution to b (`effects/<name>/generalized_force`, so that b can
!! be audited term by term against A z''). registry_build declares the
!! series once per run; frame_fill computes them at a print time.
module output_producers
   use kinds, only: wp
   use strings, only: itoa
   use model, only: model_t, vehicle_section_t, n_dof, n_seg, n_joint
   use body_state, only: body_state_t
   use effect_energies, only: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds, energy_kind_name
   use point_forces, only: point_force_list_t
   use occupant, only: occupant_t, slide_set_t, occupant_active_slides, occupant_add_slide_forces
   use joint_reactions, only: joint_reactions_at, bone_components_at
   use body_kinematics, only: point_state_t, link_cos_sin, body_points
   use proximity_guard, only: guard_none, guard_holds
   use joint_coupling, only: joint_columns
   use equations_of_motion, only: crash_system_t, system_body_state
   use output_series, only: output_series_t, series_new, column
   use output_registry, only: output_registry_t, output_frame_t
   use output_calc, only: body_outputs_t, body_outputs_compute, body_series, body_series_values, &
      body_kinetic_energy
   implicit none
   private

   public :: registry_build, frame_fill, energy_balance_t, frame_energy
   public :: producer_body, producer_energy, producer_reactions

   !> Producers other than effects (effect k of an occupant is producer k).
   integer, parameter :: producer_body = 0, producer_energy = -1, producer_reactions = -2

   !> The energy balance of one occupant at one time (C.6): body kinetic
   !! energy plus every effect's stored and dissipated energy minus what was
   !! supplied from outside is constant.
   type :: energy_balance_t
      real(wp) :: ke_body = 0.0_wp
      real(wp) :: total = 0.0_wp
      real(wp) :: error = 0.0_wp
      !> the work the moving vehicle has supplied to the body since t = 0
      !! (every effect's supplied energy), the balance's scale with ke_body
      real(wp) :: supplied = 0.0_wp
   end type energy_balance_t

contains

   !> Declare every series of the system's occupants.
   subroutine registry_build(sys, reg)
      type(crash_system_t), intent(in) :: sys
      type(output_registry_t), intent(out) :: reg
      type(output_series_t), allocatable :: own(:), fixed(:)
      type(output_series_t) :: s
      character(len=:), allocatable :: prefix
      integer :: o, k, j, kind

      allocate (reg%series(0))
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            prefix = ''
            if (size(sys%occupants) > 1) prefix = 'occupant_'//itoa(o)//'/'
            fixed = body_series()
            do j = 1, size(fixed)
               s = fixed(j)
               call place(s, producer_body, j)
               if (j == 3) call reg%add(energy_summary(occ))   ! after the vehicle: NOUT 1 tables first
               call reg%add(s)
            end do
            ! the joint reactions from the solved dynamics (A-INJ, F5-1)
            s = series_new('joints/tension', 'JOINT TENSION ON THE BONE AXES (NEWTON-EULER)', 'tension FT at each ' &
                           //'joint: -R.e, R the force of the proximal side on the distal side (sum of m a - F over ' &
                           //'it), e the distal bone''s axis; negative: compression (docs/injury.md)', 2)
            s%col = joint_columns('lb')
            call place(s, producer_reactions, 1)
            call reg%add(s)
            s = series_new('joints/shear', 'JOINT SHEAR ACROSS THE BONE AXES (NEWTON-EULER)', 'shear FS at each ' &
                           //'joint: R.e_perp, e_perp the distal bone''s axis turned by +90 deg (docs/injury.md)', 2)
            s%col = joint_columns('lb')
            call place(s, producer_reactions, 2)
            call reg%add(s)
            do k = 1, size(occ%effects)
               associate (e => occ%effects(k)%e)
                  own = e%outputs()
                  do j = 1, size(own)
                     s = own(j)
                     s%name = 'effects/'//trim(e%name)//'/'//s%name
                     call place(s, k, j)
                     call reg%add(s)
                  end do
                  if (e%acts) then
                     s = series_new('effects/'//trim(e%name)//'/generalized_force', &
                                    'GENERALIZED FORCES OF '//trim(e%title), &
                                    'contribution of '//trim(e%title)//' to b = C - G + J + S + B + Q (C.4): ' &
                                    //'on alpha_1..alpha_8 (in*lb) and x_h, y_h (lb)', 3)
                     s%col = [(column('alpha'//itoa(j), 'in*lb'), j=1, n_seg), column('x_h', 'lb'), column('y_h', 'lb')]
                     s%generalized_force = .true.
                     call place(s, k, 0)
                     call reg%add(s)
                  end if
               end associate
            end do
         end associate
      end do
      call registry_index(reg)
   contains
      subroutine place(series, producer, item)
         type(output_series_t), intent(inout) :: series
         integer, intent(in) :: producer, item
         series%name = prefix//series%name
         series%producer = producer
         series%item = item
         series%occupant = o
      end subroutine place

      !> ke_vehicle, ke_body, each effect's energies, the total and its error.
      function energy_summary(occ) result(es)
         type(occupant_t), intent(in) :: occ
         type(output_series_t) :: es
         character(len=:), allocatable :: name
         es = series_new('energy/summary', 'ENERGIES', 'energies (C.6): vehicle and body kinetic, each effect''s ' &
                         //'stored, dissipated and supplied energy (effects whose columns share a name, the ' &
                         //'contact pairs, summed); total_body = body kinetic + stored + dissipated - supplied, ' &
                         //'constant up to the integration error (balance_err)', 1)
         es%col = [column('ke_vehicle', 'in*lb'), column('ke_body', 'in*lb')]
         do k = 1, size(occ%effects)
            do kind = 1, n_energy_kinds
               if (.not. occ%effects(k)%e%has_energy(kind)) cycle
               name = energy_column_name(occ%effects(k)%e%name, occ%effects(k)%e%has_energy, kind)
               if (.not. any(es%col%name == name)) es%col = [es%col, column(name, 'in*lb')]
            end do
         end do
         es%col = [es%col, column('total_body', 'in*lb'), column('balance_err', 'in*lb')]
         ! each effect's energies' column, found by name here once (a frame
         ! adds to it by index)
         allocate (es%sum_column(n_energy_kinds*size(occ%effects)))
         es%sum_column = 0
         do k = 1, size(occ%effects)
            do kind = 1, n_energy_kinds
               if (.not. occ%effects(k)%e%has_energy(kind)) cycle
               name = energy_column_name(occ%effects(k)%e%name, occ%effects(k)%e%has_energy, kind)
               es%sum_column(n_energy_kinds*(k - 1) + kind) = findloc(es%col%name == name, .true., 1)
            end do
         end do
         call place(es, producer_energy, 0)
      end function energy_summary
   end subroutine registry_build

   !> An effect's energy column: its name, with the kind when it has several
   !! (then at most ten characters, which the listing shows: lap_b_stor,
   !! lap_b_diss, lap_b_supp, not three columns headed LAP_BELT_S).
   pure function energy_column_name(name, has, kind) result(s)
      character(len=*), intent(in) :: name
      logical, intent(in) :: has(n_energy_kinds)
      integer, intent(in) :: kind
      character(len=:), allocatable :: s
      if (count(has) > 1) then
         s = name(1:min(len_trim(name), 5))//'_'//energy_kind_name(kind)(1:4)
      else
         s = trim(name)
      end if
   end function energy_column_name

   !> Occupant o's energy balance at (t, y); total0 is the total at t = 0.
   pure function frame_energy(occ, st, y, total0) result(eb)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: y(:), total0
      type(energy_balance_t) :: eb
      real(wp) :: e(n_energy_kinds, size(occ%effects))
      call energies_and_balance(occ, st, y, total0, e, eb)
   end function frame_energy

   !> Every effect's energies e(:, k) at (t, y) and the balance they make
   !! (frame_energy).
   pure subroutine energies_and_balance(occ, st, y, total0, e, eb)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: y(:), total0
      real(wp), intent(out) :: e(:, :)
      type(energy_balance_t), intent(out) :: eb
      integer :: k
      do k = 1, size(occ%effects)
         call effect_energy(occ, k, st, y, e(:, k))
      end do
      eb = balance_of(sum(body_ke(occ, st)), e, total0)
   end subroutine energies_and_balance

   !> The balance (C.6) of the body's kinetic energy ke_body and the
   !! effects' energies e(:, k), against the total total0 at t = 0.
   pure function balance_of(ke_body, e, total0) result(eb)
      real(wp), intent(in) :: ke_body, e(:, :), total0
      type(energy_balance_t) :: eb
      integer :: k
      call balance_start(ke_body, eb)
      do k = 1, size(e, 2)
         call balance_add(eb, e(:, k))
      end do
      eb%error = eb%total - total0
   end function balance_of

   !> A balance of the body's kinetic energy ke_body alone (balance_of's start).
   pure subroutine balance_start(ke_body, eb)
      real(wp), intent(in) :: ke_body
      type(energy_balance_t), intent(out) :: eb
      eb%ke_body = ke_body
      eb%total = eb%ke_body
      eb%supplied = 0.0_wp
   end subroutine balance_start

   !> The next effect's energies e added to the balance (balance_of's step).
   pure subroutine balance_add(eb, e)
      type(energy_balance_t), intent(inout) :: eb
      real(wp), intent(in) :: e(n_energy_kinds)
      eb%total = eb%total + e(energy_stored) + e(energy_dissipated) - e(energy_supplied)
      eb%supplied = eb%supplied + e(energy_supplied)
   end subroutine balance_add

   pure function body_ke(occ, st) result(ke)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp) :: ke(n_seg)
      ke = body_kinetic_energy(occ%body, st%z, st%zdot)
   end function body_ke

   pure subroutine effect_energy(occ, k, st, y, e)
      type(occupant_t), intent(in) :: occ
      integer, intent(in) :: k
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      integer :: xo, ao
      xo = occ%extra_offset(k)
      ao = occ%aux_offset(k)
      associate (ef => occ%effects(k)%e)
         call ef%energy(st, y(xo + 1:xo + 2*ef%n_extra), y(ao + 1:ao + ef%n_aux), e)
      end associate
   end subroutine effect_energy

   !> Where each producer's series are (output_registry_t's series_of),
   !! once every series is declared (registry_build).
   pure subroutine registry_index(reg)
      type(output_registry_t), intent(inout) :: reg
      integer :: k, j, max_item, max_producer, n_occ
      max_item = 0
      max_producer = 0
      n_occ = 1
      do k = 1, size(reg%series)
         max_item = max(max_item, reg%series(k)%item)
         max_producer = max(max_producer, reg%series(k)%producer)
         n_occ = max(n_occ, reg%series(k)%occupant)
      end do
      if (allocated(reg%series_of)) deallocate (reg%series_of, reg%value_at, reg%value_count)
      allocate (reg%series_of(0:max_item, producer_reactions:max_producer, n_occ))
      allocate (reg%value_at, reg%value_count, mold=reg%series_of)
      reg%series_of = 0
      reg%value_at = -1
      reg%value_count = 0
      do k = 1, size(reg%series)
         associate (s => reg%series(k))
            ! (an effect's generalized force is its item 0)
            j = merge(0, s%item, s%generalized_force)
            reg%series_of(j, s%producer, s%occupant) = k
            reg%value_at(j, s%producer, s%occupant) = s%offset
            reg%value_count(j, s%producer, s%occupant) = size(s%col)
         end associate
      end do
   end subroutine registry_index

   !> Every series at the accepted point (t, y) where the derivative is f.
   !! total0(o): occupant o's energy total at t = 0. Returns each
   !! occupant's energy balance too. Each effect gives everything the frame
   !! takes from it at once (its frame_values: its energies, its series, its
   !! generalized force, its point forces for the joint reactions), so that
   !! an effect whose series each repeat one evaluation (a contact pair, a
   !! belt) evaluates once a frame (issue 16 section 4).
   subroutine frame_fill(sys, vehicle, reg, t, y, f, total0, frame, balance)
      type(crash_system_t), intent(in) :: sys
      type(vehicle_section_t), intent(in) :: vehicle
      type(output_registry_t), intent(in) :: reg
      real(wp), intent(in) :: t, f(:), total0(:)
      real(wp), intent(in), contiguous :: y(:)
      type(output_frame_t), intent(inout) :: frame
      type(energy_balance_t), intent(out) :: balance(:)
      type(output_registry_t) :: indexed
      integer :: o
      if (.not. allocated(frame%v)) allocate (frame%v(reg%n_values))
      frame%t = t
      if (.not. allocated(reg%series_of)) then
         ! (a registry not from registry_build, or appended to since: indexed here)
         indexed = reg
         call registry_index(indexed)
         do o = 1, size(sys%occupants)
            call occupant_frame(sys, o, vehicle, indexed, t, y, f, total0(o), frame%v, balance(o))
         end do
         return
      end if
      do o = 1, size(sys%occupants)
         call occupant_frame(sys, o, vehicle, reg, t, y, f, total0(o), frame%v, balance(o))
      end do
   end subroutine frame_fill

   !> frame_fill's work for occupant o: its series' values into v, its
   !! energy balance eb.
   subroutine occupant_frame(sys, o, vehicle, reg, t, y, f, total0, v, eb)
      type(crash_system_t), intent(in) :: sys
      integer, intent(in) :: o
      type(vehicle_section_t), intent(in) :: vehicle
      type(output_registry_t), intent(in) :: reg
      real(wp), intent(in) :: t, f(:), total0
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(inout), contiguous :: v(:)
      type(energy_balance_t), intent(out) :: eb
      type(body_state_t) :: st
      type(body_outputs_t) :: bo
      type(point_force_list_t) :: list
      type(point_state_t) :: cg(n_seg), joint(n_seg)
      type(slide_set_t) :: slides
      real(wp) :: zdd(n_dof), b_all(n_dof), gf(n_dof), e(n_energy_kinds), r(2, n_joint), ft(n_joint), fs(n_joint)
      real(wp) :: c(n_seg), s(n_seg)
      logical :: reacts, sums
      integer :: none(0)
      integer :: k, j, i, n, kind, xo, ao, n_eff, next_evaluated, n_evaluated, n_item, n_producer, at0, summary, sum_at
      integer :: sum_column(n_energy_kinds)

      associate (occ => sys%occupants(o), at => reg%value_at, n_at => reg%value_count)
         n_eff = size(occ%effects)
         n_item = ubound(at, 1)
         n_producer = ubound(at, 2)
         st = system_body_state(sys, o, t, y)
         zdd = f(occ%zdot_offset + 1:occ%zdot_offset + n_dof)
         reacts = any(at(:, producer_reactions, o) >= 0)
         ! the joints and the centres of gravity once, for the body's series,
         ! the kinetic energies and the joint reactions, from each angle's
         ! cosine and sine taken once (the bits of joint_state's and
         ! segment_cg_state's, not st%c's)
         call link_cos_sin(st%z(1:n_seg), c, s)
         call body_points(occ%body, st%z, st%zdot, zdd, c, s, joint, cg)
         call body_outputs_compute(occ%body, vehicle, st, zdd, bo, cg, joint)
         ! the energy balance (balance_of's sums, effect by effect) and the
         ! energy summary's columns, summed as the effects come
         call balance_start(sum(bo%ke_seg), eb)
         summary = reg%series_of(0, producer_energy, o)
         sum_at = at(0, producer_energy, o)
         if (summary > 0) v(sum_at + 1:sum_at + n_at(0, producer_energy, o)) = 0.0_wp
         ! the sliding constraints' forces (issue 15) need the sum of the
         ! effects' forces, occupant_forces', where one is active
         call occupant_active_slides(occ, st, y, slides)
         b_all = 0.0_wp
         list%n = 0
         next_evaluated = 1
         n_evaluated = size(occ%evaluated)
         do k = 1, n_eff
            xo = occ%extra_offset(k)
            ao = occ%aux_offset(k)
            associate (ef => occ%effects(k)%e)
               ! occupant_forces' sum: the evaluated effects, in order, but
               ! those whose proximity guard holds (inert: what add_forces gives)
               sums = .false.
               if (next_evaluated <= n_evaluated) then
                  if (occ%evaluated(next_evaluated) == k) then
                     next_evaluated = next_evaluated + 1
                     sums = slides%n > 0
                     if (sums .and. ef%guard%kind /= guard_none) sums = .not. guard_holds(ef%guard, st)
                  end if
               end if
               gf = 0.0_wp
               if (k <= n_producer) then
                  call ef%frame_values(st, y(xo + 1:xo + 2*ef%n_extra), y(ao + 1:ao + ef%n_aux), e, v, &
                                       at(1:n_item, k, o), n_at(1:n_item, k, o), at(0, k, o) >= 0, gf, &
                                       reacts .and. ef%external, list, sums, b_all)
                  ! its generalized force (the sliding constraints' added below)
                  at0 = at(0, k, o)
                  if (at0 >= 0) v(at0 + 1:at0 + n_dof) = gf
               else                                        ! (none of its series in the registry)
                  call ef%frame_values(st, y(xo + 1:xo + 2*ef%n_extra), y(ao + 1:ao + ef%n_aux), e, v, &
                                       none, none, .false., gf, reacts .and. ef%external, list, sums, b_all)
               end if
            end associate
            call balance_add(eb, e)
            if (summary > 0) then
               ! (the columns of the effect's energies, found by
               ! registry_build: shared by the contact pairs, summed)
               sum_column = reg%series(summary)%sum_column(n_energy_kinds*(k - 1) + 1:n_energy_kinds*k)
               do kind = 1, n_energy_kinds
                  j = sum_column(kind)
                  if (j > 0) v(sum_at + j) = v(sum_at + j) + e(kind)
               end do
            end if
         end do
         if (slides%n > 0) call occupant_add_slide_forces(occ, st, slides, b_all, v, at(0, 1:min(n_eff, n_producer), o))
         eb%error = eb%total - total0
         ! the body's series (C.6)
         do j = 1, n_item
            if (at(j, producer_body, o) >= 0) &
               call body_series_values(j, bo, v(at(j, producer_body, o) + 1:at(j, producer_body, o) &
                                                + n_at(j, producer_body, o)))
         end do
         ! FT and FS of every joint (both series from one solve)
         if (reacts) then
            r = joint_reactions_at(occ%body, cg, list)
            call bone_components_at(r, c, s, ft, fs)
            do j = 1, 2
               i = at(j, producer_reactions, o)
               if (i >= 0) v(i + 1:i + n_joint) = merge(ft, fs, j == 1)
            end do
         end if
         ! the energy summary's other columns
         if (summary > 0) then
            n = n_at(0, producer_energy, o)
            v(sum_at + 1) = bo%ke_vehicle
            v(sum_at + 2) = eb%ke_body
            v(sum_at + n - 1) = eb%total
            v(sum_at + n) = eb%error
         end if
      end associate
   end subroutine occupant_frame
end module output_producers
