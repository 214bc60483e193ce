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
   use occupant, only: occupant_t, occupant_add_slide_forces
   use joint_reactions, only: joint_reaction_forces, bone_components
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
      eb%ke_body = ke_body
      eb%total = eb%ke_body
      eb%supplied = 0.0_wp
      do k = 1, size(e, 2)
         eb%total = eb%total + e(energy_stored, k) + e(energy_dissipated, k) - e(energy_supplied, k)
         eb%supplied = eb%supplied + e(energy_supplied, k)
      end do
      eb%error = eb%total - total0
   end function balance_of

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

   !> The most effects an occupant of sys has.
   pure integer function max_effects(sys)
      type(crash_system_t), intent(in) :: sys
      integer :: o
      max_effects = 0
      do o = 1, size(sys%occupants)
         max_effects = max(max_effects, size(sys%occupants(o)%effects))
      end do
   end function max_effects

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
      ! (work arrays on the stack: a frame allocates nothing but the point
      ! forces' list, once)
      type(body_state_t) :: st
      type(body_outputs_t) :: bo(size(sys%occupants))
      type(point_force_list_t) :: list
      integer :: n_item
      !> where each effect's series k go in the frame (at(0, ...): its
      !! generalized force; -1: not in the registry), and their widths
      integer :: at(0:max_item(reg), max_effects(sys), size(sys%occupants))
      integer :: width(0:max_item(reg), max_effects(sys), size(sys%occupants))
      real(wp) :: gf(n_dof, max_effects(sys))             !< each effect's generalized force
      real(wp) :: ft(n_joint, size(sys%occupants)), fs(n_joint, size(sys%occupants))   !< joint tension and shear
      logical :: reacts(size(sys%occupants))
      !> each occupant's effects' energies, computed once for the balance and the energy summary
      real(wp) :: energy(n_energy_kinds, max_effects(sys), size(sys%occupants))
      integer :: o, k, k2, kind, n, i, xo, ao
      logical :: wants_gf

      if (.not. allocated(frame%v)) allocate (frame%v(reg%n_values))
      frame%t = t
      n_item = ubound(at, 1)
      at = -1
      width = 0
      reacts = .false.
      do k = 1, size(reg%series)
         associate (s => reg%series(k))
            if (s%producer > 0) then
               i = s%item
               if (s%generalized_force) i = 0
               at(i, s%producer, s%occupant) = s%offset
               width(i, s%producer, s%occupant) = size(s%col)
            else if (s%producer == producer_reactions) then
               reacts(s%occupant) = .true.
            end if
         end associate
      end do
      do o = 1, size(sys%occupants)
         associate (occ => sys%occupants(o))
            st = system_body_state(sys, o, t, y)
            call body_outputs_compute(occ%body, vehicle, st, f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), bo(o))
            list%n = 0
            do k = 1, size(occ%effects)
               xo = occ%extra_offset(k)
               ao = occ%aux_offset(k)
               associate (ef => occ%effects(k)%e)
                  wants_gf = at(0, k, o) >= 0
                  gf(:, k) = 0.0_wp
                  call ef%frame_values(st, y(xo + 1:xo + 2*ef%n_extra), y(ao + 1:ao + ef%n_aux), energy(:, k, o), &
                                       frame%v, at(1:n_item, k, o), width(1:n_item, k, o), wants_gf, gf(:, k), &
                                       reacts(o) .and. ef%external, list)
               end associate
            end do
            ! and their sliding constraints' forces (issue 15)
            call occupant_add_slide_forces(occ, st, y, gf(:, 1:size(occ%effects)))
            do k = 1, size(occ%effects)
               if (at(0, k, o) >= 0) frame%v(at(0, k, o) + 1:at(0, k, o) + n_dof) = gf(:, k)
            end do
            balance(o) = balance_of(sum(bo(o)%ke_seg), energy(:, 1:size(occ%effects), o), total0(o))
            if (reacts(o)) call reactions(occ, st, ft(:, o), fs(:, o))
         end associate
      end do
      do k = 1, size(reg%series)
         associate (s => reg%series(k), occ => sys%occupants(reg%series(k)%occupant))
            if (s%producer > 0) cycle                  ! (the effects' own, above)
            o = s%occupant
            n = size(s%col)
            associate (v => frame%v(s%offset + 1:s%offset + n))
               if (s%producer == producer_body) then
                  call body_series_values(s%item, bo(o), v)
               else if (s%producer == producer_reactions) then
                  v = merge(ft(:, o), fs(:, o), s%item == 1)
               else if (s%producer == producer_energy) then
                  v = 0.0_wp
                  v(1) = bo(o)%ke_vehicle
                  v(2) = balance(o)%ke_body
                  do k2 = 1, size(occ%effects)
                     do kind = 1, n_energy_kinds
                        ! (the column of the effect's energy of this kind, found by
                        ! registry_build: shared by the contact pairs, summed)
                        i = s%sum_column(n_energy_kinds*(k2 - 1) + kind)
                        if (i > 0) v(i) = v(i) + energy(kind, k2, o)
                     end do
                  end do
                  v(n - 1) = balance(o)%total
                  v(n) = balance(o)%error
               end if
            end associate
         end associate
      end do
   contains
      !> FT and FS of every joint at the print time (both series from one
      !! solve), from the point forces the effects gave (list).
      subroutine reactions(occ, st, ft, fs)
         type(occupant_t), intent(in) :: occ
         type(body_state_t), intent(in) :: st
         real(wp), intent(out) :: ft(n_joint), fs(n_joint)
         real(wp) :: r(2, n_joint)
         r = joint_reaction_forces(occ%body, st%z, st%zdot, f(occ%zdot_offset + 1:occ%zdot_offset + n_dof), list)
         call bone_components(r, st%z, ft, fs)
      end subroutine reactions
   end subroutine frame_fill

   !> The largest item of an effect's own series in reg (at least 1).
   pure integer function max_item(reg)
      type(output_registry_t), intent(in) :: reg
      integer :: k
      max_item = 1
      do k = 1, size(reg%series)
         if (reg%series(k)%producer > 0) max_item = max(max_item, reg%series(k)%item)
      end do
   end function max_item
end module output_producers
