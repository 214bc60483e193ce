!> One run of a model or of an assembled system, start to end, through
!! run_loop's run_t (report figure 6: C.2, then integrate (C.3) -> forces
!! (C.4) -> solve (C.5) with output (C.6) and the end tests (C.7) after
!! each accepted step), for the callers that want the whole run in one
!! call; and the warnings the effects give about the initial state.
module simulation
   use kinds, only: wp
   use error_handling, only: error_t
   use text_io, only: string_t
   use model, only: model_t
   use equations_of_motion, only: crash_system_t, system_build, system_initial_y, system_body_state
   use effect_base, only: body_state_t
   use output_sink, only: output_sink_t
   use run_summary, only: run_summary_t
   use sink_list, only: sink_list_t
   use run_loop, only: run_t
   implicit none
   private

   public :: run_simulation, run_system, run_to_end, initial_warnings

contains

   !> Run the model (run_loop's run_t, from start to end). A numerical
   !! failure ends the run with everything computed so far kept,
   !! summary%end_reason = end_failure (or end_energy) and err set
   !! (exit_numerical). sink, when present, receives the frames and events
   !! as they are made; an error it reports stops the run.
   subroutine run_simulation(m, summary, err, sink)
      type(model_t), intent(in) :: m
      type(run_summary_t), intent(out) :: summary
      type(error_t), intent(inout) :: err
      class(output_sink_t), intent(inout), optional, target :: sink
      type(run_t) :: run
      type(sink_list_t) :: sinks
      if (present(sink)) call sinks%add(sink)
      call run%init(m, sinks=sinks)
      call run_to_end(run, summary, err)
   end subroutine run_simulation

   !> What the model's effects say of its initial state (effect_t%
   !! initial_notes: a contact pair starting deep in its surface): warnings,
   !! before the run.
   function initial_warnings(m) result(notes)
      type(model_t), intent(in) :: m
      type(string_t), allocatable :: notes(:)
      type(crash_system_t) :: sys
      type(body_state_t) :: st
      real(wp), allocatable :: y(:)
      integer :: o, k, xo, ao
      allocate (notes(0))
      call system_build(m, sys)
      call system_initial_y(sys, y)
      do o = 1, size(sys%occupants)
         st = system_body_state(sys, o, 0.0_wp, y)
         associate (occ => sys%occupants(o))
            do k = 1, size(occ%effects)
               xo = occ%extra_offset(k)
               ao = occ%aux_offset(k)
               associate (e => occ%effects(k)%e)
                  notes = [notes, e%initial_notes(st, y(xo + 1:xo + 2*e%n_extra), y(ao + 1:ao + e%n_aux))]
               end associate
            end do
         end associate
      end do
   end function initial_warnings

   !> Run an assembled system (copied: its occupants may come from several
   !! models; m gives the time controls, the integrator, the numerics and
   !! the vehicle's outputs; each occupant carries its own NEND, rest limits
   !! and Table 5 limits).
   subroutine run_system(m, sys, summary, err, sink)
      type(model_t), intent(in) :: m
      type(crash_system_t), intent(in) :: sys
      type(run_summary_t), intent(out) :: summary
      type(error_t), intent(inout) :: err
      class(output_sink_t), intent(inout), optional, target :: sink
      type(run_t) :: run
      type(sink_list_t) :: sinks
      if (present(sink)) call sinks%add(sink)
      call run%init(m, system=sys, sinks=sinks)
      call run_to_end(run, summary, err)
   end subroutine run_system

   !> Advance a run until it is done, and finish it.
   subroutine run_to_end(run, summary, err)
      type(run_t), intent(inout) :: run
      type(run_summary_t), intent(out) :: summary
      type(error_t), intent(inout) :: err
      do while (.not. run%is_done())
         call run%advance()
      end do
      call run%finish(summary, err)
   end subroutine run_to_end
end module simulation
