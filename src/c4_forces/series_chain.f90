!> A chain of loading elements in series carrying one tension (docs/
!! loading.md 5): a belt section's webbing and the body under it (C.4.e,
!! figure 19), a contact's body material, padding and backing (C.4.f,
!! figures 23-25). Each element is a recurrent-loading law with its memory
!! (figure 18); an element whose curve has rate terms is rate-dependent.
!!
!! The law (D-B2 as revised in issue 14): every element carries the one
!! tension T with its own force law -
!! - a rate-independent element u: T on its branch, F_b,u(x_u) = T (its
!!   graph's vertical pieces - a padding at its cap, the column held by its
!!   gate, a plastic element held at its maximum - carry any T in their
!!   range);
!! - a rate-dependent element d: T = F_b,d(x_d) + F_v,d(x_d'), its branch
!!   and its rate terms at its own rate (Kelvin-Voigt).
!! With sum x_i = s this is a differential-algebraic system: the
!! deformation x_d of each rate-dependent element is a state of the chain,
!! integrated with the motion (an auxiliary quantity, x_offset + q_d); at a
!! state the rate-independent elements share what the states leave, r = s -
!! sum x_d (series_split, the states held), which fixes T as a function of
!! the state; then x_d' = F_v,d^-1(T - F_b,d(x_d)), and the rate-independent
!! elements share r' = s' - sum x_d' in proportion to their compliances. So
!! T is continuous (a function of continuous states) whatever an element's
!! slope does, and never exceeds what a rate-independent element carries at
!! its deformation (the column's gate and plateau). Where every element is
!! rate-dependent, the last one takes what the others leave (the absorber):
!! T = F_b,a(x_a) + F_v,a(x_a') with x_a' = s' - sum x_d'(T), one equation in
!! T. A single element is the law of loading_curves: T = max(0, F_b + F_v)
!! while F_b > 0. The chain never pulls: while it is slack (T = 0) a
!! rate-dependent element recovers at its damper's rate, F_b,d + F_v,d(x_d')
!! = 0 - the law above at T = 0, so that its rate is continuous where the
!! chain goes slack or is taken up again; its damper dissipates what its
!! spring gives up. Rate terms of an element that bottoms out, is gated or
!! is plastic are not used in a chain of several: its rigid pieces have no
!! rate.
!!
!! Energies (docs/loading.md 4): each element's stored energy is a function
!! of its deformation and memory (recurrent_stored; a gated element's gate
!! adds gate * (x - x_hold) while it is pushed beyond its hold). A
!! rate-independent element dissipates only where its law changes at an
!! accepted step (its stored energy's drops, booked in its memory: a
!! turning point, the gate's work once the column stops); a rate-dependent
!! one dissipates the work done on it, T x', less its stored energy, at the
!! rate (T - F_b) x' >= 0. The chain integrates its whole work T s': what
!! that holds beyond its elements' energies is dissipated by its last
!! rate-dependent element (the others integrate T x'), or where there is
!! none with the first rate-independent one's - so the elements' energies
!! add up to the chain's work exactly, and that element's own work, whose
!! rate follows its state's fast relaxation (docs/loading.md 5, "Cost"), is
!! not integrated. The rest also holds the energy released without work
!! where the chain's deformation jumps (a contact's geometry switching) and
!! the integration's error.
module series_chain
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use kinds, only: wp
   use strings, only: num, itoa
   use loading_curves, only: curve_is_defined, curve_max_slope, curve_kinks_about
   use recurrent_loading, only: recurrent_law_t, loading_memory_t, recurrent_eval, recurrent_accept, &
      recurrent_stored, loading_point_t
   use loading_branch, only: branch_point_t, branch_at, branch_eval, zero_extent, rate_force, rate_slope, rate_inverse, &
      min_slope, rigid_slope, branch_argument, turn_switch, zero_on_side
   use root_search, only: root_search_t, root_begin, root_update, root_running, root_not_finite, bisections
   use series_split, only: max_chain, deformation_split_t, split_deformation, split_ok, split_no_convergence, &
      split_not_finite, path_none, path_pair, path_newton, path_search, region_slack, region_unloaded, &
      region_loaded, force_tol
   implicit none
   private

   public :: max_chain, series_chain_t, chain_split_t, chain_new, chain_split, chain_accept, chain_energies
   public :: chain_set_initial, chain_relaxing, chain_split_text, chain_gates, chain_n_aux, chain_stateful
   public :: chain_stateful_any, chain_slack_split, chain_n_switch, chain_switches, chain_track_kinks
   public :: split_ok, split_no_convergence, split_not_finite
   public :: path_none, path_pair, path_newton, path_search, region_slack, region_unloaded, region_loaded

   !> A chain: its elements' laws and memories, and how they are held.
   type :: series_chain_t
      integer :: n = 0
      type(recurrent_law_t) :: law(max_chain)
      type(loading_memory_t) :: mem(max_chain)
      real(wp) :: cap(max_chain) = 0.0_wp       !< > 0: bottoms out there (figure 25)
      !> > 0: the cap is soft, the element crushed solid stiffening at this
      !! slope (a chain with a rate-dependent element: the chain's stiffest)
      real(wp) :: cap_slope(max_chain) = 0.0_wp
      !> the steering column behind its padding (D-C19): held by a gate, the
      !! force of the element before it at that one's cap
      logical :: gated(max_chain) = .false.
      !> rate-dependent in a chain of several: its deformation is a state,
      !! x_offset + the chain's auxiliary quantity n + state(i)
      logical :: stateful(max_chain) = .false.
      integer :: state(max_chain) = 0
      integer :: n_states = 0
      !> every element rate-dependent: this one takes what the others leave
      integer :: absorber = 0
      !> the one rate-independent element, without cap or gate, where every
      !! other is a state (the belts' chains: a webbing and rate-dependent
      !! bodies); 0: none. Its chain splits directly (lone_split).
      integer :: lone = 0
      !> its rate terms act (a single element; a stateful one; the absorber)
      logical :: rated(max_chain) = .false.
      !> the last rated element (0: none): its dissipated energy is what the
      !! chain's work holds beyond every other energy, not an integral of its
      !! own (chain_energies)
      integer :: rest = 0
      real(wp) :: x_offset(max_chain) = 0.0_wp
      !> the work done on each element before t = 0 (D-C26: an initial
      !! deformation counts as a loading before the run; its stored energy),
      !! and on the whole chain
      real(wp) :: w_initial(max_chain) = 0.0_wp, w_initial_chain = 0.0_wp
      integer :: max_iter = 60
      !> (issue 15) the kinks of each element's curve about its branch's
      !! argument at the last accepted state (curve_kinks_about; -huge,
      !! huge: none): it switches where the argument leaves [lo, hi)
      real(wp) :: kink_lo(max_chain) = -huge(1.0_wp), kink_hi(max_chain) = huge(1.0_wp)
   end type series_chain_t

   !> The chain at one state.
   type :: chain_split_t
      integer :: status = split_ok
      integer :: region = region_slack
      integer :: iterations = 0              !< evaluations of the elements' branches
      integer :: path = path_none            !< the solver of the rate-independent split
      integer :: sweeps = 0
      real(wp) :: force = 0.0_wp             !< T, the tension every element carries
      real(wp) :: guess = 0.0_wp             !< the unknown of the split's search (a start for the next)
      real(wp) :: guess_rate = 0.0_wp        !< its rate
      !> (the arrays for the chain's n elements only, set by chain_split: no
      !! default initialization, which would cost as much as a split)
      real(wp) :: x(max_chain)               !< element deformations
      real(wp) :: rate(max_chain)            !< their rates
      real(wp) :: gate(max_chain)            !< the gated elements' gates
      !> the rates of the chain's auxiliary quantities: per element the work
      !! done on it, T x' (a rate-dependent one's; 0 for the others), the
      !! chain's, T s', then per state its rate
      real(wp) :: aux_rate(2*max_chain + 1)
   end type chain_split_t

contains

   !> A chain of the n laws (the memories fresh), with caps and gates.
   pure function chain_new(law, cap, gated, max_iter) result(ch)
      type(recurrent_law_t), intent(in) :: law(:)
      real(wp), intent(in), optional :: cap(:)
      logical, intent(in), optional :: gated(:)
      integer, intent(in), optional :: max_iter
      type(series_chain_t) :: ch
      logical :: usable(max_chain)
      integer :: i, j
      ch%n = size(law)
      ch%law(1:ch%n) = law
      if (present(cap)) ch%cap(1:ch%n) = cap
      if (present(gated)) ch%gated(1:ch%n) = gated
      if (present(max_iter)) ch%max_iter = max_iter
      do i = 1, ch%n
         call track_kink(ch, i, 0.0_wp)      ! every element undeformed
      end do
      if (ch%n == 1) then
         ch%rated(1) = ch%law(1)%n_rate > 0
         if (ch%rated(1)) ch%rest = 1
         return
      end if
      do i = 1, ch%n
         usable(i) = ch%law(i)%n_rate > 0 .and. curve_is_defined(ch%law(i)%curve) .and. .not. ch%gated(i) &
                     .and. .not. ch%law(i)%plastic .and. .not. ch%cap(i) > 0.0_wp
      end do
      ch%rated(1:ch%n) = usable(1:ch%n)
      ch%rest = findloc(usable(1:ch%n), .true., 1, back=.true.)
      if (all(usable(1:ch%n))) ch%absorber = ch%n
      ! a rate-dependent element's state cannot follow a chain that is rigid -
      ! a padding at its cap with the column held by its gate: the states
      ! would chatter about it - so there the padding, crushed solid,
      ! stiffens at the chain's stiffest slope instead (docs/loading.md 5)
      if (any(usable(1:ch%n))) then
         do i = 1, ch%n
            if (ch%cap(i) > 0.0_wp) ch%cap_slope(i) = maxval([(curve_max_slope(ch%law(j)%curve), j=1, ch%n)])
         end do
      end if
      do i = 1, ch%n
         if (.not. usable(i) .or. i == ch%absorber) cycle
         ch%stateful(i) = .true.
         ch%n_states = ch%n_states + 1
         ch%state(i) = ch%n_states
      end do
      if (ch%absorber == 0 .and. ch%n_states == ch%n - 1) then
         i = findloc(ch%stateful(1:ch%n), .false., 1)
         if (.not. (ch%cap(i) > 0.0_wp .or. ch%gated(i))) ch%lone = i
      end if
   end function chain_new

   !> The chain's auxiliary quantities (docs/loading.md 4): per element the
   !! work done on it (used for the rate-dependent ones), the chain's, then
   !! per state one.
   pure integer function chain_n_aux(ch)
      type(series_chain_t), intent(in) :: ch
      chain_n_aux = ch%n + 1 + ch%n_states
   end function chain_n_aux

   !> Whether element i's deformation is a state of the chain.
   pure logical function chain_stateful(ch, i)
      type(series_chain_t), intent(in) :: ch
      integer, intent(in) :: i
      chain_stateful = ch%stateful(i)
   end function chain_stateful

   !> Whether any element's deformation is a state of the chain.
   pure logical function chain_stateful_any(ch)
      type(series_chain_t), intent(in) :: ch
      chain_stateful_any = ch%n_states > 0
   end function chain_stateful_any

   !> The gates (D-C19): a gated element's, the branch force of the element
   !! before it at that one's cap, with its memory; 0 for the others.
   pure function chain_gates(ch) result(g)
      type(series_chain_t), intent(in) :: ch
      real(wp) :: g(max_chain)
      type(branch_point_t) :: bp
      integer :: i
      g = 0.0_wp
      do i = 2, ch%n
         if (.not. (ch%gated(i) .and. ch%cap(i - 1) > 0.0_wp)) cycle
         bp = branch_at(ch%law(i - 1), ch%mem(i - 1), ch%cap(i - 1))
         g(i) = bp%force
      end do
   end function chain_gates

   !> chain_split's result at any s <= 0 for a chain without states (ok
   !! false for one with states, whose slack depends on them), in the fields
   !! the chain's switching functions read (force, x, gate; the status and
   !! the region): slack, no force, every element at 0 (split_deformation's
   !! slack exit), the gates as chain_split sets them. Without the split's
   !! own work (issue 16 section 4: a contact pair proved slack, pair_switches).
   pure subroutine chain_slack_split(ch, sp, ok)
      type(series_chain_t), intent(in) :: ch
      type(chain_split_t), intent(out) :: sp
      logical, intent(out) :: ok
      ok = ch%n_states == 0 .and. ch%absorber == 0
      sp%x = 0.0_wp
      sp%rate = 0.0_wp
      sp%aux_rate = 0.0_wp
      sp%gate = 0.0_wp
      if (any(ch%gated(2:ch%n))) sp%gate = chain_gates(ch)
   end subroutine chain_slack_split

   !> The chain at total deformation s (slack taken out) and rate s_dot, its
   !! states in aux (the chain's auxiliary quantities, chain_n_aux of them).
   !! guess: a start for the rate-independent split's search (sp%guess of a
   !! nearby state); search: that split by the search by force alone (the
   !! tests' reference), and given at all, the general path also for a chain
   !! that splits directly (lone_split; the tests' reference for it). Pure:
   !! the memories are read, never written.
   pure subroutine chain_split(ch, s, s_dot, aux, sp, guess, search)
      type(series_chain_t), intent(in) :: ch
      real(wp), intent(in) :: s, s_dot
      real(wp), intent(in) :: aux(:)
      type(chain_split_t), intent(out) :: sp
      real(wp), intent(in), optional :: guess
      logical, intent(in), optional :: search
      type(deformation_split_t) :: dsp
      type(loading_point_t) :: pt
      type(branch_point_t) :: bp
      real(wp) :: xf(max_chain), fb(max_chain), w(max_chain), r_dot, t, total
      integer :: i, j, n, n_flat, a

      n = ch%n
      ! (whole arrays, not 1:n: stores in line rather than a call of memset
      ! each; the elements beyond the chain's are never read)
      sp%x = 0.0_wp
      sp%rate = 0.0_wp
      sp%aux_rate = 0.0_wp
      sp%gate = 0.0_wp
      if (any(ch%gated(2:n))) sp%gate = chain_gates(ch)    ! (none gated: all 0)
      if (.not. (ieee_is_finite(s) .and. ieee_is_finite(s_dot))) then
         sp%status = split_not_finite
         return
      end if
      if (ch%lone > 0 .and. .not. present(search)) then
         call lone_split(ch, s, s_dot, aux, sp)
         return
      end if
      if (n == 1) then
         ! one element: the law of loading_curves, T = max(0, F_b + F_v) while F_b > 0
         sp%guess = s
         sp%guess_rate = s_dot
         if (.not. s > 0.0_wp) return
         pt = recurrent_eval(ch%law(1), ch%mem(1), s, s_dot)
         sp%x(1) = s
         sp%rate(1) = s_dot
         sp%force = pt%force
         sp%region = merge(region_loaded, region_unloaded, pt%branch > 0.0_wp)
         sp%aux_rate(2) = pt%force*s_dot
         sp%iterations = 1
         return
      end if
      ! slack without states: what the general path gives there (chain_slack_split:
      ! nothing carried, nothing moves), without it (issue 16 section 4: the
      ! contact pairs near contact but not in it)
      if (ch%n_states == 0 .and. ch%absorber == 0 .and. .not. s > 0.0_wp .and. .not. present(search)) return

      ! the rate-independent elements share what the states leave (held there)
      xf = 0.0_wp
      do i = 1, n
         if (ch%stateful(i)) xf(i) = ch%x_offset(i) + aux(n + 1 + ch%state(i))
      end do
      call split_deformation(n, ch%law, ch%mem, s, ch%max_iter, ch%cap, sp%gate, ch%cap_slope, ch%stateful, xf, dsp, &
                             guess, search)
      sp%status = dsp%status
      sp%region = dsp%region
      sp%iterations = dsp%iterations
      sp%path = dsp%path
      sp%sweeps = dsp%sweeps
      sp%guess = dsp%guess
      if (dsp%status /= split_ok) return
      sp%x = dsp%x                 ! (whole: 0 beyond n, stores in line rather than memcpy)
      do i = 1, n
         fb(i) = 0.0_wp
         if (.not. ch%rated(i)) cycle
         bp = branch_at(ch%law(i), ch%mem(i), sp%x(i))
         fb(i) = bp%force
      end do

      a = ch%absorber
      if (a == 0) then
         t = max(dsp%force, 0.0_wp)
      else
         t = absorber_tension()
         if (t < 0.0_wp) then
            sp%status = split_not_finite
            return
         end if
      end if
      sp%force = t
      ! the states' rates: each rate-dependent element carries T with its own
      ! rate term - slack too (T = 0: it recovers at its damper's rate)
      r_dot = s_dot
      do i = 1, n
         if (.not. ch%stateful(i)) cycle
         sp%rate(i) = rate_inverse(ch%law(i), t - fb(i))
         r_dot = r_dot - sp%rate(i)
         sp%aux_rate(n + 1 + ch%state(i)) = sp%rate(i)
      end do
      ! the rest shared by the rate-independent elements: their compliances
      ! (loaded), their residual deformations (taken up but unloaded)
      w = 0.0_wp
      select case (dsp%region)
      case (region_loaded)
         n_flat = 0
         do i = 1, n
            if (ch%stateful(i)) cycle
            if (.not. dsp%slope(i) > min_slope) n_flat = n_flat + 1
         end do
         total = 0.0_wp
         do i = 1, n
            if (ch%stateful(i)) cycle
            if (n_flat > 0) then
               if (.not. dsp%slope(i) > min_slope) w(i) = 1.0_wp/real(n_flat, wp)   ! a flat branch takes it all
            else if (dsp%slope(i) < rigid_slope) then
               w(i) = 1.0_wp/dsp%slope(i)
               total = total + w(i)
            end if
         end do
         if (n_flat == 0) then
            if (total > 0.0_wp) then
               w(1:n) = w(1:n)/total
            else
               w(1:n) = 0.0_wp          ! every one rigid: the rest takes no rate
            end if
         end if
      case (region_unloaded)
         total = 0.0_wp
         do i = 1, n
            if (.not. ch%stateful(i)) total = total + sp%x(i)
         end do
         do i = 1, n
            if (.not. ch%stateful(i) .and. total > 0.0_wp) w(i) = sp%x(i)/total
         end do
      end select
      ! (only where they are not 0: a slack chain's rates are +0, bit for bit
      ! those of a pair's early exit, D-C29)
      do i = 1, n
         if (.not. ch%stateful(i) .and. w(i) > 0.0_wp) sp%rate(i) = w(i)*r_dot
         if (t > 0.0_wp .and. ch%rated(i) .and. i /= ch%rest) sp%aux_rate(i) = t*sp%rate(i)
      end do
      if (t > 0.0_wp) sp%aux_rate(n + 1) = t*s_dot
      ! the search's start and its rate: x of the first free element, or the force
      sp%guess_rate = 0.0_wp
      select case (dsp%path)
      case (path_newton, path_search)
         i = 0
         do j = 1, n
            if (ch%stateful(j)) cycle
            if (dsp%slope(j) > min_slope .and. dsp%slope(j) < rigid_slope) then
               if (i == 0) then
                  i = j
               else if (dsp%slope(j) > dsp%slope(i)) then
                  i = j
               end if
            end if
         end do
         if (i > 0) sp%guess_rate = dsp%slope(i)*sp%rate(i)
      case default
         i = findloc(ch%stateful(1:n), .false., 1)
         if (i > 0) sp%guess_rate = sp%rate(i)
      end select
   contains
      !> Every element rate-dependent: T >= 0 with T = F_b,a(x_a) + F_v,a(s' -
      !! sum_d F_v,d^-1(T - F_b,d)) - the right side falls as T grows, so the
      !! root is unique; 0 where the absorber carries nothing or would pull;
      !! -1 where the search met a value that is not finite.
      pure real(wp) function absorber_tension() result(tt)
         type(root_search_t) :: q
         real(wp) :: hi, psi, dpsi
         integer :: it
         tt = 0.0_wp
         if (.not. fb(a) > 0.0_wp) return
         call psi_at(0.0_wp, psi, dpsi)
         if (.not. psi < 0.0_wp) return
         hi = max(fb(a), 1.0_wp)
         do it = 1, 400
            call psi_at(hi, psi, dpsi)
            if (psi >= 0.0_wp) exit
            hi = 2.0_wp*hi
         end do
         call root_begin(q, 0.0_wp, hi, fb(a), 1.0e-14_wp*hi, force_tol, ch%max_iter)
         do
            call psi_at(q%x, psi, dpsi)
            call root_update(q, psi, dpsi, max(q%x, fb(a)))
            if (q%state /= root_running) exit
         end do
         tt = q%x
         if (q%state == root_not_finite) tt = -1.0_wp
      end function absorber_tension

      !> psi(T) = T - F_b,a - F_v,a(x_a'(T)), increasing, and its slope.
      pure subroutine psi_at(tt, psi, dpsi)
         real(wp), intent(in) :: tt
         real(wp), intent(out) :: psi, dpsi
         real(wp) :: va, vd, comp, c
         integer :: k
         va = s_dot
         comp = 0.0_wp
         do k = 1, n
            if (.not. ch%stateful(k)) cycle
            vd = rate_inverse(ch%law(k), tt - fb(k))
            va = va - vd
            c = rate_slope(ch%law(k), vd)
            if (c > 0.0_wp) comp = comp + 1.0_wp/c
         end do
         psi = tt - fb(a) - rate_force(ch%law(a), va)
         dpsi = 1.0_wp + rate_slope(ch%law(a), va)*comp
      end subroutine psi_at
   end subroutine chain_split

   !> chain_split of a chain with a lone rate-independent element l (no cap,
   !! no gate; every other element a state, none the absorber): the general
   !! path's operations in its order - split_deformation's split of one
   !! free element (slack, taken up within its residual deformation, or
   !! loaded: its deformation what the states leave), then the states' rates
   !! at the tension and the rest's rate, all of it to l - on the chain's
   !! arrays, without the general split's bookkeeping (issue 16 section 4:
   !! some 40 % of a belt chain's split; the same bits, test_direct_splits_bits).
   !! sp as chain_split leaves it before the split (cleared, no gates); s and
   !! s_dot finite.
   pure subroutine lone_split(ch, s, s_dot, aux, sp)
      type(series_chain_t), intent(in) :: ch
      real(wp), intent(in) :: s, s_dot, aux(:)
      type(chain_split_t), intent(inout) :: sp
      type(branch_point_t) :: bp
      real(wp) :: held_sum, sfree, z, zfree, force, slope, t, r_dot, w, total
      integer :: i, n, l, seg
      n = ch%n
      l = ch%lone
      ! the states' deformations, and what they leave (split_deformation)
      held_sum = 0.0_wp
      do i = 1, n
         if (i == l) cycle
         sp%x(i) = ch%x_offset(i) + aux(n + 1 + ch%state(i))
         held_sum = held_sum + sp%x(i)
      end do
      sfree = s - held_sum
      force = 0.0_wp
      slope = 0.0_wp
      if (sfree > 0.0_wp) then
         z = zero_extent(ch%law(l), ch%mem(l))
         zfree = 0.0_wp + z
         if (sfree <= zfree) then
            sp%region = region_unloaded         ! taken up within its residual deformation
            sp%x(l) = sfree*z/zfree
         else
            sp%region = region_loaded           ! its deformation what the states leave
            sp%x(l) = sfree
            seg = 0
            call branch_eval(ch%law(l), ch%mem(l), sfree, seg, bp)
            force = bp%force
            slope = bp%slope
            sp%iterations = 1
         end if
         sp%guess = sp%x(l)
      end if
      ! the states carry T with their own rate terms (chain_split)
      t = max(force, 0.0_wp)
      sp%force = t
      r_dot = s_dot
      do i = 1, n
         if (i == l) cycle
         bp = branch_at(ch%law(i), ch%mem(i), sp%x(i))
         sp%rate(i) = rate_inverse(ch%law(i), t - bp%force)
         r_dot = r_dot - sp%rate(i)
         sp%aux_rate(n + 1 + ch%state(i)) = sp%rate(i)
         if (t > 0.0_wp .and. i /= ch%rest) sp%aux_rate(i) = t*sp%rate(i)
      end do
      ! the rest to l: its share of the compliances, or of the residuals (1 but
      ! where they are 0 or rigid, computed as chain_split computes it)
      w = 0.0_wp
      select case (sp%region)
      case (region_loaded)
         total = 0.0_wp
         if (.not. slope > min_slope) then
            w = 1.0_wp/real(1, wp)
         else if (slope < rigid_slope) then
            w = 1.0_wp/slope
            total = total + w
            if (total > 0.0_wp) then
               w = w/total
            else
               w = 0.0_wp
            end if
         end if
      case (region_unloaded)
         total = 0.0_wp + sp%x(l)
         if (total > 0.0_wp) w = sp%x(l)/total
      end select
      if (w > 0.0_wp) sp%rate(l) = w*r_dot
      if (t > 0.0_wp) sp%aux_rate(n + 1) = t*s_dot
      sp%guess_rate = sp%rate(l)
   end subroutine lone_split

   !> The stored and dissipated energy of each element at the state of sp
   !! (chain_split's; aux the chain's auxiliary quantities): its stored
   !! energy a function of its deformation and memory; its dissipated energy,
   !! a rate-independent element's what its memory booked, a rate-dependent
   !! one's the work done on it less its stored energy - for the last one
   !! (rest), and where none is rated the first rate-independent one, what
   !! the chain's work holds beyond every other energy (the module's note).
   !! They add up to the chain's work.
   pure subroutine chain_energies(ch, sp, aux, stored, dissipated)
      type(series_chain_t), intent(in) :: ch
      type(chain_split_t), intent(in) :: sp
      real(wp), intent(in) :: aux(:)
      real(wp), intent(out) :: stored(:), dissipated(:)
      integer :: i, first
      do i = 1, ch%n
         stored(i) = element_stored(ch, i, sp%x(i), sp%gate(i))
         if (i == ch%rest) then
            dissipated(i) = 0.0_wp
         else if (ch%rated(i)) then
            dissipated(i) = ch%w_initial(i) + aux(i) - stored(i)
         else
            dissipated(i) = ch%mem(i)%e_dissipated
         end if
      end do
      first = ch%rest
      if (first == 0) first = findloc(ch%rated(1:ch%n), .false., 1)
      if (first == 0) first = 1
      dissipated(first) = dissipated(first) + (ch%w_initial_chain + aux(ch%n + 1) &
                                               - sum(stored(1:ch%n)) - sum(dissipated(1:ch%n)))
   end subroutine chain_energies

   !> Element i's stored energy at deformation x: its law's
   !! (recurrent_stored); beyond a soft cap the elastic crush of the solid;
   !! gated, its gate's work beyond its hold, which a state past it gives
   !! back along the same path until the turning point is accepted (then it
   !! is dissipated: the column does not spring back through its gate).
   pure real(wp) function element_stored(ch, i, x, gate) result(e)
      type(series_chain_t), intent(in) :: ch
      integer, intent(in) :: i
      real(wp), intent(in) :: x, gate
      type(branch_point_t) :: bp
      real(wp) :: over
      over = 0.0_wp
      if (ch%cap_slope(i) > 0.0_wp) over = max(0.0_wp, x - ch%cap(i))
      e = recurrent_stored(ch%law(i), ch%mem(i), x - over)
      if (over > 0.0_wp) then
         bp = branch_at(ch%law(i), ch%mem(i), ch%cap(i))
         e = e + (bp%force + 0.5_wp*ch%cap_slope(i)*over)*over
      end if
      if (gate > 0.0_wp) e = e + gate*max(0.0_wp, x - hold(i))
   contains
      pure real(wp) function hold(k)
         integer, intent(in) :: k
         hold = max(ch%mem(k)%x_hold, zero_extent(ch%law(k), ch%mem(k)))
      end function hold
   end function element_stored

   !> After an ACCEPTED step: every element's memory from its deformation
   !! and rate at the accepted state (figure 18; recurrent_accept books the
   !! energy its law's change dissipates), the gates' work past a hold that
   !! moved dissipated. (A rate-dependent element recovering while the chain
   !! is slack moves with the motion, chain_split: nothing jumps here.)
   !! changed: the right-hand side is a different function from here on (the
   !! stepper restarts).
   !! An element that does not move at the accepted state (held at its cap,
   !! by its gate or at f_max, or beside a flat element, which takes the
   !! whole rate) cannot decide its turning point or new cycle from its own
   !! rate, 0: once another element's memory changed there, the split with
   !! the new memories gives it the rate it has from here on, and it decides
   !! from that, at the same state (issue 15, docs/contacts.md D-C31: the
   !! steering column that stops yielding holds, and the face in front of
   !! it unloads from there; its switch, the rate the elements share, is
   !! located with the column's - decided a step later, the face's turning
   !! point was not on an accepted state).
   pure subroutine chain_accept(ch, s, s_dot, aux, changed, guess, split)
      type(series_chain_t), intent(inout) :: ch
      real(wp), intent(in) :: s, s_dot
      real(wp), intent(in) :: aux(:)
      logical, intent(out) :: changed
      real(wp), intent(in), optional :: guess
      !> the chain's split at this state, when the caller has it (chain_split's)
      type(chain_split_t), intent(in), optional :: split
      type(chain_split_t) :: sp, sp_new
      real(wp) :: gate_work(max_chain), g_new(max_chain), e0
      logical :: c, still(max_chain), pass_changed
      integer :: i, n, pass
      changed = .false.
      n = ch%n
      if (present(split)) then
         sp = split
      else
         call chain_split(ch, s, s_dot, aux, sp, guess)
      end if
      ! a split that fails here fails again at the next step's first
      ! evaluation of this state, which ends the run with the failure text
      if (sp%status /= split_ok) return
      do i = 1, n
         gate_work(i) = 0.0_wp
         if (sp%gate(i) > 0.0_wp) gate_work(i) = sp%gate(i)*max(0.0_wp, sp%x(i) - hold(i))
         still(i) = .true.
         if (ch%cap_slope(i) > 0.0_wp .and. sp%x(i) > ch%cap(i)) then
            ! crushed solid: its own deformation the cap's, not moving
            call recurrent_accept(ch%law(i), ch%mem(i), ch%cap(i), 0.0_wp, c)
         else
            call recurrent_accept(ch%law(i), ch%mem(i), sp%x(i), sp%rate(i), c)
            still(i) = .not. abs(sp%rate(i)) > 0.0_wp
         end if
         still(i) = still(i) .and. .not. c
         changed = changed .or. c
      end do
      ! the elements that did not move, with the rates the new memories give
      pass_changed = changed
      do pass = 1, n
         if (.not. (pass_changed .and. any(still(1:n)))) exit
         pass_changed = .false.
         call chain_split(ch, s, s_dot, aux, sp_new, guess)
         if (sp_new%status /= split_ok) exit
         do i = 1, n
            if (.not. still(i)) cycle
            if (ch%cap_slope(i) > 0.0_wp .and. sp_new%x(i) > ch%cap(i)) cycle
            if (.not. abs(sp_new%rate(i)) > 0.0_wp) cycle
            call recurrent_accept(ch%law(i), ch%mem(i), sp_new%x(i), sp_new%rate(i), c)
            still(i) = .false.
            pass_changed = pass_changed .or. c
         end do
         changed = changed .or. pass_changed
      end do
      ! a gate's work past a hold that moved (the column stopped) is dissipated
      g_new = chain_gates(ch)
      do i = 1, n
         if (.not. (sp%gate(i) > 0.0_wp .or. g_new(i) > 0.0_wp)) cycle
         e0 = gate_work(i) - g_new(i)*max(0.0_wp, sp%x(i) - hold(i))
         ch%mem(i)%e_dissipated = ch%mem(i)%e_dissipated + e0
      end do
   contains
      !> Where the gate of element k holds it (series_split's x_h).
      pure real(wp) function hold(k)
         integer, intent(in) :: k
         hold = max(ch%mem(k)%x_hold, zero_extent(ch%law(k), ch%mem(k)))
      end function hold
   end subroutine chain_accept

   !> Whether a rate-dependent element of the chain still carries load on its
   !! branch: slack, it still recovers (its state moves, chain_split; a
   !! slack chain's accept must still follow its memory).
   pure logical function chain_relaxing(ch, aux) result(relaxing)
      type(series_chain_t), intent(in) :: ch
      real(wp), intent(in) :: aux(:)
      type(branch_point_t) :: bp
      integer :: i
      relaxing = .false.
      do i = 1, ch%n
         if (.not. ch%stateful(i)) cycle
         bp = branch_at(ch%law(i), ch%mem(i), ch%x_offset(i) + aux(ch%n + 1 + ch%state(i)))
         relaxing = relaxing .or. bp%force > 0.0_wp
      end do
   end function chain_relaxing

   !> At the initial state (C.2, D-C21: the initial force with the rate 0):
   !! every element at the split of s0 with all of them free, fresh memories;
   !! the states start there, and the work done on each before t = 0 is its
   !! stored energy there (D-C26: the initial deformation counts as a
   !! loading before the run, so nothing is dissipated at t = 0).
   pure subroutine chain_set_initial(ch, s0)
      type(series_chain_t), intent(inout) :: ch
      real(wp), intent(in) :: s0
      type(deformation_split_t) :: dsp
      real(wp) :: g(max_chain), x_held(max_chain)
      logical :: held(max_chain)                ! (every element free)
      integer :: i
      ch%x_offset = 0.0_wp
      ch%w_initial = 0.0_wp
      ch%w_initial_chain = 0.0_wp
      if (.not. s0 > 0.0_wp) return
      g = chain_gates(ch)
      held = .false.
      x_held = 0.0_wp
      call split_deformation(ch%n, ch%law, ch%mem, s0, ch%max_iter, ch%cap, g, ch%cap_slope, held, x_held, dsp)
      if (dsp%status /= split_ok) return
      do i = 1, ch%n
         if (ch%stateful(i)) ch%x_offset(i) = dsp%x(i)
         ch%w_initial(i) = element_stored(ch, i, dsp%x(i), g(i))
         call track_kink(ch, i, dsp%x(i))
      end do
      ch%w_initial_chain = sum(ch%w_initial(1:ch%n))
   end subroutine chain_set_initial

   !> Issue 15: how many switching functions the chain has (chain_switches):
   !! its slack taken up or released; the clip of a single rate-dependent
   !! element's force, or of the absorber's, at 0; per element with a curve
   !! its turning point (unless it is elastic) and the kinks of its curve
   !! below and above it.
   pure integer function chain_n_switch(ch) result(n)
      type(series_chain_t), intent(in) :: ch
      integer :: i
      n = 1
      if ((ch%n == 1 .and. ch%rated(1)) .or. ch%absorber > 0) n = n + 1
      do i = 1, ch%n
         if (.not. curve_is_defined(ch%law(i)%curve)) cycle
         if (.not. ch%law(i)%elastic) n = n + 1
         n = n + 2
      end do
   end function chain_n_switch

   !> Issue 15: the chain's switching functions at deformation s, rate s_dot
   !! and states aux (chain_split's arguments; guess its start), in the
   !! order chain_n_switch counts them, each continuous in the state for the
   !! memories the chain holds and changing sign exactly where the tension,
   !! or its slope, changes discontinuously, or where a memory must change:
   !! - slack (in): the part of s the rate-independent elements share less
   !!   their residual deformations, sfree - sum z_i (one element: s - z):
   !!   > 0 where the chain carries load (series_split's regions). T is
   !!   continuous there, its slope is not (with rate terms of a single
   !!   element, T itself jumps);
   !! - clip (lb): a single rate-dependent element's F_b + F_v(s'), or the
   !!   absorber's tension at T = 0 (-psi(0), chain_split), where its branch
   !!   carries load (else +1): T = max(0, ...) kinks where it is 0;
   !! - per element with a curve: its turning point or new cycle (unless
   !!   elastic; in/s; loading_branch's turn_switch, 1e-7 in/s past 0): for
   !!   a rate-independent element the rate they share, r' = s' - sum x_d'
   !!   (their rates are shares of it), where the chain carries load; for a
   !!   state its own x_d'; then, in in, its branch's argument (branch_argument)
   !!   less the kink of its curve below it at the last accepted state, and
   !!   the kink above less the argument (+1 where there is none): where a
   !!   table's point, or the end of its flat start, is passed.
   !! Where one is exactly 0 at a point the law counts as short of its switch
   !! (no load at a slack of 0, the kink interval's lower end inside it), it
   !! is nudged to that side (zero_on_side): the driver accepts where a
   !! function reaches 0. Pure, like chain_split. A
   !! split that fails gives +1 everywhere (the evaluation that follows
   !! fails and says why).
   pure subroutine chain_switches(ch, s, s_dot, aux, g, guess)
      type(series_chain_t), intent(in) :: ch
      real(wp), intent(in) :: s, s_dot, aux(:)
      real(wp), intent(out) :: g(:)
      real(wp), intent(in), optional :: guess
      type(chain_split_t) :: sp
      type(branch_point_t) :: bp
      real(wp) :: r_dot, fb(max_chain), va, d
      logical :: taut
      integer :: i, k, n
      g = 1.0_wp
      n = ch%n
      call chain_split(ch, s, s_dot, aux, sp, guess)
      if (sp%status /= split_ok) return
      ! the slack: what the rate-independent elements share less their residuals
      k = 1
      if (n == 1) then
         g(k) = s - zero_extent(ch%law(1), ch%mem(1))
      else
         g(k) = s
         do i = 1, n
            if (ch%stateful(i)) then
               g(k) = g(k) - sp%x(i)
            else
               g(k) = g(k) - zero_extent(ch%law(i), ch%mem(i))
            end if
         end do
      end if
      g(k) = zero_on_side(g(k), .false.)    ! (no load at 0)
      taut = g(k) > 0.0_wp
      ! the rate the rate-independent elements share; the states' branch forces
      r_dot = s_dot
      do i = 1, n
         fb(i) = 0.0_wp
         if (.not. ch%stateful(i)) cycle
         r_dot = r_dot - sp%rate(i)
         bp = branch_at(ch%law(i), ch%mem(i), sp%x(i))
         fb(i) = bp%force
      end do
      ! the clip at T = 0 of a single rate-dependent element or the absorber
      if (n == 1 .and. ch%rated(1)) then
         k = k + 1
         bp = branch_at(ch%law(1), ch%mem(1), s)
         if (taut .and. bp%force > 0.0_wp) g(k) = bp%force + rate_force(ch%law(1), s_dot)
      else if (ch%absorber > 0) then
         k = k + 1
         bp = branch_at(ch%law(ch%absorber), ch%mem(ch%absorber), sp%x(ch%absorber))
         if (taut .and. bp%force > 0.0_wp) then
            va = s_dot
            do i = 1, n
               if (ch%stateful(i)) va = va - rate_inverse(ch%law(i), -fb(i))
            end do
            g(k) = bp%force + rate_force(ch%law(ch%absorber), va)
         end if
      end if
      ! per element: its turning point, the kinks of its curve about it
      do i = 1, n
         if (.not. curve_is_defined(ch%law(i)%curve)) cycle
         if (.not. ch%law(i)%elastic) then
            k = k + 1
            if (ch%stateful(i)) then
               ! a state's own rate, where it carries load or not: below its
               ! residual it is F_v^-1(T) >= 0, so nothing switches there but
               ! where T reaches 0 (with the slack). (A state taken up at the
               ! end of a step can be left a little deformed and relaxing by
               ! the step's later stages: it turns at once, unlocated, and
               ! takes a new cycle where its rate becomes positive, located;
               ! a function that changed to a constant where it took load
               ! would cross there by a jump, which takes the location a
               ! hundred tries.)
               g(k) = turn_switch(ch%mem(i), .true., sp%rate(i))
            else
               g(k) = turn_switch(ch%mem(i), taut, r_dot)
            end if
         end if
         d = branch_argument(ch%law(i), ch%mem(i), sp%x(i))
         ! (the interval [lo, hi) holds its lower end, not its upper)
         if (ch%kink_lo(i) > -huge(1.0_wp)) g(k + 1) = zero_on_side(d - ch%kink_lo(i), .true.)
         if (ch%kink_hi(i) < huge(1.0_wp)) g(k + 2) = ch%kink_hi(i) - d
         k = k + 2
      end do
   end subroutine chain_switches

   !> Issue 15: after an ACCEPTED step, with the memories accept left (sp:
   !! the chain's split there with them), the kinks of each element's curve
   !! about its branch's argument, which chain_switches' kink functions
   !! measure from until the next accepted step.
   pure subroutine chain_track_kinks(ch, sp)
      type(series_chain_t), intent(inout) :: ch
      type(chain_split_t), intent(in) :: sp
      integer :: i
      if (sp%status /= split_ok) return
      do i = 1, ch%n
         call track_kink(ch, i, sp%x(i))
      end do
   end subroutine chain_track_kinks

   !> Element i's kinks about its branch's argument at deformation x.
   pure subroutine track_kink(ch, i, x)
      type(series_chain_t), intent(inout) :: ch
      integer, intent(in) :: i
      real(wp), intent(in) :: x
      ch%kink_lo(i) = -huge(1.0_wp)
      ch%kink_hi(i) = huge(1.0_wp)
      if (.not. curve_is_defined(ch%law(i)%curve)) return
      call curve_kinks_about(ch%law(i)%curve, branch_argument(ch%law(i), ch%mem(i), x), ch%kink_lo(i), &
                             ch%kink_hi(i))
   end subroutine track_kink

   !> Why a split failed, for the failure message.
   pure function chain_split_text(sp, s, s_dot, max_iter, setting) result(text)
      type(chain_split_t), intent(in) :: sp
      real(wp), intent(in) :: s, s_dot
      integer, intent(in) :: max_iter
      character(len=*), intent(in), optional :: setting   !< where the deck sets max_iter, e.g. ' (*BELTOPTIONS ITER)'
      character(len=:), allocatable :: text
      select case (sp%status)
      case (split_no_convergence)
         text = 'the shared deflection did not converge within '//itoa(max_iter)//' iterations'
         if (present(setting)) text = text//setting
         text = text//' and '//itoa(bisections)//' bisections at the deformation '//num(s, 6)//' in, rate '//num(s_dot, 6)//' in/s'
      case (split_not_finite)
         text = 'the shared deflection met a value that is not finite (deformation '//num(s, 6)//' in, rate ' &
                //num(s_dot, 6)//' in/s)'
      case default
         text = ''
      end select
   end function chain_split_text
end module series_chain
