!> The occupant's body from the deck (report C.1, Table 1, Table 6, figures
!! 9 and 10): the segments, contact arcs and initial position (*SEGMENTS,
!! *ARCS, *INITIAL) and the joints with their restraints and stop curves
!! (*JOINTS, *RESTRAINTS, *STOPCURVE) - each section's builder, which reads
!! the fields by the names of the card table, and its validator, which
!! checks what single fields cannot (lengths that join segments, stops in
!! order and about the initial angles, curves that rise).
module body_input
   use kinds, only: wp, deg
   use error_handling, only: error_t
   use strings, only: itoa, num
   use deck_cards, only: g_segments, g_joints, g_restraints, g_stopcurve, g_arcs, g_initial
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: card_value, card_int, card_given, group_value
   use model_origin, only: model_origin_t, cards, group_present, field_given, card_key, indexed_card, &
      list_card, card_ref, problem
   use model, only: body_section_t, joints_section_t, stop_curve_t, n_joint, n_arc, joint_partner, form_cubic, &
      form_table
   implicit none
   private

   public :: build_body, check_body, build_joints, check_joints

contains

   !> Table 1 segment columns, the contact arcs and the initial position.
   subroutine build_body(deck, b)
      type(deck_t), intent(in) :: deck
      type(body_section_t), intent(out) :: b
      integer :: k, i

      associate (g => deck%group(g_segments))
         do k = 1, g%n
            i = g%card(k)%index
            b%mass(i) = card_value(deck, g_segments, g%card(k), 'M')
            b%inertia(i) = card_value(deck, g_segments, g%card(k), 'I')
            b%length(i) = card_value(deck, g_segments, g%card(k), 'L')
            b%rho(i) = card_value(deck, g_segments, g%card(k), 'RHO')
         end do
      end associate
      associate (g => deck%group(g_initial))
         do k = 1, g%n
            i = g%card(k)%index
            b%theta0(i) = card_value(deck, g_initial, g%card(k), 'THETA')
            b%theta_dot0(i) = card_value(deck, g_initial, g%card(k), 'THETADOT')
         end do
      end associate
      associate (g => deck%group(g_arcs))
         do k = 1, g%n
            i = g%card(k)%index
            b%r_arc(i) = card_value(deck, g_arcs, g%card(k), 'R')
            if (i <= n_arc) then
               b%rho_arc(i) = card_value(deck, g_arcs, g%card(k), 'RHOP')
               b%gamma_arc(i) = card_value(deck, g_arcs, g%card(k), 'GAMMA')
            end if
         end do
      end associate
   end subroutine build_body

   !> The segments' lengths that join the body together, the centres of
   !! gravity within them, the arcs' fields Table 1 defines.
   subroutine check_body(b, orig, err)
      type(body_section_t), intent(in) :: b
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      integer :: k, i
      integer, parameter :: chain(6) = [1, 2, 3, 4, 5, 7]

      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_segments)
      do k = 1, size(cs)
         i = cs(k)%index
         ! the lengths that join segments together (section B) must be positive
         if (any(chain == i) .and. .not. b%length(i) > 0.0_wp) call problem(orig, err, cs(k), &
            'segment '//itoa(i)//': L = '//num(b%length(i))//' in; expected L > 0 (it places the next joint; ' &
            //'section B)', 'L')
         if (any([1, 2, 5, 7] == i) .and. b%rho(i) > b%length(i) .and. b%length(i) > 0.0_wp) &
            call problem(orig, err, cs(k), 'segment '//itoa(i)//': RHO = '//num(b%rho(i)) &
            //' in lies beyond the far joint (L = '//num(b%length(i))//' in)', 'L RHO')
      end do
      cs = cards(orig, g_arcs)
      do k = 1, size(cs)
         i = cs(k)%index
         if (.not. any([2, 3, 4] == i) .and. field_given(orig, g_arcs, cs(k), 'RHOP')) &
            call problem(orig, err, cs(k), 'arc '//itoa(i)//': RHOP is defined for arcs 2-4 only (Table 1); ' &
            //'expected blank', 'RHOP')
         if (.not. any([2, 3] == i) .and. field_given(orig, g_arcs, cs(k), 'GAMMA')) &
            call problem(orig, err, cs(k), 'arc '//itoa(i)//': GAMMA is defined for arcs 2-3 only (Table 1); ' &
            //'expected blank', 'GAMMA')
      end do
   end subroutine check_body

   !> Table 1 joint columns, the restraint forms and their curves.
   subroutine build_joints(deck, jt)
      type(deck_t), intent(in) :: deck
      type(joints_section_t), intent(out) :: jt
      integer :: k, i, side

      jt%xi = group_value(deck, g_joints, 'XI')   ! the default, for joints without a card
      associate (g => deck%group(g_joints))
         do k = 1, g%n
            i = g%card(k)%index
            jt%k_elastic(i) = card_value(deck, g_joints, g%card(k), 'K')
            jt%c_friction(i) = card_value(deck, g_joints, g%card(k), 'CF')
            jt%xi(i) = card_value(deck, g_joints, g%card(k), 'XI')
            associate (r => jt%restraint(i))
               r%lower = card_value(deck, g_joints, g%card(k), 'OMEGA')
               r%upper = card_value(deck, g_joints, g%card(k), 'BOMEGA')
               r%coef_lower = [card_value(deck, g_joints, g%card(k), 'TLOW'), 0.0_wp, 0.0_wp]
               r%coef_upper = [card_value(deck, g_joints, g%card(k), 'THIGH'), 0.0_wp, 0.0_wp]
               r%dislocation_lower = r%lower
               r%dislocation_upper = r%upper
            end associate
         end do
      end associate

      associate (g => deck%group(g_restraints))
         do k = 1, g%n
            i = g%card(k)%index
            associate (r => jt%restraint(i), c => g%card(k))
               r%form = card_int(deck, g_restraints, c, 'FORM')
               r%coef_lower(2:3) = [card_value(deck, g_restraints, c, 'C2LOW'), &
                                    card_value(deck, g_restraints, c, 'C3LOW')]
               r%coef_upper(2:3) = [card_value(deck, g_restraints, c, 'C2HIGH'), &
                                    card_value(deck, g_restraints, c, 'C3HIGH')]
               if (card_given(deck, g_restraints, c, 'DISLOW')) &
                  r%dislocation_lower = card_value(deck, g_restraints, c, 'DISLOW')
               if (card_given(deck, g_restraints, c, 'DISHIGH')) &
                  r%dislocation_upper = card_value(deck, g_restraints, c, 'DISHIGH')
            end associate
         end do
      end associate

      do i = 1, n_joint
         do side = 1, 2
            call build_curve(deck, i, side, jt)
         end do
      end do
   end subroutine build_joints

   !> The stops: OMEGA below BOMEGA with the initial relative angle between
   !! them, the cubic's coefficients only with FORM = CUBIC, the
   !! dislocation limits beyond the stops, each stop curve (check_curve),
   !! and FORM = TABLE exactly where there are stop curves.
   subroutine check_joints(jt, body, orig, err)
      type(joints_section_t), intent(in) :: jt
      type(body_section_t), intent(in) :: body
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      type(card_t) :: rc
      integer :: k, i
      real(wp) :: rel0

      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_joints)
      do k = 1, size(cs)
         i = cs(k)%index
         associate (r => jt%restraint(i))
            if (.not. r%lower < r%upper) then
               call problem(orig, err, cs(k), 'joint '//itoa(i)//': OMEGA = '//num(r%lower/deg) &
                  //' deg must be less than BOMEGA = '//num(r%upper/deg)//' deg', 'OMEGA BOMEGA')
            else if (group_present(orig, g_initial)) then
               ! the stops act on the relative angle alpha_i - alpha_m itself (docs/errata.md D-3)
               rel0 = body%theta0(i) - body%theta0(joint_partner(i))
               if (rel0 < r%lower .or. rel0 > r%upper) &
                  call problem(orig, err, cs(k), 'joint '//itoa(i)//': the initial relative angle ' &
                  //'Theta_'//itoa(i)//' - Theta_'//itoa(joint_partner(i))//' = '//num(rel0/deg) &
                  //' deg lies outside OMEGA..BOMEGA = '//num(r%lower/deg)//'..'//num(r%upper/deg)//' deg (' &
                  //card_ref(orig, indexed_card(orig, g_initial, i))//' and ' &
                  //card_ref(orig, indexed_card(orig, g_initial, joint_partner(i)))//')', 'OMEGA BOMEGA')
            end if
         end associate
      end do

      cs = cards(orig, g_restraints)
      do k = 1, size(cs)
         i = cs(k)%index
         associate (r => jt%restraint(i), c => cs(k))
            if (r%form /= form_cubic .and. (field_given(orig, g_restraints, c, 'C2LOW') &
                .or. field_given(orig, g_restraints, c, 'C3LOW') .or. field_given(orig, g_restraints, c, 'C2HIGH') &
                .or. field_given(orig, g_restraints, c, 'C3HIGH'))) &
               call problem(orig, err, c, 'joint '//itoa(i)//': C2LOW..C3HIGH are used only with FORM = CUBIC; ' &
               //'expected them blank', 'FORM C2LOW C3LOW C2HIGH C3HIGH')
            if (r%dislocation_lower > r%lower) call problem(orig, err, c, 'joint '//itoa(i) &
               //': DISLOW = '//num(r%dislocation_lower/deg)//' deg must not exceed the lower stop angle OMEGA = ' &
               //num(r%lower/deg)//' deg ('//card_ref(orig, indexed_card(orig, g_joints, i))//')', 'DISLOW')
            if (r%dislocation_upper < r%upper) call problem(orig, err, c, 'joint '//itoa(i) &
               //': DISHIGH = '//num(r%dislocation_upper/deg)//' deg must not be below the upper stop angle ' &
               //'BOMEGA = '//num(r%upper/deg)//' deg ('//card_ref(orig, indexed_card(orig, g_joints, i))//')', &
               'DISHIGH')
         end associate
      end do

      do i = 1, n_joint
         call check_curve(jt%restraint(i)%curve_lower, i, 1, orig, err)
         call check_curve(jt%restraint(i)%curve_upper, i, 2, orig, err)
         associate (r => jt%restraint(i))
            if (r%form == form_table) then
               if (.not. (allocated(r%curve_lower%depth) .and. allocated(r%curve_upper%depth))) &
                  call problem(orig, err, indexed_card(orig, g_restraints, i), 'joint '//itoa(i)//': FORM = ' &
                  //'TABLE needs *STOPCURVE cards for both its LOWER and UPPER stops', 'FORM')
            else if (allocated(r%curve_lower%depth) .or. allocated(r%curve_upper%depth)) then
               rc = indexed_card(orig, g_restraints, i)
               if (rc%number > 0) then
                  call problem(orig, err, indexed_card(orig, g_stopcurve, i), 'joint '//itoa(i)//' has ' &
                     //'*STOPCURVE cards but its restraint form is not TABLE ('//card_ref(orig, rc) &
                     //'): give FORM TABLE there')
               else
                  call problem(orig, err, indexed_card(orig, g_stopcurve, i), 'joint '//itoa(i)//' has ' &
                     //'*STOPCURVE cards but its restraint form is not TABLE: add a *RESTRAINTS card with ' &
                     //'FORM TABLE for it')
               end if
            end if
         end associate
      end do
   end subroutine check_joints

   !> The points of one side (1 lower, 2 upper) of one joint's stop curve,
   !! from its *STOPCURVE cards in their order.
   subroutine build_curve(deck, joint, side, jt)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: joint, side
      type(joints_section_t), intent(inout) :: jt
      integer :: k, n
      type(stop_curve_t) :: c

      associate (g => deck%group(g_stopcurve))
         n = count([(on_curve(g%card(k)), k=1, g%n)])
         if (n == 0) return
         allocate (c%depth(n), c%torque(n))
         n = 0
         do k = 1, g%n
            if (.not. on_curve(g%card(k))) cycle
            n = n + 1
            c%depth(n) = card_value(deck, g_stopcurve, g%card(k), 'DEPTH')
            c%torque(n) = card_value(deck, g_stopcurve, g%card(k), 'TORQUE')
         end do
      end associate
      if (side == 1) then
         jt%restraint(joint)%curve_lower = c
      else
         jt%restraint(joint)%curve_upper = c
      end if
   contains
      logical function on_curve(card)
         type(card_t), intent(in) :: card
         on_curve = card%index == joint .and. card_int(deck, g_stopcurve, card, 'SIDE') == side
      end function on_curve
   end subroutine build_curve

   !> A stop curve (side 1 lower, 2 upper, of one joint) starts at DEPTH
   !! = 0, its depths increase, and it has two points at least; point n
   !! is located at the n-th *STOPCURVE card of its joint and side.
   subroutine check_curve(c, joint, side, orig, err)
      type(stop_curve_t), intent(in) :: c
      integer, intent(in) :: joint, side
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t), allocatable :: cs(:)
      type(card_t) :: point
      integer :: k, n
      character(len=:), allocatable :: stop

      if (.not. allocated(c%depth)) return
      allocate (cs(0))      ! (realloc on assignment: a descriptor set first)
      cs = cards(orig, g_stopcurve)
      cs = pack(cs, [(cs(k)%index == joint .and. card_key(orig, g_stopcurve, cs(k), 'SIDE') == side, k=1, size(cs))])
      stop = trim(merge('LOWER', 'UPPER', side == 1))
      do n = 1, size(c%depth)
         point = list_card(orig, g_stopcurve, cs, n)
         if (n == 1 .and. c%depth(1) > 0.0_wp) call problem(orig, err, point, 'joint ' &
            //itoa(joint)//', '//stop//' stop: DEPTH = '//num(c%depth(1)/deg) &
            //' deg; the first point of a stop curve must have DEPTH = 0', 'DEPTH')
         if (n > 1) then
            if (.not. c%depth(n) > c%depth(n - 1)) call problem(orig, err, point, 'joint ' &
               //itoa(joint)//', '//stop//' stop: DEPTH = ' &
               //num(c%depth(n)/deg)//' deg after '//num(c%depth(n - 1)/deg)//' deg ('//card_ref(orig, &
               list_card(orig, g_stopcurve, cs, n - 1))//'); DEPTH must increase from card to card of a stop curve', &
               'DEPTH')
         end if
      end do
      if (size(c%depth) < 2) call problem(orig, err, point, 'joint '//itoa(joint)//', ' &
         //stop//' stop: a stop curve needs at least two points; this is its only card', 'SIDE')
   end subroutine check_curve
end module body_input
