!> Report C.4.e, the shared deflection: "the nominal deformation is the sum
!! of the actual belt elongation and the body deflection ... Thus the total
!! deformation must be partitioned between the belt elongation and the body
!! deflection, and likewise for the rate." (figure 19, lost; docs/belts.md 3).
!!
!! A belt section and the body surface under it are elements in series
!! carrying one tension: the webbing (its *BELTLOADING law) and the abdomen
!! (material 11) or the chest (material 12), each a recurrent-loading law
!! with its own memory. A belt *chain* is such a series: one section and its
!! body surface (the report's independent sections), or, when several
!! sections share one tension (*BELTOPTIONS COUPLING), every webbing section
!! and body surface of the shared sections. The chain's law - one tension in
!! every element, each with its own rate term; a rate-dependent body's
!! deflection a state of the chain - is series_chain's (docs/loading.md 5);
!! this module holds the belts' chains: their sections and elements, where
!! their auxiliary quantities lie, the lap belt's halved law (D-B5).
module belt_shared_deflection
   use kinds, only: wp
   use recurrent_loading, only: recurrent_law_t
   use series_chain, only: max_chain, series_chain_t, chain_split_t, chain_split, chain_accept, chain_energies, &
      chain_n_aux, chain_switches, chain_track_kinks
   implicit none
   private

   public :: belt_chain_t, belt_chain_n_aux, belt_chain_split, belt_chain_rates, belt_chain_accept
   public :: belt_chain_energies, scaled_law, belt_chain_switches

   !> Sections carrying one tension, and the elements in series along them.
   type :: belt_chain_t
      integer :: n_sections = 0
      integer :: section(3) = 0              !< the effect's sections in this chain
      integer :: webbing(3) = 0              !< element of each section's webbing
      integer :: body(3) = 0                 !< element of the body under each section (0: rigid)
      real(wp) :: slack = 0.0_wp             !< sum of the sections' Delta_j
      type(series_chain_t) :: chain          !< its elements in series
      !> its first auxiliary quantity in the effect's: the elements' and states'
      !! (series_chain), then the work the vehicle supplies
      integer :: aux_offset = 0
      integer :: start_aux = 0               !< its search's start among the effect's aux (D-B7)
   end type belt_chain_t

contains

   !> The chain's auxiliary quantities, the supplied work included (its
   !! search's start apart, D-B7).
   pure integer function belt_chain_n_aux(bc)
      type(belt_chain_t), intent(in) :: bc
      belt_chain_n_aux = chain_n_aux(bc%chain) + 1
   end function belt_chain_n_aux

   !> The chain at deformation s (its sections' less their slack) and rate
   !! s_dot, from the effect's auxiliary quantities aux (its states, its
   !! search's start).
   pure subroutine belt_chain_split(bc, s, s_dot, aux, sp)
      type(belt_chain_t), intent(in) :: bc
      real(wp), intent(in) :: s, s_dot, aux(:)
      type(chain_split_t), intent(out) :: sp
      call chain_split(bc%chain, s, s_dot, aux(bc%aux_offset + 1:bc%aux_offset + chain_n_aux(bc%chain)), sp, &
                       aux(bc%start_aux))
   end subroutine belt_chain_split

   !> The rates of the chain's auxiliary quantities in the effect's aux_rate
   !! from its split: the elements' and states' (series_chain), the work the
   !! vehicle supplies at the moving anchorages, F (s' - g . z') (D-B4, given
   !! as anchor_rate = s' - g . z'), the search's start (D-B7).
   pure subroutine belt_chain_rates(bc, sp, anchor_rate, aux_rate)
      type(belt_chain_t), intent(in) :: bc
      type(chain_split_t), intent(in) :: sp
      real(wp), intent(in) :: anchor_rate
      real(wp), intent(inout) :: aux_rate(:)
      integer :: m
      m = chain_n_aux(bc%chain)
      aux_rate(bc%aux_offset + 1:bc%aux_offset + m) = sp%aux_rate(1:m)
      aux_rate(bc%aux_offset + m + 1) = sp%force*anchor_rate
      aux_rate(bc%start_aux) = sp%guess_rate
   end subroutine belt_chain_rates

   !> After an accepted step: the elements' memories (series_chain's
   !! chain_accept; sp, the chain's split at this state, belt_chain_split's),
   !! when update; then the kinks its switching functions measure from
   !! (chain_track_kinks), from the split with the memories as they are left.
   !! changed: the stepper must restart.
   pure subroutine belt_chain_accept(bc, s, s_dot, aux, sp, update, changed)
      type(belt_chain_t), intent(inout) :: bc
      real(wp), intent(in) :: s, s_dot, aux(:)
      type(chain_split_t), intent(inout) :: sp
      logical, intent(in) :: update
      logical, intent(out) :: changed
      changed = .false.
      if (update) call chain_accept(bc%chain, s, s_dot, aux(bc%aux_offset + 1:bc%aux_offset + chain_n_aux(bc%chain)), &
                                    changed, aux(bc%start_aux), sp)
      if (changed) call belt_chain_split(bc, s, s_dot, aux, sp)
      call chain_track_kinks(bc%chain, sp)
   end subroutine belt_chain_accept

   !> The chain's switching functions at deformation s and rate s_dot
   !! (series_chain's chain_switches, issue 15).
   pure subroutine belt_chain_switches(bc, s, s_dot, aux, g)
      type(belt_chain_t), intent(in) :: bc
      real(wp), intent(in) :: s, s_dot, aux(:)
      real(wp), intent(out) :: g(:)
      call chain_switches(bc%chain, s, s_dot, aux(bc%aux_offset + 1:bc%aux_offset + chain_n_aux(bc%chain)), g, &
                          aux(bc%start_aux))
   end subroutine belt_chain_switches

   !> Each element's stored and dissipated energy at the split sp, and the
   !! work supplied through the chain.
   pure subroutine belt_chain_energies(bc, sp, aux, stored, dissipated, supplied)
      type(belt_chain_t), intent(in) :: bc
      type(chain_split_t), intent(in) :: sp
      real(wp), intent(in) :: aux(:)
      real(wp), intent(out) :: stored(max_chain), dissipated(max_chain), supplied
      integer :: m
      m = chain_n_aux(bc%chain)
      call chain_energies(bc%chain, sp, aux(bc%aux_offset + 1:bc%aux_offset + m), stored, dissipated)
      supplied = aux(bc%aux_offset + m + 1)
   end subroutine belt_chain_energies

   !> The law with its forces multiplied by factor (> 0): curve and rate
   !! terms; G and R, and so every deformation of figure 18, unchanged.
   !! One side of a lap belt whose two sides are given (D-B5) carries half
   !! the lap belt's law.
   pure function scaled_law(law, factor) result(s)
      type(recurrent_law_t), intent(in) :: law
      real(wp), intent(in) :: factor
      type(recurrent_law_t) :: s
      s = law
      s%curve%sigma = factor*law%curve%sigma
      s%curve%sigma_rate = factor*law%curve%sigma_rate
      if (allocated(law%curve%force)) s%curve%force = factor*law%curve%force
   end function scaled_law
end module belt_shared_deflection
