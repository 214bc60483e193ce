!> *FMVSS208 (issue 18): the limits of the summary's FMVSS 208 table from
!! the deck, read by the names of the card table (every field has its
!! default and range there; nothing to check across fields).
module fmvss_input
   use deck_cards, only: g_fmvss
   use deck_reader, only: deck_t
   use deck_fields, only: group_value
   use model, only: fmvss_limits_t
   implicit none
   private

   public :: build_fmvss

contains

   !> FMVSS 208 S6's limits (SI), the deck's or the defaults.
   subroutine build_fmvss(deck, lim)
      type(deck_t), intent(in) :: deck
      type(fmvss_limits_t), intent(out) :: lim
      lim%hic15 = group_value(deck, g_fmvss, 'HIC15')
      lim%clip3ms = group_value(deck, g_fmvss, 'CLIP3MS')
      lim%chest_deflection = group_value(deck, g_fmvss, 'CHESTD')
      lim%nij = group_value(deck, g_fmvss, 'NIJ')
      lim%neck_tension = group_value(deck, g_fmvss, 'NECKT')
      lim%neck_compression = group_value(deck, g_fmvss, 'NECKC')
      lim%femur = group_value(deck, g_fmvss, 'FEMUR')
   end subroutine build_fmvss
end module fmvss_input
