!> The run's controls from the deck (report C.1, C.3, C.6, C.7): *OPTIONS,
!! *TIME and *NUMERICS - each section's builder, which reads the fields by
!! the names of the card table, and the validator of *TIME, which checks
!! what single fields cannot (the step dividing the print interval and, for
!! the fixed-step integrators, the run).
module options_input
   use kinds, only: wp
   use error_handling, only: error_t
   use strings, only: itoa, num
   use deck_cards, only: g_options, g_time, g_numerics
   use deck_reader, only: deck_t, card_t
   use deck_fields, only: group_value, group_int
   use model_origin, only: model_origin_t, first_card, card_ref, problem
   use model, only: options_section_t, time_section_t, numerics_section_t, nint_adams, nint_rk4
   implicit none
   private

   public :: build_options, build_time, check_time, build_numerics

contains

   !> *OPTIONS (C.1). (NEND = 2 needs a contact of Table 9: checked with
   !! the interior, interior_input.)
   subroutine build_options(deck, o)
      type(deck_t), intent(in) :: deck
      type(options_section_t), intent(out) :: o
      o%nbody = group_int(deck, g_options, 'NBODY')
      o%nbelt = group_int(deck, g_options, 'NBELT')
      o%nend = group_int(deck, g_options, 'NEND')
      o%nload = group_int(deck, g_options, 'NLOAD')
      o%nout = group_int(deck, g_options, 'NOUT')
      o%nint = group_int(deck, g_options, 'NINT')
   end subroutine build_options

   !> *TIME (C.3, C.6, C.7).
   subroutine build_time(deck, tc)
      type(deck_t), intent(in) :: deck
      type(time_section_t), intent(out) :: tc
      tc%t_max = group_value(deck, g_time, 'TMAX')
      tc%dt = group_value(deck, g_time, 'DT')
      tc%dt_print = group_value(deck, g_time, 'DTPRINT')
      tc%corrector_tol = group_value(deck, g_time, 'CTOL')
      tc%corrector_max_iter = group_int(deck, g_time, 'CITER')
      tc%rtol = group_value(deck, g_time, 'RTOL')
      tc%atol = group_value(deck, g_time, 'ATOL')
   end subroutine build_time

   !> *TIME against the integrator NINT: the step within the print
   !! interval, the fixed steps dividing the run and the print interval,
   !! the counts of steps countable.
   subroutine check_time(tc, nint, orig, err)
      type(time_section_t), intent(in) :: tc
      integer, intent(in) :: nint
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(card_t) :: c
      character(len=:), allocatable :: integrator
      c = first_card(orig, g_time)
      integrator = '(NINT = '//itoa(nint)//' of '//card_ref(orig, first_card(orig, g_options))//')'
      if (tc%dt > tc%dt_print) call problem(orig, err, c, 'DT = '//num(tc%dt) &
         //' s exceeds DTPRINT = '//num(tc%dt_print)//' s', 'DT DTPRINT')
      if (nint == nint_adams .or. nint == nint_rk4) then
         if (.not. whole_multiple(tc%t_max, tc%dt)) call problem(orig, err, c, 'TMAX = ' &
            //num(tc%t_max)//' s is not a whole multiple of DT = '//num(tc%dt)//' s, as the fixed-step ' &
            //'integrators need '//integrator, 'TMAX DT')
         if (.not. whole_multiple(tc%dt_print, tc%dt)) call problem(orig, err, c, 'DTPRINT = ' &
            //num(tc%dt_print)//' s is not a whole multiple of DT = '//num(tc%dt)//' s, as the fixed-step ' &
            //'integrators need '//integrator, 'DT DTPRINT')
      end if
      ! step and print counts must stay countable (and far from integer overflow)
      if (tc%t_max/tc%dt > 1.0e9_wp) call problem(orig, err, c, 'TMAX/DT = '//num(tc%t_max/tc%dt, 4) &
         //' steps: more than 1e9', 'TMAX DT')
      if (tc%dt_print/tc%dt > 1.0e9_wp) call problem(orig, err, c, 'DTPRINT/DT = '//num(tc%dt_print/tc%dt, 4) &
         //' steps: more than 1e9', 'DT DTPRINT')
   end subroutine check_time

   !> *NUMERICS: the program's own numerical controls.
   subroutine build_numerics(deck, nc)
      type(deck_t), intent(in) :: deck
      type(numerics_section_t), intent(out) :: nc
      nc%am_start = group_int(deck, g_numerics, 'ASTART')
      nc%solver = group_int(deck, g_numerics, 'SOLVER')
      nc%energy_tol = group_value(deck, g_numerics, 'EBTOL')
      nc%energy_continue = group_int(deck, g_numerics, 'EBFAIL') == 2
   end subroutine build_numerics

   !> fixed-step runs need t to be n*dt for a whole n (to 1e-9 relative)
   logical function whole_multiple(t, dt)
      real(wp), intent(in) :: t, dt
      real(wp) :: q
      q = t/dt
      whole_multiple = abs(q - anint(q)) <= 1.0e-9_wp*max(1.0_wp, q) .and. anint(q) >= 1.0_wp
   end function whole_multiple
end module options_input
