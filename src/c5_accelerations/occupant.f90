!> An occupant: its body (Table 1), the body constants of C.2, the effects
!! its deck calls for, and where its part of the state vector lives. The
!! kernels of C.4-C.5 take an occupant, never a whole system, and nothing
!! assumes that an occupant starts at offset 0: the report's phase-three
!! directions (two occupants; Section D) have room here.
module occupant
   use kinds, only: wp, i8
   use segment_trig, only: segment_cos_sin
   use model, only: model_t, body_section_t, n_dof, n_seg, solver_dense, injury_section_t, end_tests_section_t
   use preliminary, only: body_constants_t, body_constants, initial_state
   use effect_base, only: effect_t, body_state_t, slide_t
   use effect_slots, only: effect_slot_t
   use point_forces, only: point_force_list_t
   use proximity_guard, only: guard_none, guard_holds
   use effect_factory, only: build_effects
   use body_kinematics, only: joint_positions
   use vehicle_motion, only: vehicle_motion_t, vehicle_state_at
   use state_layout, only: state_layout_t
   use sliding_constraints, only: sliding_multipliers, max_slides
   use body_matrix, only: body_accelerations, body_structure_matches, matrix_structured => solver_structured, &
      matrix_dense => solver_dense
   implicit none
   private

   public :: occupant_t, occupant_build, occupant_state, occupant_rhs, occupant_forces, occupant_frame
   public :: occupant_rhs_kept
   public :: occupant_vehicle
   public :: occupant_initial_y, occupant_add_effect, occupant_point_forces, occupant_chest_deflection
   public :: occupant_slide_switches, occupant_settle, occupant_slide_forces
   public :: slide_set_t, occupant_active_slides, occupant_add_slide_forces
   public :: slides_overflow

   !> occupant_rhs's info for an occupant whose effects may hold more
   !! sliding constraints (n_slide, all of them active at once) than the
   !! solve has room for (max_slides): refused at its every evaluation, so
   !! that none is ever left out (before, gather_slides kept the first
   !! max_slides active ones and dropped the rest without a word)
   integer, parameter :: slides_overflow = -1000

   type :: occupant_t
      character(len=16) :: label = 'occupant'
      type(body_section_t) :: body
      type(body_constants_t) :: bc
      type(effect_slot_t), allocatable :: effects(:)
      !> the effects evaluated by the right-hand side (those adding forces or
      !! integrating quantities of their own), and those with memory (whose
      !! accept is called after each accepted step)
      integer, allocatable :: evaluated(:), remembering(:)
      !> an evaluated effect with memory keeps, at the evaluation that ends a
      !! step, what its accept needs (effect_t%keeps; occupant_rhs_kept)
      logical :: keeps = .false.
      !> the effects that may hold sliding constraints (issue 15), and how
      !! many constraints they may hold in all
      integer, allocatable :: sliding(:)
      integer :: n_slide = 0
      !> how A z'' = b is solved (C.5): the L D L**T written for figure 27's
      !! structure, or LAPACK's dense one (*NUMERICS SOLVER, and always for a
      !! body coupled otherwise)
      integer :: solver = matrix_structured
      logical :: needs_vehicle = .false.
      logical :: needs_joints = .false.   !< an effect reads st's interior frame data (occupant_frame)
      !> offsets in y: z is y(z_offset+1 : z_offset+n_dof), z' likewise
      integer :: z_offset = 0, zdot_offset = 0
      !> per effect: its extra coordinates and rates, its auxiliary quantities
      integer, allocatable :: extra_offset(:), aux_offset(:)
      real(wp) :: z0(n_dof) = 0.0_wp, zdot0(n_dof) = 0.0_wp
      !> its own end test and limits (C.7: *OPTIONS NEND, *ENDTESTS; Table 5:
      !! *INJURY), so that occupants built from different models keep theirs
      integer :: nend = 0
      type(end_tests_section_t) :: end_tests
      type(injury_section_t) :: injury
   end type occupant_t

   !> Active sliding constraints, packed (gather_slides): direction d,
   !! range [lo, hi], the y index of the work their power goes to (0:
   !! none), their effect and its slot, their place among all the
   !! occupant's slots; the multipliers and A^-1 d once solved.
   type :: slide_set_t
      integer :: n = 0
      real(wp) :: d(n_dof, max_slides) = 0.0_wp, y_cols(n_dof, max_slides) = 0.0_wp
      real(wp) :: lo(max_slides) = 0.0_wp, hi(max_slides) = 0.0_wp
      real(wp) :: lam(max_slides) = 0.0_wp, lam_clipped(max_slides) = 0.0_wp
      real(wp) :: offset(max_slides) = 0.0_wp, bias(max_slides) = 0.0_wp
      integer :: aux_supplied(max_slides) = 0
      integer :: aux_at(max_slides) = 0, owner(max_slides) = 0, slot(max_slides) = 0, pos(max_slides) = 0
   end type slide_set_t

