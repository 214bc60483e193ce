!> Report C.4.e, the belt forces B of b = C - G + J + S + B + Q: a lap belt
!! wrapping the hip (j = 1) and a torso belt acting at two points of the
!! torso centre lines (j = 2 on the centre torso, j = 3 on the upper
!! torso), as NBELT (*OPTIONS) calls for them (docs/belts.md).
!!
!! For each section the geometry (belt_geometry: C.4.e, C.2 with C2-1..C2-3,
!! BE-2, A-B1) gives the nominal deformation delta_j, its rate and its
!! gradient. The sections form chains that each carry one tension
!! (*BELTOPTIONS COUPLING): every section alone (the report's phase two), the
!! two torso sections together, or all three. A chain's deformation is the
!! sum of its sections' delta_j less their slack Delta_j; it is shared
!! between the webbing of each section and the body surface under it - the
!! abdomen (material 11) under the lap belt, the chest (material 12) under
!! the torso belt - by belt_shared_deflection, each element with its own
!! recurrent-loading memory (figure 18). A material without a loading
!! curve is rigid: the webbing then takes the whole deformation.
!!
!! Generalized forces: B = -F sum_j d(delta_j)/dz over the chain's sections
!! (erratum BE-1: the printed B_2, B_3 are not this).
!!
!! Energies (C.6; docs/loading.md 4): each element's stored energy is a
!! function of its deformation and memory, its dissipated energy what its
!! memory booked at turning points plus the work of its rate terms
!! (integrated, an auxiliary quantity); and the work the vehicle supplies
!! through the belt,
!! integrated with the rate F (s' - g . z'), g = sum_j d(delta_j)/dz: the
!! part of the chain's deformation rate that the moving anchorages make
!! (the vehicle's motion at fixed z). Its difference from F s' is B . z',
!! the power of the belt on the body, so body kinetic energy + stored +
!! dissipated - supplied stays constant (docs/belts.md 5).
!!
!! Memory (figure 18: cycle, turning point, residual deformation of every
!! element) changes only in accept, from the accepted state.
!!
!! A rate-dependent body under a webbing (the chest, the abdomen) has its
!! deflection as a state of the chain (series_chain: one tension in every
!! element, each with its own rate term), integrated with the motion. Each
!! chain integrates one more auxiliary quantity: the unknown of its
!! shared-deflection search, whose rate the split gives. It is only the
!! search's start: the forces do not depend on it (docs/belts.md 3).
module belt_forces
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
   use kinds, only: wp, deg
   use strings, only: num, itoa, upper
   use model, only: model_t, n_dof, n_seg, belt_card_lap2, coupling_torso
   use effect_base, only: effect_t, body_state_t, kept_inputs_t, kept_set, kept_matches
   use effect_events, only: accept_result_t
   use effect_peaks, only: effect_peak_t
   use effect_energies, only: energy_stored, energy_dissipated, energy_supplied, n_energy_kinds
   use point_forces, only: point_force_list_t, point_force_add
   use output_series, only: output_series_t, series_new, column
   use belt_geometry, only: belt_section_geometry_t, belt_kinematics_t, belt_body_t, &
      lap_belt_geometry, torso_belt_geometry, belt_kinematics, belt_body_of_state, belt_body_fill, belt_section_add, &
      lap_wrap, belt_lap
   use recurrent_loading, only: recurrent_law_t, belt_law, material_law
   use series_chain, only: max_chain, chain_split_t, chain_split_text, split_ok, chain_new, chain_relaxing, &
      chain_n_aux, chain_n_switch
   use belt_shared_deflection, only: belt_chain_t, belt_chain_n_aux, belt_chain_split, belt_chain_rates, &
      belt_chain_accept, belt_chain_energies, scaled_law, belt_chain_switches
   implicit none
   private

   public :: belt_effect_t, belt_chain_t, belt_effect, belt_part_lap, belt_part_torso, belt_part_all
   public :: belt_section_state, belt_state_t, max_belt_sections
   public :: out_force, out_angle, out_deformation, out_rate, out_energy

   !> Which belts an effect holds (the factory builds one effect per part).
   integer, parameter :: belt_part_lap = 1, belt_part_torso = 2, belt_part_all = 3
   !> Sections of one effect at most (the lap belt's two sides and the torso's two).
   integer, parameter :: max_belt_sections = 4
   !> The body materials under the belts (Table 4).
   integer, parameter :: material_abdomen = 11, material_chest = 12
   !> The effect's output series (item numbers).
   integer, parameter :: out_force = 1, out_angle = 2, out_deformation = 3, out_rate = 4, out_energy = 5

   type, extends(effect_t) :: belt_effect_t
      integer :: n_sections = 0
      type(belt_section_geometry_t) :: geom(max_belt_sections)
      integer :: card(max_belt_sections) = 0          !< j of its *BELTS card
      integer :: chain_of(max_belt_sections) = 0
      integer :: position(max_belt_sections) = 0      !< its place in its chain
      character(len=8) :: label(max_belt_sections) = ' '
      integer :: n_chains = 0
      type(belt_chain_t) :: chain(max_belt_sections)
      real(wp) :: length(n_seg) = 0.0_wp              !< segment lengths (L_1, L_2 place joints 2, 3)
      integer :: last_segment = 3                     !< the highest segment its sections lie on
      integer :: max_iter = 60
      !> each chain's deformation, its rate and its split at the evaluation
      !! that ended the step (add_forces_kept), for accept, and the inputs
      !! they were computed from (issue 16 section 4: a cache, forgotten at
      !! every accept)
      real(wp) :: kept_s(max_belt_sections) = 0.0_wp, kept_s_dot(max_belt_sections) = 0.0_wp
      type(chain_split_t) :: kept_split(max_belt_sections)
      type(kept_inputs_t) :: kept
      !> each chain's largest tension over the accepted steps (lb) and when:
      !! a study's criteria (study_peaks), kept in accept
      real(wp) :: tension_max(max_belt_sections) = 0.0_wp, t_tension_max(max_belt_sections) = 0.0_wp
   contains
      procedure :: add_forces => belt_add_forces
      procedure :: add_forces_kept => belt_add_forces_kept
      procedure :: chest_deflection => belt_chest_deflection
      procedure :: accept => belt_accept
      procedure :: switches => belt_switches
      procedure :: energy => belt_energy
      procedure :: outputs => belt_outputs
      procedure :: output_values => belt_output_values
      procedure :: frame_values => belt_frame_values
      procedure :: describe => belt_describe
      procedure :: failure_text => belt_failure_text
      procedure :: point_forces => belt_point_forces
      procedure :: study_peaks => belt_study_peaks
   end type belt_effect_t

   !> Everything about the effect's sections at one state (for accept and outputs).
   type :: belt_state_t
      type(belt_kinematics_t) :: kin(max_belt_sections)
      type(chain_split_t) :: split(max_belt_sections)
      real(wp) :: s(max_belt_sections) = 0.0_wp, s_dot(max_belt_sections) = 0.0_wp  !< per chain
      real(wp) :: g(n_dof, max_belt_sections) = 0.0_wp                            !< per chain
   end type belt_state_t

contains

   !> The belts of `part` as the model describes them (NBELT, *BELTS,
   !! *BELTLOADING, *BELTOPTIONS, *MATERIALS 11 and 12): their geometry fixed
   !! at t = 0 from the initial position (C.2), their chains and laws.
   function belt_effect(m, part) result(e)
      type(model_t), intent(in) :: m
      integer, intent(in) :: part
      type(belt_effect_t) :: e
      real(wp) :: joint0(2, 3), theta0(3)
      integer :: k, c, j
      logical :: two_sides

      associate (bt => m%belts, th => m%body%theta0, ln => m%body%length)
         ! the initial interior position of joints 1-3: the hip at the origin (C.1)
         theta0 = th(1:3)
         joint0(:, 1) = 0.0_wp
         joint0(:, 2) = joint0(:, 1) + ln(1)*[cos(th(1)), sin(th(1))]
         joint0(:, 3) = joint0(:, 2) + ln(2)*[cos(th(2)), sin(th(2))]
         e%length = ln
         e%max_iter = bt%max_iter
         two_sides = bt%lap_sides == 2
         select case (part)
         case (belt_part_lap)
            e%name = 'lap_belt'
            e%title = 'lap belt (C.4.e)'
            call add_section(1)
            if (two_sides) call add_section(belt_card_lap2)
            do k = 1, e%n_sections
               call add_chain([k])
            end do
         case (belt_part_torso)
            e%name = 'torso_belt'
            e%title = 'torso belt (C.4.e)'
            call add_section(2)
            call add_section(3)
            if (bt%coupling == coupling_torso) then      ! one tension in both torso sections (D-B3)
               e%title = 'torso belt, one tension (C.4.e)'
               call add_chain([1, 2])
            else
               call add_chain([1])
               call add_chain([2])
            end if
         case default
            e%name = 'belt'
            e%title = 'lap and torso belt, one tension (C.4.e)'
            call add_section(1)
            call add_section(2)
            call add_section(3)
            call add_chain([1, 2, 3])
         end select
      end associate
      e%last_segment = maxval(e%geom(1:e%n_sections)%segment)
      ! its sections' forces act on their segments only (lower and centre torso, upper torso)
      e%acts_on = .false.
      do k = 1, e%n_sections
         e%acts_on(e%geom(k)%segment) = .true.
      end do
      e%needs_vehicle = .true.
      e%external = .true.
      e%has_energy = .true.
      e%n_aux = 0
      do c = 1, e%n_chains
         e%chain(c)%aux_offset = e%n_aux
         e%n_aux = e%n_aux + belt_chain_n_aux(e%chain(c))   ! elements, states, supplied
      end do
      ! the searches' starts last, outside the step-size control (D-B7)
      e%n_aux_start = e%n_chains
      do c = 1, e%n_chains
         e%chain(c)%start_aux = e%n_aux + c
      end do
      e%n_aux = e%n_aux + e%n_aux_start
      do c = 1, e%n_chains
         associate (ch => e%chain(c)%chain)
            do j = 1, ch%n
               e%has_memory = e%has_memory .or. .not. ch%law(j)%elastic
            end do
            e%has_memory = e%has_memory .or. ch%n_states > 0
         end associate
      end do
      ! issue 15: every chain's switches (series_chain's chain_switches; the
      ! kinks they measure from are memory, kept in accept), then each lap
      ! section's wrap (lap_wrap)
      e%n_switch = 0
      do c = 1, e%n_chains
         e%n_switch = e%n_switch + chain_n_switch(e%chain(c)%chain)
      end do
      e%n_switch = e%n_switch + count(e%geom(1:e%n_sections)%kind == belt_lap)
      e%has_memory = e%has_memory .or. e%n_switch > 0
      e%keeps = .true.      ! (its accept takes the chains' splits from the step's last evaluation)
   contains
      !> Section j of the *BELTS cards: its geometry at t = 0 (C.2).
      subroutine add_section(j)
         integer, intent(in) :: j
         integer :: k
         associate (bt => m%belts)
            e%n_sections = e%n_sections + 1
            k = e%n_sections
            e%card(k) = j
            if (j == 1 .or. j == belt_card_lap2) then
               e%geom(k) = lap_belt_geometry(bt%h(j), bt%length_anchor(j), bt%phi_anchor(j), joint0(:, 1), theta0(1))
               e%label(k) = 'lap'
               if (two_sides) e%label(k) = trim(merge('lap_a', 'lap_b', j == 1))
            else
               e%geom(k) = torso_belt_geometry(j, bt%h(j), bt%length0(j), bt%phi0(j), joint0(:, j), theta0(j))
               e%label(k) = 'torso'//itoa(j)
            end if
         end associate
      end subroutine add_section

      !> A chain of the effect's sections ks: per section its webbing (the
      !! *BELTLOADING law; half of it for each of two lap sides) and, when the
      !! material has a loading curve, the body surface under it.
      subroutine add_chain(ks)
         integer, intent(in) :: ks(:)
         integer :: q, k, j, jl, l, c, n
         real(wp) :: factor
         type(recurrent_law_t) :: law(max_chain)
         e%n_chains = e%n_chains + 1
         c = e%n_chains
         n = 0
         associate (ch => e%chain(c))
            ch%n_sections = size(ks)
            do q = 1, size(ks)
               k = ks(q)
               j = e%card(k)
               ch%section(q) = k
               e%chain_of(k) = c
               e%position(k) = q
               ch%slack = ch%slack + m%belts%slack(j)
               factor = 1.0_wp
               if (two_sides .and. (j == 1 .or. j == belt_card_lap2)) factor = 0.5_wp   ! each side half the law (D-B5)
               n = n + 1
               ch%webbing(q) = n
               jl = j
               if (j == belt_card_lap2) jl = 1          ! the lap belt's second side: the lap law
               law(n) = scaled_law(belt_law(m%loading, jl), factor)
               l = merge(material_abdomen, material_chest, j == 1 .or. j == belt_card_lap2)
               if (l == material_chest .and. m%loading%material_curve(l) > 0) e%deflects_chest = .true.
               if (m%loading%material_curve(l) > 0) then       ! else the body is rigid (D-B6)
                  n = n + 1
                  ch%body(q) = n
                  law(n) = scaled_law(material_law(m%materials, m%loading, l), factor)
               end if
            end do
            ch%chain = chain_new(law(1:n), max_iter=m%belts%max_iter)
         end associate
      end subroutine add_chain
   end function belt_effect

   !> Kinematics and splits of every section and chain at a state (aux: the
   !! effect's auxiliary quantities, for the searches' starts).
   pure function belt_section_state(this, st, aux) result(bs)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: aux(:)
      type(belt_state_t) :: bs
      type(belt_body_t) :: bb
      integer :: k, c, q
      bb = belt_body_of_state(this%length, st%z, st%zdot, st%c, st%s, st%vehicle%pos, st%vehicle%vel)
      do c = 1, this%n_chains
         associate (ch => this%chain(c))
            bs%s(c) = -ch%slack
            bs%s_dot(c) = 0.0_wp
            bs%g(:, c) = 0.0_wp
            do q = 1, ch%n_sections
               k = ch%section(q)
               bs%kin(k) = belt_kinematics(this%geom(k), bb)
               bs%s(c) = bs%s(c) + bs%kin(k)%delta
               bs%s_dot(c) = bs%s_dot(c) + bs%kin(k)%delta_rate
               bs%g(:, c) = bs%g(:, c) + bs%kin(k)%gradient
            end do
            call belt_chain_split(ch, bs%s(c), bs%s_dot(c), aux, bs%split(c))
         end associate
      end do
   end function belt_section_state

   !> The chest's deflection under the torso belt (issue 18): the largest
   !! share of the shared deflection (D-B2) that the chest's material (12)
   !! takes under a torso section at st (in; 0 for a rigid chest).
   pure real(wp) function belt_chest_deflection(this, st, extra, aux) result(d)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(belt_state_t) :: bs
      integer :: k, q
      associate (u1 => size(extra))
      end associate
      d = 0.0_wp
      if (.not. this%deflects_chest) return
      bs = belt_section_state(this, st, aux)
      do k = 1, this%n_sections
         if (this%card(k) == 1 .or. this%card(k) == belt_card_lap2) cycle      ! the lap belt's: the abdomen
         q = this%position(k)
         associate (ch => this%chain(this%chain_of(k)))
            if (ch%body(q) > 0) d = max(d, bs%split(this%chain_of(k))%x(ch%body(q)))
         end associate
      end do
   end function belt_chest_deflection

   !> Each section's tension on the body (its chain's F) as a force -F e
   !! at the point where it acts (belt_kinematics_t), turned from the
   !! interior into the inertial frame: X = x_c + R(Φ)ᵀ x (for the joint
   !! reactions; the list's virtual work is B).
   pure subroutine belt_point_forces(this, st, extra, aux, list)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(point_force_list_t), intent(inout) :: list
      type(belt_state_t) :: bs
      associate (u1 => size(extra))
      end associate
      bs = belt_section_state(this, st, aux)
      call belt_state_point_forces(this, st, bs, list)
   end subroutine belt_point_forces

   !> The sections' forces on the body (belt_point_forces) from their state bs.
   pure subroutine belt_state_point_forces(this, st, bs, list)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      type(belt_state_t), intent(in) :: bs
      type(point_force_list_t), intent(inout) :: list
      real(wp) :: c, s, f
      integer :: k
      c = cos(st%vehicle%pos(3))
      s = sin(st%vehicle%pos(3))
      do k = 1, this%n_sections
         f = bs%split(this%chain_of(k))%force
         if (.not. f > 0.0_wp) cycle
         associate (p => bs%kin(k)%point, d => -f*bs%kin(k)%direction)
            call point_force_add(list, this%geom(k)%segment, &
                                 st%vehicle%pos(1:2) + [c*p(1) + s*p(2), -s*p(1) + c*p(2)], &
                                 [c*d(1) + s*d(2), -s*d(1) + c*d(2)])
         end associate
      end do
   end subroutine belt_state_point_forces

   !> B = -F sum_j d(delta_j)/dz per chain (C.4.e, BE-1), and the rates of the
   !! auxiliary quantities: per element W, E_abs, D_v (E6-2), per chain the
   !! supplied work F (s' - g . z') and the search's start. A split that
   !! fails makes its rates NaN: the system reports the evaluation as
   !! failed, with failure_text. (Written out rather than through
   !! belt_section_state: it runs at every evaluation.)
   pure subroutine belt_add_forces(this, st, extra, aux, b, extra_rate, aux_rate)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      type(belt_body_t) :: bb
      type(chain_split_t) :: sp
      real(wp) :: s, s_dot, g(n_dof)
      integer :: c, a
      associate (u1 => size(extra), u2 => size(extra_rate))
      end associate
      call belt_body_fill(this%length, st%z, st%zdot, st%c, st%s, st%vehicle%pos, st%vehicle%vel, &
                          this%last_segment, bb)
      do c = 1, this%n_chains
         associate (ch => this%chain(c))
            call chain_deformation(this, ch, bb, s, s_dot, g)
            call belt_chain_split(ch, s, s_dot, aux, sp)
            if (sp%status /= split_ok) then
               a = ch%aux_offset
               aux_rate(a + 1:a + belt_chain_n_aux(ch)) = ieee_value(0.0_wp, ieee_quiet_nan)
               aux_rate(ch%start_aux) = ieee_value(0.0_wp, ieee_quiet_nan)
               cycle
            end if
            b = b - sp%force*g
            ! the work of the moving anchorages: F times the deformation rate at fixed z (D-B4)
            call belt_chain_rates(ch, sp, s_dot - dot_product(g, st%zdot), aux_rate)
         end associate
      end do
   end subroutine belt_add_forces

   !> belt_add_forces at the evaluation that ends a step (effect_t's
   !! add_forces_kept): the same bits (its loop, written out again so that
   !! add_forces stays as it is), and each chain's s, s' and split kept for
   !! accept, tagged by st and aux.
   subroutine belt_add_forces_kept(this, st, extra, aux, b, extra_rate, aux_rate)
      class(belt_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(inout) :: b(n_dof)
      real(wp), intent(out) :: extra_rate(:), aux_rate(:)
      type(belt_body_t) :: bb
      type(chain_split_t) :: sp
      real(wp) :: s, s_dot, g(n_dof)
      integer :: c, a, m
      associate (u1 => size(extra), u2 => size(extra_rate))
      end associate
      call belt_body_fill(this%length, st%z, st%zdot, st%c, st%s, st%vehicle%pos, st%vehicle%vel, &
                          this%last_segment, bb)
      do c = 1, this%n_chains
         associate (ch => this%chain(c))
            call chain_deformation(this, ch, bb, s, s_dot, g)
            call belt_chain_split(ch, s, s_dot, aux, sp)
            this%kept_s(c) = s
            this%kept_s_dot(c) = s_dot
            this%kept_split(c) = sp
            if (sp%status /= split_ok) then
               a = ch%aux_offset
               aux_rate(a + 1:a + belt_chain_n_aux(ch)) = ieee_value(0.0_wp, ieee_quiet_nan)
               aux_rate(ch%start_aux) = ieee_value(0.0_wp, ieee_quiet_nan)
               cycle
            end if
            ! C.4.e: the webbing's tension F along the belt's direction g (its
            ! generalized force, errata BE-1; the work rate of D-B4 and E6-2)
            b = b - sp%force*g
            ! belt_chain_rates(ch, sp, s_dot - dot_product(g, st%zdot), aux_rate),
            ! its three lines: called from belt_add_forces alone, it is inlined
            ! there (a second caller took it out of line: +4.5 M instructions
            ! on the belted driver). test_kept_accept compares the two.
            m = chain_n_aux(ch%chain)
            aux_rate(ch%aux_offset + 1:ch%aux_offset + m) = sp%aux_rate(1:m)
            aux_rate(ch%aux_offset + m + 1) = sp%force*(s_dot - dot_product(g, st%zdot))
            aux_rate(ch%start_aux) = sp%guess_rate
         end associate
      end do
      call kept_set(this%kept, st, extra, aux)
   end subroutine belt_add_forces_kept

   !> The chain's deformation s: its sections' nominal deformations less
   !! its slack (D-B1), with its rate and its gradient in z.
   pure subroutine chain_deformation(this, ch, bb, s, s_dot, g)
      class(belt_effect_t), intent(in) :: this
      type(belt_chain_t), intent(in) :: ch
      type(belt_body_t), intent(in) :: bb
      real(wp), intent(out) :: s, s_dot, g(n_dof)
      integer :: q
      s = -ch%slack
      s_dot = 0.0_wp
      g = 0.0_wp
      do q = 1, ch%n_sections
         call belt_section_add(this%geom(ch%section(q)), bb, s, s_dot, g)
      end do
   end subroutine chain_deformation

   !> After an accepted step: every element's memory from its deformation
   !! and rate at the accepted state (figure 18; series_chain's chain_accept;
   !! a slack chain's rate-dependent body still recovering, its state
   !! moving, still turns); a changed law restarts the stepper. A chain that
   !! is slack and holds no rate-dependent element still loaded, or whose
   !! elements are all elastic and stateless, keeps its memories. Then, for
   !! every chain, the kinks its switching functions measure from (issue 15).
   subroutine belt_accept(this, st, extra, aux, result)
      class(belt_effect_t), intent(inout) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      type(accept_result_t), intent(inout) :: result
      type(belt_body_t) :: bb
      type(chain_split_t) :: sp
      real(wp) :: s, s_dot, g(n_dof)
      integer :: c
      logical :: changed, update, reuse
      associate (u1 => size(extra))
      end associate
      ! each chain's s, s' and split: those kept at the evaluation that ended
      ! the step where it was at st and aux exactly (with the memory as it
      ! is: kept since the last accept), else computed: the same bits
      reuse = kept_matches(this%kept, st, extra, aux)
      this%kept%valid = .false.          ! (the memory may change below)
      if (reuse) then
         this%accepts_reused = this%accepts_reused + 1
      else
         call belt_body_fill(this%length, st%z, st%zdot, st%c, st%s, st%vehicle%pos, st%vehicle%vel, &
                             this%last_segment, bb)
      end if
      do c = 1, this%n_chains
         associate (ch => this%chain(c))
            if (reuse) then
               s = this%kept_s(c)
               s_dot = this%kept_s_dot(c)
               sp = this%kept_split(c)
            else
               call chain_deformation(this, ch, bb, s, s_dot, g)
               call belt_chain_split(ch, s, s_dot, aux, sp)
            end if
            update = .not. (all(ch%chain%law(1:ch%chain%n)%elastic) .and. ch%chain%n_states == 0)   ! no memory
            if (update .and. .not. s > 0.0_wp) then
               update = ch%chain%n_states > 0
               if (update) update = chain_relaxing(ch%chain, aux(ch%aux_offset + 1:ch%aux_offset &
                                                                 + chain_n_aux(ch%chain)))
            end if
            ! the chain's tension at the accepted state, before its memory
            ! changes (as a print time's frame shows it): its peak
            if (sp%force > this%tension_max(c)) then
               this%tension_max(c) = sp%force
               this%t_tension_max(c) = st%t
            end if
            call belt_chain_accept(ch, s, s_dot, aux, sp, update, changed)
            result%restart = result%restart .or. changed
         end associate
      end do
   end subroutine belt_accept

   !> The largest tension of each section over the accepted steps (its
   !! chain's: the sections of a chain carry one tension), for a study's
   !! criteria (C.8: "large forces in the belts themselves"): named
   !! <label>_tension ('lap', 'lap_a', 'lap_b': the lap belt; 'torso2',
   !! 'torso3': the torso belt's sections), in lb; 0 for a belt that never
   !! pulled. Not in the listing nor HDF5 (effect_t%study_peaks).
   function belt_study_peaks(this) result(p)
      class(belt_effect_t), intent(in) :: this
      type(effect_peak_t), allocatable :: p(:)
      integer :: k, c
      allocate (p(this%n_sections))
      do k = 1, this%n_sections
         c = this%chain_of(k)
         p(k) = effect_peak_t(name=trim(this%label(k))//'_tension', title=this%title, &
                              label='largest tension F_'//itoa(this%card(k)), unit='lb', &
                              value=this%tension_max(c), t=this%t_tension_max(c))
      end do
   end function belt_study_peaks

   !> Issue 15: the switching functions of every chain, in order
   !! (series_chain's chain_switches: slack, clip, turning points, kinks of
   !! the curves), then the wrap of each lap section about the hip, where
   !! it leaves the hip (belt_geometry's lap_wrap; docs/belts.md 10).
   pure subroutine belt_switches(this, st, extra, aux, g)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: g(:)
      type(belt_body_t) :: bb
      real(wp) :: s, s_dot, grad(n_dof)
      integer :: c, i, k
      associate (u1 => size(extra))
      end associate
      call belt_body_fill(this%length, st%z, st%zdot, st%c, st%s, st%vehicle%pos, st%vehicle%vel, &
                          this%last_segment, bb)
      i = 0
      do c = 1, this%n_chains
         associate (ch => this%chain(c))
            k = chain_n_switch(ch%chain)
            call chain_deformation(this, ch, bb, s, s_dot, grad)
            call belt_chain_switches(ch, s, s_dot, aux, g(i + 1:i + k))
            i = i + k
         end associate
      end do
      do k = 1, this%n_sections
         if (this%geom(k)%kind /= belt_lap) cycle
         i = i + 1
         g(i) = lap_wrap(this%geom(k), bb)
      end do
   end subroutine belt_switches

   !> Stored and dissipated energy of every element (docs/loading.md 4), and
   !! the work supplied by the vehicle.
   pure subroutine belt_energy(this, st, extra, aux, e)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      type(belt_state_t) :: bs
      real(wp) :: ce(max_chain), de(max_chain), supplied
      integer :: c, n
      associate (u2 => size(extra))
      end associate
      e = 0.0_wp
      bs = belt_section_state(this, st, aux)
      do c = 1, this%n_chains
         n = this%chain(c)%chain%n
         call belt_chain_energies(this%chain(c), bs%split(c), aux, ce, de, supplied)
         e(energy_stored) = e(energy_stored) + sum(ce(1:n))
         e(energy_dissipated) = e(energy_dissipated) + sum(de(1:n))
         e(energy_supplied) = e(energy_supplied) + supplied
      end do
   end subroutine belt_energy

   !> The effect's series: forces (NOUT 1), angles and deformations (2),
   !! rates and energies (3).
   function belt_outputs(this) result(series)
      class(belt_effect_t), intent(in) :: this
      type(output_series_t), allocatable :: series(:)
      integer :: k, c
      character(len=:), allocatable :: t, l
      t = upper(trim(this%title))
      allocate (series(5))
      series(out_force) = series_new('force', t//': TENSION', 'tension F of each section (lb), the force ' &
                                     //'its chain carries (C.4.e): webbing and body surface in series', 1)
      series(out_angle) = series_new('angle', t//': ANGLE PHI', 'direction phi_j of each section, from its ' &
                                     //'anchor to its belt or tangent point, from the interior horizontal ' &
                                     //'(C.4.e, BE-2)', 2)
      series(out_deformation) = series_new('deformation', t//': DEFORMATIONS', 'per section: nominal ' &
                                           //'deformation delta_j (C.4.e), webbing elongation and body ' &
                                           //'deflection (the shared deflection; they add up to delta_j less ' &
                                           //'the slack once it is taken up)', 2)
      series(out_rate) = series_new('rate', t//': DEFORMATION RATES', 'per section: the rates of the ' &
                                    //'nominal deformation, the webbing elongation and the body deflection', 3)
      series(out_energy) = series_new('energy', t//': ENERGIES', 'per section: stored and dissipated energy ' &
                                      //'of the webbing and of the body surface (C.6, E6-2); per chain: the ' &
                                      //'work supplied by the vehicle through the anchorages', 3)
      do k = 1, this%n_sections
         l = trim(this%label(k))
         block
            series(out_force)%col = [series(out_force)%col, column(l, 'lb')]
            series(out_angle)%col = [series(out_angle)%col, column(l, 'rad', 'deg', 1.0_wp/deg)]
            series(out_deformation)%col = [series(out_deformation)%col, column(l//'_nominal', 'in'), &
                                           column(l//'_belt', 'in'), column(l//'_body', 'in')]
            series(out_rate)%col = [series(out_rate)%col, column(l//'_nominal', 'in/s'), &
                                    column(l//'_belt', 'in/s'), column(l//'_body', 'in/s')]
            series(out_energy)%col = [series(out_energy)%col, column(l//'_belt_ce', 'in*lb'), &
                                      column(l//'_belt_de', 'in*lb'), column(l//'_body_ce', 'in*lb'), &
                                      column(l//'_body_de', 'in*lb')]
         end block
      end do
      do c = 1, this%n_chains
         series(out_energy)%col = [series(out_energy)%col, &
                                   column(trim(this%label(this%chain(c)%section(1)))//'_supplied', 'in*lb')]
      end do
   end function belt_outputs

   pure subroutine belt_output_values(this, item, st, extra, aux, values)
      class(belt_effect_t), intent(in) :: this
      integer, intent(in) :: item
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: values(:)
      type(belt_state_t) :: bs
      real(wp) :: ce(max_chain, max_belt_sections), de(max_chain, max_belt_sections), supplied(max_belt_sections)
      integer :: c
      associate (u1 => size(extra))
      end associate
      bs = belt_section_state(this, st, aux)
      ce = 0.0_wp
      de = 0.0_wp
      supplied = 0.0_wp
      if (item == out_energy) then
         do c = 1, this%n_chains
            call belt_chain_energies(this%chain(c), bs%split(c), aux, ce(:, c), de(:, c), supplied(c))
         end do
      end if
      call belt_item_values(this, bs, item, ce, de, supplied, values)
   end subroutine belt_output_values

   !> Series item of the belt (belt_outputs' layout) into v, from the
   !! sections' state bs and, for the energies, each chain's elements'
   !! stored and dissipated energies ce, de and its supplied work.
   pure subroutine belt_item_values(this, bs, item, ce, de, supplied, v)
      class(belt_effect_t), intent(in) :: this
      type(belt_state_t), intent(in) :: bs
      integer, intent(in) :: item
      real(wp), intent(in) :: ce(:, :), de(:, :), supplied(:)
      real(wp), intent(out) :: v(:)
      integer :: k, q, i, ic
      v = 0.0_wp
      do k = 1, this%n_sections
         ic = this%chain_of(k)
         q = this%position(k)
         associate (ch => this%chain(ic), sp => bs%split(ic))
            select case (item)
            case (out_force)
               v(k) = sp%force
            case (out_angle)
               v(k) = bs%kin(k)%phi
            case (out_deformation)
               v(3*k - 2) = bs%kin(k)%delta
               v(3*k - 1) = sp%x(ch%webbing(q))
               if (ch%body(q) > 0) v(3*k) = sp%x(ch%body(q))
            case (out_rate)
               v(3*k - 2) = bs%kin(k)%delta_rate
               v(3*k - 1) = sp%rate(ch%webbing(q))
               if (ch%body(q) > 0) v(3*k) = sp%rate(ch%body(q))
            case (out_energy)
               i = ch%webbing(q)
               v(4*k - 3:4*k - 2) = [ce(i, ic), de(i, ic)]
               i = ch%body(q)
               if (i > 0) v(4*k - 1:4*k) = [ce(i, ic), de(i, ic)]
            end select
         end associate
      end do
      if (item == out_energy) v(4*this%n_sections + 1:4*this%n_sections + this%n_chains) = supplied(1:this%n_chains)
   end subroutine belt_item_values

   !> A print time's frame (effect_t's frame_values): the sections' state
   !! and splits (belt_section_state) once for the energies, the five series
   !! and the point forces, each chain's energies once, the same bits as
   !! belt_energy, belt_output_values and belt_point_forces each computing
   !! them, and the generalized force from them too: a chain's s, s' and
   !! gradient in belt_section_state are chain_deformation's, the same
   !! additions in the same order (each section adds at most one term to an
   !! entry of the gradient, so summing its own gradient from 0 first
   !! changes nothing: 0 + a = a, a sum that starts from +0 never being -0;
   !! test_frame_values checks it with the torso's two sections on one
   !! tension), and so is its split.
   pure subroutine belt_frame_values(this, st, extra, aux, e, values, at, width, gf, b, pf, list, sums, b_sum)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      real(wp), intent(out) :: e(n_energy_kinds)
      real(wp), intent(inout) :: values(:)
      integer, intent(in) :: at(:), width(:)
      logical, intent(in) :: gf, pf, sums
      real(wp), intent(inout) :: b(n_dof), b_sum(n_dof)
      type(point_force_list_t), intent(inout) :: list
      type(belt_state_t) :: bs
      real(wp) :: ce(max_chain, max_belt_sections), de(max_chain, max_belt_sections), supplied(max_belt_sections)
      integer :: n, item, ic
      associate (u1 => size(extra))
      end associate
      bs = belt_section_state(this, st, aux)
      ! belt_energy
      e = 0.0_wp
      do ic = 1, this%n_chains
         n = this%chain(ic)%chain%n
         call belt_chain_energies(this%chain(ic), bs%split(ic), aux, ce(:, ic), de(:, ic), supplied(ic))
         e(energy_stored) = e(energy_stored) + sum(ce(1:n, ic))
         e(energy_dissipated) = e(energy_dissipated) + sum(de(1:n, ic))
         e(energy_supplied) = e(energy_supplied) + supplied(ic)
      end do
      ! belt_output_values
      do item = 1, min(size(at), out_energy)
         if (at(item) < 0) cycle
         call belt_item_values(this, bs, item, ce, de, supplied, values(at(item) + 1:at(item) + width(item)))
      end do
      if (gf) call add_forces_into(b)
      if (sums) call add_forces_into(b_sum)
      if (pf) call belt_state_point_forces(this, st, bs, list)
   contains
      !> belt_add_forces' B added to bb
      pure subroutine add_forces_into(bb)
         real(wp), intent(inout) :: bb(n_dof)
         integer :: jc
         do jc = 1, this%n_chains
            if (bs%split(jc)%status /= split_ok) cycle
            bb = bb - bs%split(jc)%force*bs%g(:, jc)
         end do
      end subroutine add_forces_into
   end subroutine belt_frame_values

   !> One line for the listing: the sections, their anchors and chains.
   function belt_describe(this) result(text)
      class(belt_effect_t), intent(in) :: this
      character(len=:), allocatable :: text
      integer :: k, c
      text = trim(this%title)//':'
      do k = 1, this%n_sections
         c = this%chain_of(k)
         text = text//' '//trim(this%label(k))//' anchor ('//num(this%geom(k)%anchor(1), 7)//', ' &
                //num(this%geom(k)%anchor(2), 7)//') in'
         if (this%chain(c)%body(this%position(k)) == 0) text = text//' (body rigid)'
         if (k < this%n_sections) text = text//';'
      end do
   end function belt_describe

   !> Why the last evaluation at this state failed ('' when it did not).
   pure function belt_failure_text(this, st, extra, aux) result(text)
      class(belt_effect_t), intent(in) :: this
      type(body_state_t), intent(in) :: st
      real(wp), intent(in) :: extra(:), aux(:)
      character(len=:), allocatable :: text
      type(belt_state_t) :: bs
      integer :: c
      associate (u1 => size(extra))
      end associate
      text = ''
      bs = belt_section_state(this, st, aux)
      do c = 1, this%n_chains
         if (bs%split(c)%status == split_ok) cycle
         text = trim(this%title)//', '//trim(this%label(this%chain(c)%section(1)))//': ' &
                //chain_split_text(bs%split(c), bs%s(c), bs%s_dot(c), this%max_iter, ' (*BELTOPTIONS ITER)')
         return
      end do
   end function belt_failure_text
end module belt_forces
