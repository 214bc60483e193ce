!> Issue 15: the switching functions of a contact pair's chain of loading
!! elements in series (series_chain; docs/loading.md 5; docs/contacts.md
!! 3.6, "Switches (issue 15)"); nothing in them is the contacts' but the
!! caps and gates, which only their chains have. Where its tension T, or T's slope, changes
!! discontinuously, or where an element's memory (figure 18) should change,
!! each of these changes sign, as a continuous function of the chain's
!! deformation s, its rate and its states for the memories the chain holds:
!! - the take-up: s less the rate-dependent elements' deformations (their
!!   states) less the others' zero extents (residual deformations, a
!!   table's flat start): the chain carries load beyond it (onset and
!!   release; a single element with rate terms jumps there from zero);
!! - per element, the kinks of its branch (loading_branch's branch_kinks:
!!   a table's points on the branch, the turning point delta_max where an
!!   unloading curve meets the loading curve);
!! - per element with memory, its turning point and the point x of a new
!!   cycle under load (C.4.e): where its rate changes sign (a free element
!!   of the rate-independent part moves with r' = s' - sum of the states'
!!   rates; a rate-dependent one at F_v^-1(T - F_b): the sign of T - F_b),
!!   loaded, signed so that it crosses zero where recurrent_accept changes
!!   the memory;
!! - a padding's bottoming at its cap (figure 25: T reaching its force at
!!   the cap; beyond a soft cap, its deformation the cap), the steering
!!   column's gate (D-C19: T reaching the column's force at its hold plus
!!   the gate, where it yields, and its force at its hold, below which it
!!   springs back), a plastic element held at delta_max up to f_max (D-B10);
!! - a single element with rate terms: max(0, F_b + F_v) clipped at zero.
!! Not covered: a chain whose every element is rate-dependent (its absorber
!! clips T at zero where no shipped deck has one).
module contact_chain_switches
   use kinds, only: wp
   use series_chain, only: series_chain_t, chain_split_t, max_chain
   use loading_curves, only: curve_is_defined, curve_max_slope
   use loading_branch, only: branch_point_t, branch_at, held_plastic, zero_extent, branch_kink_count, &
      branch_kinks, rate_force, min_slope
   implicit none
   private

   public :: chain_switch_count, chain_take_up, chain_switch_values

   !> A rate (in/s) as a length: its sign is all that matters, this keeps
   !! it of the take-up's size where the two are compared.
   real(wp), parameter :: rate_time = 1.0e-3_wp
   !> A force (lb) as a length where the chain's compliance does not give
   !! one (a rigid chain, a flat element holding the tension).
   real(wp), parameter :: ref_stiffness = 1000.0_wp