contains

   !> Build an occupant from the model: constants, initial state, effects,
   !! and its slots in the state layout.
   subroutine occupant_build(m, label, layout, occ)
      type(model_t), intent(in) :: m
      character(len=*), intent(in) :: label
      type(state_layout_t), intent(inout) :: layout
      type(occupant_t), intent(out) :: occ
      integer :: k, n_eff

      occ%label = label
      occ%body = m%body
      occ%nend = m%options%nend
      occ%end_tests = m%end_tests
      occ%injury = m%injury
      occ%bc = body_constants(m%body)
      occ%solver = matrix_structured
      if (m%numerics%solver == solver_dense .or. .not. body_structure_matches(occ%bc)) occ%solver = matrix_dense
      call initial_state(m%body, m%vehicle, occ%z0, occ%zdot0)
      call build_effects(m, occ%bc, occ%z0, occ%effects, occ%zdot0)
      n_eff = size(occ%effects)
      call layout%reserve(label//': z', n_dof, occ%z_offset)
      call layout%reserve(label//': z''', n_dof, occ%zdot_offset)
      allocate (occ%extra_offset(n_eff), occ%aux_offset(n_eff), occ%evaluated(0), occ%remembering(0), occ%sliding(0))
      do k = 1, n_eff
         call place_effect(occ, k, layout)
      end do
   end subroutine occupant_build

   !> Give effect k its slots in the layout and its place in the lists.
   subroutine place_effect(occ, k, layout)
      type(occupant_t), intent(inout) :: occ
      integer, intent(in) :: k
      type(state_layout_t), intent(inout) :: layout
      integer :: j
      associate (e => occ%effects(k)%e)
         call layout%reserve(trim(occ%label)//': '//trim(e%name)//' q, q''', 2*e%n_extra, occ%extra_offset(k))
         call layout%reserve(trim(occ%label)//': '//trim(e%name)//' work', e%n_aux - e%n_aux_start, occ%aux_offset(k))
         if (e%n_aux_start > 0) call layout%reserve(trim(occ%label)//': '//trim(e%name)//' search starts', &
                                                    e%n_aux_start, j, error_controlled=.false.)
         occ%needs_vehicle = occ%needs_vehicle .or. e%needs_vehicle
         occ%needs_joints = occ%needs_joints .or. e%needs_joints .or. e%guard%kind /= guard_none
         occ%needs_vehicle = occ%needs_vehicle .or. occ%needs_joints   ! (occupant_frame reads it)
         if (.not. allocated(occ%evaluated)) allocate (occ%evaluated(0))
         if (.not. allocated(occ%remembering)) allocate (occ%remembering(0))
         if (e%acts .or. e%n_aux > 0 .or. e%n_extra > 0) occ%evaluated = [(occ%evaluated(j), j=1, size(occ%evaluated)), k]
         if (e%has_memory) occ%remembering = [(occ%remembering(j), j=1, size(occ%remembering)), k]
         ! (an effect with sliding constraints never keeps: effect_t%keeps)
         if (e%n_slide > 0) e%keeps = .false.
         occ%keeps = occ%keeps .or. (e%keeps .and. e%has_memory .and. any(occ%evaluated == k))
         if (.not. allocated(occ%sliding)) allocate (occ%sliding(0))
         if (e%n_slide > 0) then
            occ%sliding = [(occ%sliding(j), j=1, size(occ%sliding)), k]
            occ%n_slide = occ%n_slide + e%n_slide
         end if
      end associate
   end subroutine place_effect

   !> One more effect for a built occupant (a test's toy effect, or a
   !! caller's own): appended to its list, given its slots at the end of y.
   subroutine occupant_add_effect(occ, e, layout)
      type(occupant_t), intent(inout) :: occ
      class(effect_t), intent(in) :: e
      type(state_layout_t), intent(inout) :: layout
      type(effect_slot_t), allocatable :: longer(:)
      integer :: k, n
      n = size(occ%effects) + 1
      allocate (longer(n))
      do k = 1, n - 1
         call move_alloc(occ%effects(k)%e, longer(k)%e)
      end do
      allocate (longer(n)%e, source=e)
      call move_alloc(longer, occ%effects)
      occ%extra_offset = [occ%extra_offset, 0]
      occ%aux_offset = [occ%aux_offset, 0]
      call place_effect(occ, n, layout)
   end subroutine occupant_add_effect

   !> The occupant's initial part of y: z0, z'0, each effect's extra
   !! degrees of freedom as it says; auxiliary quantities (work) start at 0.
   pure subroutine occupant_initial_y(occ, y)
      type(occupant_t), intent(in) :: occ
      real(wp), intent(inout) :: y(:)
      integer :: k, xo
      y(occ%z_offset + 1:occ%z_offset + n_dof) = occ%z0
      y(occ%zdot_offset + 1:occ%zdot_offset + n_dof) = occ%zdot0
      do k = 1, size(occ%effects)
         xo = occ%extra_offset(k)
         associate (e => occ%effects(k)%e)
            call e%initial_extra(y(xo + 1:xo + 2*e%n_extra))
            y(occ%aux_offset(k) + 1:occ%aux_offset(k) + e%n_aux) = 0.0_wp
         end associate
      end do
   end subroutine occupant_initial_y

   !> What the effects see: the occupant's coordinates and rates in y, the
   !! sines and cosines of the segment angles. The caller then adds the
   !! vehicle's state when the occupant's effects need it
   !! (occ%needs_vehicle; occupant_vehicle).
   pure subroutine occupant_state(occ, t, y, st)
      type(occupant_t), intent(in) :: occ
      real(wp), intent(in) :: t, y(:)
      type(body_state_t), intent(inout) :: st
      st%t = t
      st%z = y(occ%z_offset + 1:occ%z_offset + n_dof)
      st%zdot = y(occ%zdot_offset + 1:occ%zdot_offset + n_dof)
      call segment_cos_sin(st%z(1:n_seg), st%c, st%s)     ! (segment_trig: the same bits in every build)
   end subroutine occupant_state

   !> The vehicle's state at t into st, after occupant_state, and then the
   !! interior frame's data when the occupant's effects need it
   !! (occupant_frame, occ%needs_joints): once per evaluation rather than
   !! once per contact pair, and not at all for a body-only deck.
   pure subroutine occupant_vehicle(occ, vm, t, st)
      type(occupant_t), intent(in) :: occ
      type(vehicle_motion_t), intent(in) :: vm
      real(wp), intent(in) :: t
      type(body_state_t), intent(inout) :: st
      st%vehicle = vehicle_state_at(vm, t)
      if (occ%needs_joints) call occupant_frame(occ%body, st)
   end subroutine occupant_vehicle

   !> The interior frame's data of st (body_state_t; its z, c, s and
   !! vehicle set): each segment's proximal joint (joint_positions) and
   !! e(theta_i) turned into the interior frame, x = R(Phi)(X - x_c) (the
   !! start of C.4; no trigonometry at a pitch of zero), the coordinates'
   !! size |X| + |Y| + |x_c| + |y_c| and the rates' size. For the contact
   !! pairs' bound (pair_far), which only needs them within its margin, not
   !! to the bit (a pair's own geometry, body_feature, does its own).
   pure subroutine occupant_frame(body, st)
      type(body_section_t), intent(in) :: body
      type(body_state_t), intent(inout) :: st
      real(wp) :: p(2, n_seg), d(2), cp, sp
      integer :: i
      p = joint_positions(body, st%z, st%c, st%s)
      associate (vpos => st%vehicle%pos)
         if (abs(vpos(3)) > 0.0_wp) then
            cp = cos(vpos(3))
            sp = sin(vpos(3))
            do i = 1, n_seg
               d = p(:, i) - vpos(1:2)
               st%frame_joint(:, i) = [d(1)*cp - d(2)*sp, d(1)*sp + d(2)*cp]
               st%frame_axis(:, i) = [st%c(i)*cp - st%s(i)*sp, st%s(i)*cp + st%c(i)*sp]
            end do
         else
            do i = 1, n_seg
               st%frame_joint(:, i) = p(:, i) - vpos(1:2)
               st%frame_axis(:, i) = [st%c(i), st%s(i)]
            end do
         end if
         do i = 1, n_seg
            st%joint_size(i) = abs(p(1, i)) + abs(p(2, i)) + abs(vpos(1)) + abs(vpos(2))
         end do
      end associate
      st%rate_size = sum(abs(st%zdot)) + sum(abs(st%vehicle%vel))
   end subroutine occupant_frame

   !> The forces from outside the body that the occupant's effects apply at
   !! st (for the joint reactions, A-INJ); with segments, only those of the
   !! effects that may act on one of them (effect_t%acts_on: the joint
   !! reactions of a distal side need only its own forces).
   pure subroutine occupant_point_forces(occ, st, y, list, segments)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: y(:)
      type(point_force_list_t), intent(inout) :: list
      logical, intent(in), optional :: segments(n_seg)
      integer :: k, xo, ao
      list%n = 0      ! (its storage kept: nothing allocated once it is large enough)
      do k = 1, size(occ%effects)
         associate (e => occ%effects(k)%e)
            if (.not. e%external) cycle
            if (present(segments)) then
               if (.not. any(e%acts_on .and. segments)) cycle
            end if
            ! an effect inert for certain at st applies no force (its proximity
            ! guard, D-C29: a far contact pair), so it is not asked
            if (e%guard%kind /= guard_none) then
               if (guard_holds(e%guard, st)) cycle
            end if
            xo = occ%extra_offset(k)
            ao = occ%aux_offset(k)
            call e%point_forces(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), list)
         end associate
      end do
   end subroutine occupant_point_forces

   !> The chest's deflection at st (in; issue 18): the largest that any
   !! effect deflecting the chest's material reports (the torso belt's
   !! sections, the chest's contacts); 0 when none does.
   pure real(wp) function occupant_chest_deflection(occ, st, y) result(d)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: y(:)
      integer :: k, xo, ao
      d = 0.0_wp
      do k = 1, size(occ%effects)
         associate (e => occ%effects(k)%e)
            if (.not. e%deflects_chest) cycle
            xo = occ%extra_offset(k)
            ao = occ%aux_offset(k)
            d = max(d, e%chest_deflection(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux)))
         end associate
      end do
   end function occupant_chest_deflection

   !> b = C - G + J + S + B + Q (C.4): the sum of the evaluated effects'
   !! generalized forces, and the rates of their own quantities into dydt.
   !! counts(k) counts the evaluations of effect k. An effect whose
   !! proximity guard holds at st (proximity_guard; D-C29) is inert there: its
   !! rates are zero and b is left as it is, what its add_forces would
   !! give, without the dispatch; it is counted all the same.
   pure subroutine occupant_forces(occ, st, y, b, dydt, counts)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out) :: b(n_dof)
      real(wp), intent(inout), contiguous :: dydt(:)
      integer(i8), intent(inout) :: counts(:)
      integer :: n, k, xo, ao
      logical :: inert
      b = 0.0_wp
      do n = 1, size(occ%evaluated)
         k = occ%evaluated(n)
         xo = occ%extra_offset(k)
         ao = occ%aux_offset(k)
         associate (e => occ%effects(k)%e)
            inert = .false.
            if (e%guard%kind /= guard_none) inert = guard_holds(e%guard, st)
            if (inert) then
               dydt(xo + 1:xo + 2*e%n_extra) = 0.0_wp
               dydt(ao + 1:ao + e%n_aux) = 0.0_wp
            else
               call e%add_forces(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), b, &
                                 dydt(xo + 1:xo + 2*e%n_extra), dydt(ao + 1:ao + e%n_aux))
            end if
         end associate
         counts(k) = counts(k) + 1
      end do
   end subroutine occupant_forces

   !> The occupant's part of f(t, y): z' and z'' from A z'' = b (C.5), and
   !! the rates of its effects' quantities. info /= 0: A is not positive
   !! definite (body_accelerations' outcome, which system_rhs answers the
   !! stepper with).
   pure subroutine occupant_rhs(occ, st, y, dydt, counts, info)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(inout), contiguous :: dydt(:)
      integer(i8), intent(inout) :: counts(:)
      integer, intent(out) :: info
      real(wp) :: b(n_dof), zdd(n_dof)
      call occupant_forces(occ, st, y, b, dydt, counts)
      call body_accelerations(occ%bc, st%c, st%s, b, zdd, info, occ%solver)
      if (info == 0 .and. occ%n_slide > max_slides) info = slides_overflow
      if (info == 0 .and. occ%n_slide > 0) call slide(occ, st, y, zdd, dydt, info)
      dydt(occ%z_offset + 1:occ%z_offset + n_dof) = st%zdot
      dydt(occ%zdot_offset + 1:occ%zdot_offset + n_dof) = zdd
   end subroutine occupant_rhs

   !> occupant_rhs at the evaluation that ends a step (rhs_end; issue 16
   !! section 4): the same bits, but the effects that keep (effect_t%keeps)
   !! are evaluated through add_forces_kept, which keeps what their accept
   !! needs at this state. Only the effects' kept results change.
   !! (occupant_forces' loop and occupant_rhs' solve written out again, so
   !! that every other evaluation stays as it was.)
   subroutine occupant_rhs_kept(occ, st, y, dydt, counts, info)
      type(occupant_t), intent(inout) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(inout), contiguous :: dydt(:)
      integer(i8), intent(inout) :: counts(:)
      integer, intent(out) :: info
      real(wp) :: b(n_dof), zdd(n_dof)
      type(slide_set_t) :: set
      integer :: n, k, xo, ao, c
      logical :: inert
      ! occupant_forces, the keeping effects through add_forces_kept
      b = 0.0_wp
      do n = 1, size(occ%evaluated)
         k = occ%evaluated(n)
         xo = occ%extra_offset(k)
         ao = occ%aux_offset(k)
         associate (e => occ%effects(k)%e)
            inert = .false.
            if (e%guard%kind /= guard_none) inert = guard_holds(e%guard, st)
            if (inert) then
               dydt(xo + 1:xo + 2*e%n_extra) = 0.0_wp
               dydt(ao + 1:ao + e%n_aux) = 0.0_wp
            else if (e%keeps) then
               call e%add_forces_kept(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), b, &
                                      dydt(xo + 1:xo + 2*e%n_extra), dydt(ao + 1:ao + e%n_aux))
            else
               call e%add_forces(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), b, &
                                 dydt(xo + 1:xo + 2*e%n_extra), dydt(ao + 1:ao + e%n_aux))
            end if
         end associate
         counts(k) = counts(k) + 1
      end do
      call body_accelerations(occ%bc, st%c, st%s, b, zdd, info, occ%solver)
      if (info == 0 .and. occ%n_slide > max_slides) info = slides_overflow
      if (info == 0 .and. occ%n_slide > 0) then
         ! slide's lines (with a second caller, the compiler no longer puts
         ! slide in line in occupant_rhs, at every evaluation)
         call gather_slides(occ, st, y, set)
         if (set%n > 0) call set_multipliers(occ, st, zdd, set, info)
         ! the sliding constraints' multipliers (issue 15, errata D-4b): z'' and
         ! the work they dissipate and supply, as occupant_rhs
         if (set%n > 0 .and. info == 0) then
            do c = 1, set%n
               zdd = zdd + set%y_cols(:, c)*set%lam_clipped(c)
               if (set%aux_at(c) > 0) dydt(set%aux_at(c)) = dydt(set%aux_at(c)) &
                                                           - set%lam_clipped(c)*(dot_product(set%d(:, c), st%zdot) &
                                                                                 + set%offset(c))
               if (set%aux_supplied(c) > 0) dydt(set%aux_supplied(c)) = dydt(set%aux_supplied(c)) &
                                                                       - set%lam_clipped(c)*set%offset(c)
            end do
         end if
      end if
      dydt(occ%z_offset + 1:occ%z_offset + n_dof) = st%zdot
      dydt(occ%zdot_offset + 1:occ%zdot_offset + n_dof) = zdd
   end subroutine occupant_rhs_kept

   !> The active sliding constraints (issue 15) held at zdd: their
   !! multipliers, each clipped to its range, added to zdd, and the power
   !! each dissipates to its effect's work (dydt).
   pure subroutine slide(occ, st, y, zdd, dydt, info)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(inout) :: zdd(n_dof)
      real(wp), intent(inout), contiguous :: dydt(:)
      integer, intent(out) :: info
      type(slide_set_t) :: set
      integer :: c
      info = 0
      call gather_slides(occ, st, y, set)
      if (set%n == 0) return
      call set_multipliers(occ, st, zdd, set, info)
      if (info /= 0) return
      do c = 1, set%n
         zdd = zdd + set%y_cols(:, c)*set%lam_clipped(c)
         ! the friction's power at its sliding velocity, dissipated, and the
         ! rest of the force's power, supplied by the vehicle (sliding_surface)
         if (set%aux_at(c) > 0) dydt(set%aux_at(c)) = dydt(set%aux_at(c)) &
                                                     - set%lam_clipped(c)*(dot_product(set%d(:, c), st%zdot) + set%offset(c))
         if (set%aux_supplied(c) > 0) dydt(set%aux_supplied(c)) = dydt(set%aux_supplied(c)) &
                                                                 - set%lam_clipped(c)*set%offset(c)
      end do
   end subroutine slide

   !> The switching functions of the occupant's sliding constraints at
   !! st (issue 15), two per constraint its effects may hold, in the order
   !! of the effects and their constraints: the multiplier minus lo and hi
   !! minus the multiplier for an active one, 1 for one not active. They
   !! cost the forces and the solve, only while one is active.
   pure subroutine occupant_slide_switches(occ, st, y, g, rates, counts)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out) :: g(:)
      real(wp), intent(inout), contiguous :: rates(:)    !< workspace: y's size
      integer(i8), intent(inout) :: counts(:)            !< workspace: at least occ's effects
      type(slide_set_t) :: set
      real(wp) :: zdd(n_dof)
      integer :: c, info
      g = 1.0_wp
      call gather_slides(occ, st, y, set)
      if (set%n == 0) return
      call unconstrained(occ, st, y, zdd, info, rates, counts)
      if (info == 0) call set_multipliers(occ, st, zdd, set, info)
      if (info /= 0) return
      do c = 1, set%n
         g(2*set%pos(c) - 1) = set%lam(c) - set%lo(c)
         g(2*set%pos(c)) = set%hi(c) - set%lam(c)
      end do
   end subroutine occupant_slide_switches

   !> On an accepted state (memory): every active sliding constraint whose
   !! multiplier lies outside its range leaves its surface (the effect's
   !! release), the farthest first, the rest solved again without it;
   !! changed: one did (the right-hand side jumped there).
   subroutine occupant_settle(occ, st, y, changed, rates, counts)
      type(occupant_t), intent(inout) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      logical, intent(out) :: changed
      real(wp), intent(inout), contiguous :: rates(:)    !< workspace: y's size
      integer(i8), intent(inout) :: counts(:)            !< workspace: at least occ's effects
      type(slide_set_t) :: set
      real(wp) :: zdd(n_dof), v, v_max
      integer :: c, c_max, round, info
      changed = .false.
      do round = 1, occ%n_slide
         call gather_slides(occ, st, y, set)
         if (set%n == 0) return
         call unconstrained(occ, st, y, zdd, info, rates, counts)
         if (info == 0) call set_multipliers(occ, st, zdd, set, info)
         if (info /= 0) return
         v_max = 0.0_wp
         c_max = 0
         do c = 1, set%n
            ! how far outside its range, relative to the range (an empty one,
            ! a friction without load, lies outside by any excess)
            v = max(set%lo(c) - set%lam(c), set%lam(c) - set%hi(c))
            if (v > 0.0_wp) then
               if (set%hi(c) - set%lo(c) > v/huge(1.0_wp)) then
                  v = v/(set%hi(c) - set%lo(c))
               else
                  v = huge(1.0_wp)
               end if
            end if
            if (v > v_max) then
               v_max = v
               c_max = c
            end if
         end do
         if (c_max == 0) return
         call occ%effects(set%owner(c_max))%e%release(set%slot(c_max), set%lam(c_max) > set%hi(c_max))
         changed = .true.
      end do
   end subroutine occupant_settle

   !> Effect k's generalized force from its active sliding constraints at
   !! st, added to b (its recorded generalized force: the multipliers as
   !! the motion has them, clipped).
   pure subroutine occupant_slide_forces(occ, st, y, k, b)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      integer, intent(in) :: k
      real(wp), intent(inout) :: b(n_dof)
      type(slide_set_t) :: set
      real(wp) :: zdd(n_dof)
      real(wp), allocatable :: rates(:)
      integer(i8), allocatable :: counts(:)
      integer :: c, info
      if (occ%effects(k)%e%n_slide == 0) return
      call gather_slides(occ, st, y, set)
      if (.not. any(set%owner(1:set%n) == k)) return
      allocate (rates(size(y)), counts(size(occ%effects)))     ! (at a print time only)
      call unconstrained(occ, st, y, zdd, info, rates, counts)
      if (info == 0) call set_multipliers(occ, st, zdd, set, info)
      if (info /= 0) return
      do c = 1, set%n
         if (set%owner(c) == k) b = b + set%d(:, c)*set%lam_clipped(c)
      end do
   end subroutine occupant_slide_forces

   !> The active sliding constraints of occ's effects at st (gather_slides,
   !! for a print time's frame: set%n of them).
   pure subroutine occupant_active_slides(occ, st, y, set)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      type(slide_set_t), intent(out) :: set
      set%n = 0
      if (occ%n_slide > 0) call gather_slides(occ, st, y, set)
   end subroutine occupant_active_slides

   !> Every effect's generalized force from the active sliding constraints
   !! set (occupant_active_slides, at least one) added to v(at(k) + 1 :
   !! at(k) + n_dof), effect k's (none where at(k) < 0 or k > size(at)),
   !! given b_all, the sum of the effects' forces at st as occupant_forces
   !! gives it: occupant_slide_forces for every k at once, the same bits,
   !! without the effects' forces again (a print time's frame has them,
   !! issue 16 section 4).
   pure subroutine occupant_add_slide_forces(occ, st, set, b_all, v, at)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      type(slide_set_t), intent(inout) :: set
      real(wp), intent(in) :: b_all(n_dof)
      real(wp), intent(inout) :: v(:)
      integer, intent(in) :: at(:)
      real(wp) :: zdd(n_dof)
      integer :: c, info, k
      call body_accelerations(occ%bc, st%c, st%s, b_all, zdd, info, occ%solver)    ! (unconstrained's)
      if (info == 0) call set_multipliers(occ, st, zdd, set, info)
      if (info /= 0) return
      do c = 1, set%n
         k = set%owner(c)
         if (k > size(at)) cycle
         if (at(k) < 0) cycle
         v(at(k) + 1:at(k) + n_dof) = v(at(k) + 1:at(k) + n_dof) + set%d(:, c)*set%lam_clipped(c)
      end do
   end subroutine occupant_add_slide_forces

   !> z''_0 = A^-1 b at st, b all the effects' forces (no constraint).
   pure subroutine unconstrained(occ, st, y, zdd, info, rates, counts)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      real(wp), intent(out) :: zdd(n_dof)
      integer, intent(out) :: info
      real(wp), intent(inout), contiguous :: rates(:)    !< workspace (the effects' rates, not kept)
      integer(i8), intent(inout) :: counts(:)            !< workspace (not counted as evaluations)
      real(wp) :: b(n_dof)
      call occupant_forces(occ, st, y, b, rates, counts(1:size(occ%effects)))
      call body_accelerations(occ%bc, st%c, st%s, b, zdd, info, occ%solver)
   end subroutine unconstrained

   !> The active sliding constraints of occ's effects at st, packed: all of
   !! them, as occ%n_slide <= max_slides (occupant_rhs refuses an occupant
   !! with more, slides_overflow; such an occupant gets none here).
   pure subroutine gather_slides(occ, st, y, set)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in), contiguous :: y(:)
      type(slide_set_t), intent(out) :: set
      type(slide_t) :: sk(max_slides)
      integer :: q, k, j, ns, xo, ao, base
      set%n = 0
      base = 0
      if (occ%n_slide > max_slides) return
      do q = 1, size(occ%sliding)
         k = occ%sliding(q)
         xo = occ%extra_offset(k)
         ao = occ%aux_offset(k)
         associate (e => occ%effects(k)%e)
            ns = e%n_slide
            call e%slides(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux), sk(1:ns))
            do j = 1, ns
               if (.not. sk(j)%active) cycle
               set%n = set%n + 1
               set%d(:, set%n) = sk(j)%d
               set%lo(set%n) = sk(j)%lo
               set%hi(set%n) = sk(j)%hi
               set%offset(set%n) = sk(j)%offset
               set%bias(set%n) = sk(j)%bias
               set%aux_at(set%n) = 0
               if (sk(j)%aux_dissipated > 0) set%aux_at(set%n) = ao + sk(j)%aux_dissipated
               set%aux_supplied(set%n) = 0
               if (sk(j)%aux_supplied > 0) set%aux_supplied(set%n) = ao + sk(j)%aux_supplied
               set%owner(set%n) = k
               set%slot(set%n) = j
               set%pos(set%n) = base + j
            end do
            base = base + e%n_slide
         end associate
      end do
   end subroutine gather_slides

   !> The multipliers of the set (lam, and lam_clipped to their ranges)
   !! and A^-1 d of each, given z''_0.
   pure subroutine set_multipliers(occ, st, zdd0, set, info)
      type(occupant_t), intent(in) :: occ
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: zdd0(n_dof)
      type(slide_set_t), intent(inout) :: set
      integer, intent(out) :: info
      integer :: n
      n = set%n
      call sliding_multipliers(occ%bc, st%c, st%s, occ%solver, zdd0, set%d(:, 1:n), set%bias(1:n), set%lam(1:n), &
                               set%y_cols(:, 1:n), info)
      set%lam_clipped(1:n) = max(set%lo(1:n), min(set%hi(1:n), set%lam(1:n)))
   end subroutine set_multipliers
end module occupant
