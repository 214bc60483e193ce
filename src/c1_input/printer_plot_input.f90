!> The listing's printer plots from the deck (C.6, *PRINTERPLOT; issue 18):
!! the section's builder, which reads the times by the names of the card
!! table, and its validator: the times increase and lie within TMAX.
module printer_plot_input
   use error_handling, only: error_t
   use strings, only: num
   use deck_cards, only: g_printerplot
   use deck_reader, only: deck_t
   use deck_fields, only: single_card, group_value, group_given
   use model_origin, only: model_origin_t, first_card, problem
   use model, only: printer_plot_section_t, time_section_t, max_plot_times
   implicit none
   private

   public :: build_printer_plot, check_printer_plot

   !> The fields T1..T7 of *PRINTERPLOT.
   character(len=2), parameter :: time_field(max_plot_times) = ['T1', 'T2', 'T3', 'T4', 'T5', 'T6', 'T7']

contains

   !> Wanted when the deck holds the card; each time field given, in order.
   subroutine build_printer_plot(deck, pp)
      type(deck_t), intent(in) :: deck
      type(printer_plot_section_t), intent(out) :: pp
      integer :: k
      pp%wanted = single_card(deck, g_printerplot)
      do k = 1, max_plot_times
         pp%given(k) = group_given(deck, g_printerplot, time_field(k))
         if (pp%given(k)) pp%times(k) = group_value(deck, g_printerplot, time_field(k))
      end do
   end subroutine build_printer_plot

   !> Each time given is later than the one given before it and at most TMAX.
   subroutine check_printer_plot(pp, tc, orig, err)
      type(printer_plot_section_t), intent(in) :: pp
      type(time_section_t), intent(in) :: tc
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      integer :: k, before
      if (.not. pp%wanted) return
      before = 0
      do k = 1, max_plot_times
         if (.not. pp%given(k)) cycle
         if (pp%times(k) > tc%t_max) call problem(orig, err, first_card(orig, g_printerplot), time_field(k)//' = ' &
            //num(pp%times(k))//' s lies after TMAX = '//num(tc%t_max)//' s: the run draws nothing then', &
            time_field(k))
         if (before > 0) then
            if (pp%times(k) <= pp%times(before)) call problem(orig, err, first_card(orig, g_printerplot), &
               time_field(k)//' = '//num(pp%times(k))//' s must be later than '//time_field(before)//' = ' &
               //num(pp%times(before))//' s', time_field(before)//' '//time_field(k))
         end if
         before = k
      end do
   end subroutine check_printer_plot
end module printer_plot_input