contains

   !> How many switching functions chain_switch_values gives for ch (fixed
   !! by its laws, caps and gates; the take-up is the caller's).
   pure integer function chain_switch_count(ch) result(n)
      type(series_chain_t), intent(in) :: ch
      integer :: i
      n = 0
      do i = 1, ch%n
         n = n + branch_kink_count(ch%law(i))
         if (has_memory(ch, i)) n = n + 1
         if (ch%cap(i) > 0.0_wp) n = n + 1
         if (is_gated(ch, i)) n = n + 2
         if (has_memory(ch, i) .and. ch%law(i)%plastic) n = n + 1
      end do
      if (ch%n == 1 .and. ch%law(1)%n_rate > 0) n = n + 1
   end function chain_switch_count

   !> The chain's take-up at total deformation s (its states in aux,
   !! series_chain's auxiliary quantities): s less the rate-dependent
   !! elements' deformations less the others' zero extents (in). > 0 where
   !! the chain carries load (series_split's loaded region).
   pure real(wp) function chain_take_up(ch, s, aux) result(u)
      type(series_chain_t), intent(in) :: ch
      real(wp), intent(in) :: s, aux(:)
      integer :: i
      u = s
      do i = 1, ch%n
         if (ch%stateful(i)) then
            u = u - (ch%x_offset(i) + aux(ch%n + 1 + ch%state(i)))
         else
            u = u - zero_extent(ch%law(i), ch%mem(i))
         end if
      end do
   end function chain_take_up

   !> The chain's switching functions (chain_switch_count of them, in g) at
   !! the state of sp (chain_split's, at the rate s_dot), take_up its
   !! chain_take_up there: per element its branch's kinks, its memory's
   !! switch, its cap, its gate's two, a plastic hold; then a single
   !! rate-dependent element's clip. A switch an element's memory does not
   !! have at present is a constant that is never crossed. Scale (in): a
   !! switch of the rate-independent elements is a difference of a force
   !! (T - F*, lb) or of one element's deformation (x_i - X, in), each a
   !! function of s with a kink at its own root, where the chain's
   !! compliance changes (by 25 times where a padding bottoms on metal),
   !! which a root search across the kink converges on slowly; each is
   !! measured instead as the change of s that reaches it at the chain's
   !! present compliance, (T - F*) C and (x_i - X) k_i C (C = the sum of
   !! 1/k over the free elements, k_i element i's slope): s - s* on each
   !! side of the root, exactly on tables' straight pieces. (The scale
   !! changes where another element's slope does, itself a switch, and
   !! never the sign.) An element that does not move with s (held, or a
   !! state), or one on a flat piece, which takes all of it, is measured by
   !! its own deformation.
   pure subroutine chain_switch_values(ch, s_dot, sp, take_up, g)
      type(series_chain_t), intent(in) :: ch
      real(wp), intent(in) :: s_dot, take_up
      type(chain_split_t), intent(in) :: sp
      real(wp), intent(out) :: g(:)
      type(branch_point_t) :: bp
      real(wp) :: t, r_dot, x, sigma, f_h(max_chain), f_cap(max_chain), k(max_chain), c, scale
      logical :: held(max_chain)
      integer :: i, j, nk, n_flat
      t = sp%force
      ! each element's slope and whether it moves with s at T (series_split's held_at)
      c = 0.0_wp
      n_flat = 0
      do i = 1, ch%n
         f_cap(i) = huge(1.0_wp)
         if (ch%cap(i) > 0.0_wp) then
            bp = branch_at(ch%law(i), ch%mem(i), ch%cap(i))
            f_cap(i) = bp%force
         end if
         f_h(i) = 0.0_wp
         if (is_gated(ch, i)) then
            bp = branch_at(ch%law(i), ch%mem(i), max(ch%mem(i)%x_hold, zero_extent(ch%law(i), ch%mem(i))))
            f_h(i) = bp%force
         end if
         if (ch%cap(i) > 0.0_wp .and. ch%cap_slope(i) > 0.0_wp .and. sp%x(i) > ch%cap(i)) then
            k(i) = ch%cap_slope(i)
         else
            bp = branch_at(ch%law(i), ch%mem(i), sp%x(i))
            k(i) = bp%slope
         end if
         held(i) = ch%stateful(i)
         if (ch%cap(i) > 0.0_wp .and. .not. ch%cap_slope(i) > 0.0_wp) held(i) = held(i) .or. t >= f_cap(i)
         if (is_gated(ch, i)) held(i) = held(i) .or. (t >= f_h(i) .and. t <= f_h(i) + sp%gate(i))
         if (held_plastic(ch%law(i), ch%mem(i))) held(i) = held(i) .or. t <= ch%mem(i)%f_max
         if (held(i)) cycle
         if (k(i) > min_slope) then
            c = c + 1.0_wp/k(i)
         else
            n_flat = n_flat + 1
         end if
      end do
      ! a force's distance in s (lb -> in): at a fixed stiffness where the
      ! chain is rigid or a flat element holds T
      scale = 1.0_wp/ref_stiffness
      if (n_flat == 0 .and. c > 0.0_wp) scale = c
      ! the rate the rate-independent elements share (series_chain)
      r_dot = s_dot
      do i = 1, ch%n
         if (ch%stateful(i)) r_dot = r_dot - sp%rate(i)
      end do
      j = 0
      do i = 1, ch%n
         x = sp%x(i)
         ! its branch's kinks (beyond a cap the element is crushed solid: its
         ! own deformation stays the cap's, series_split's element_eval)
         nk = branch_kink_count(ch%law(i))
         if (ch%cap(i) > 0.0_wp) then
            call branch_kinks(ch%law(i), ch%mem(i), min(x, ch%cap(i)), g(j + 1:j + nk))
         else
            call branch_kinks(ch%law(i), ch%mem(i), x, g(j + 1:j + nk))
         end if
         if (.not. held(i)) then
            if (k(i) > min_slope) then
               if (n_flat == 0) g(j + 1:j + nk) = g(j + 1:j + nk)*k(i)*c
            else
               g(j + 1:j + nk) = g(j + 1:j + nk)*real(n_flat, wp)
            end if
         end if
         j = j + nk
         if (has_memory(ch, i)) then
            ! figure 18: loading, it turns where its rate goes below zero; unloading,
            ! a new cycle begins where it goes above (recurrent_accept)
            sigma = merge(-1.0_wp, 1.0_wp, ch%mem(i)%unloading)
            j = j + 1
            ! (at a rate of 0, recurrent_accept changes nothing: the positive side)
            if (ch%stateful(i)) then
               bp = branch_at(ch%law(i), ch%mem(i), x)
               g(j) = held_side(sigma*(t - bp%force), 1.0_wp)
            else
               g(j) = held_side(max(sigma*r_dot*rate_time, -take_up), 1.0_wp)
            end if
         end if
         if (ch%cap(i) > 0.0_wp) then
            ! figure 25: the padding bottoms out
            j = j + 1
            if (ch%cap_slope(i) > 0.0_wp) then
               g(j) = x - ch%cap(i)
               if (k(i) > min_slope .and. n_flat == 0) g(j) = g(j)*k(i)*c
            else
               g(j) = held_side((t - f_cap(i))*scale, 1.0_wp)
            end if
         end if
         if (is_gated(ch, i)) then
            ! D-C19: held at its hold from its force there to that plus the gate
            g(j + 1) = held_side((t - (f_h(i) + sp%gate(i)))*scale, -1.0_wp)
            g(j + 2) = 1.0_wp
            if (f_h(i) > 0.0_wp) g(j + 2) = held_side((t - f_h(i))*scale, 1.0_wp)
            j = j + 2
         end if
         if (has_memory(ch, i) .and. ch%law(i)%plastic) then
            ! D-B10: held at delta_max up to f_max
            j = j + 1
            g(j) = 1.0_wp
            if (held_plastic(ch%law(i), ch%mem(i))) g(j) = held_side((t - ch%mem(i)%f_max)*scale, -1.0_wp)
         end if
      end do
      if (ch%n == 1 .and. ch%law(1)%n_rate > 0) then
         ! loading.md 2: T = max(0, F_b + F_v) while F_b > 0
         j = j + 1
         bp = branch_at(ch%law(1), ch%mem(1), sp%x(1))
         g(j) = max(bp%force + rate_force(ch%law(1), s_dot), -max(curve_max_slope(ch%law(1)%curve), 1.0_wp)*take_up)
      end if
   end subroutine chain_switch_values

   !> A switching function g, which where it is 0 exactly (a split that
   !! lands on a threshold T = F*, a rate of 0) takes the sign of the side
   !! the law takes there (side: series_split's held_at's, recurrent_accept's),
   !! not 0: an accepted state just past the switch where g were 0 would
   !! count as not crossed, and its leaving again would be missed.
   pure real(wp) function held_side(g, side) result(gs)
      real(wp), intent(in) :: g, side
      gs = g
      if (.not. abs(g) > 0.0_wp) gs = sign(tiny(1.0_wp), side)
   end function held_side

   !> Whether element i's law has a memory that changes (figure 18).
   pure logical function has_memory(ch, i)
      type(series_chain_t), intent(in) :: ch
      integer, intent(in) :: i
      has_memory = .not. ch%law(i)%elastic .and. curve_is_defined(ch%law(i)%curve)
   end function has_memory

   !> Whether element i is held by a gate (series_chain's chain_gates).
   pure logical function is_gated(ch, i)
      type(series_chain_t), intent(in) :: ch
      integer, intent(in) :: i
      is_gated = .false.
      if (i > 1) is_gated = ch%gated(i) .and. ch%cap(i - 1) > 0.0_wp
   end function is_gated
end module contact_chain_switches
