!> The model of a run from the deck's plain tables (report C.1), with the
!! one preliminary calculation the deck's seat needs (C.2): each section
!! built by its builder and checked by its validator (c1_input:
!! options_input, body_input, injury_input, loading_input, belts_input,
!! vehicle_input, seat_input, interior_input), in the order of the sections,
!! so that a deck's problems come in the order they always have; and the
!! rigid-beam seat's initial relations solved for the quantities the deck
!! does not give (seat_beam_statics). The validators read the values from
!! the sections and only the locations of their messages from the deck
!! (model_origin: file, line, group, card, field, columns).
module model_builder
   use error_handling, only: error_t, error_append
   use deck_cards, only: g_title
   use deck_reader, only: deck_t
   use deck_fields, only: single_card
   use model_origin, only: model_origin_t, deck_origin
   use model, only: model_t, seat_rigid_beam
   use options_input, only: build_options, build_time, check_time, build_numerics
   use body_input, only: build_body, check_body, build_joints, check_joints
   use injury_input, only: build_injury, check_injury, build_end_tests
   use loading_input, only: build_materials, check_materials, build_loading, check_loading
   use belts_input, only: build_belts, check_belts
   use vehicle_input, only: build_vehicle, check_vehicle, check_vehicle_tables, build_environment
   use seat_input, only: build_seat, check_seat, rigid_beam_problem
   use interior_input, only: build_interior, check_interior, check_scene
   use printer_plot_input, only: build_printer_plot, check_printer_plot
   use seat_beam_statics, only: rigid_beam_statics
   use fmvss_input, only: build_fmvss
   implicit none
   private

   public :: build_model, check_model

contains

   !> Fill m from the deck's tables, section by section, then check it
   !! (check_model); append every problem found to err.
   subroutine build_model(deck, m, err)
      type(deck_t), intent(in) :: deck
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      type(error_t) :: vehicle_problems

      m%warnings = deck%warnings
      m%title = ' '
      if (single_card(deck, g_title)) m%title = deck%group(g_title)%card(1)%text
      call build_options(deck, m%options)
      call build_time(deck, m%time)
      call build_numerics(deck, m%numerics)
      call build_body(deck, m%body)
      call build_joints(deck, m%joints)
      call build_injury(deck, m%injury)
      call build_materials(deck, m%materials)
      call build_loading(deck, m%options%nload, m%loading)
      call build_belts(deck, m%belts)
      call build_vehicle(deck, m%vehicle, vehicle_problems)
      m%environment = build_environment(deck)
      m%end_tests = build_end_tests(deck)
      call build_seat(deck, m%body, m%materials, m%seat)
      call build_interior(deck, m%interior)
      call build_fmvss(deck, m%fmvss)
      call build_printer_plot(deck, m%printer_plot)
      call check_model(m, deck_origin(deck), err, vehicle_problems)
   end subroutine build_model

   !> Check a model, built from a deck or in code, by every section's
   !! validator in the order of the sections, so that a deck's problems come
   !! in the order they always have; and solve the rigid-beam seat's
   !! initial relations (C.2) for the quantities the deck does not give.
   !! orig locates the messages (model_origin: the deck the model came
   !! from, its groups and fields). vehicle_problems: what reading the
   !! vehicle's tables found (a pulse file), told in its section's place.
   subroutine check_model(m, orig, err, vehicle_problems)
      type(model_t), intent(inout) :: m
      type(model_origin_t), intent(in) :: orig
      type(error_t), intent(inout) :: err
      type(error_t), intent(in), optional :: vehicle_problems
      type(error_t) :: statics

      call check_time(m%time, m%options%nint, orig, err)
      call check_body(m%body, orig, err)
      call check_joints(m%joints, m%body, orig, err)
      call check_injury(orig, err)
      call check_materials(orig, err)
      call check_loading(m%loading, m%materials, m%options%nload, orig, m%warnings, err)
      call check_belts(m%belts, m%options%nbelt, m%body, m%loading, orig, m%warnings, err)
      if (present(vehicle_problems)) then
         if (vehicle_problems%failed()) call error_append(err, vehicle_problems%code, vehicle_problems%message)
      end if
      call check_vehicle(m%vehicle, orig, err)
      if (.not. err%failed()) call check_vehicle_tables(m%vehicle, orig, m%warnings, err)
      call check_seat(m%seat, m%body, orig, err)
      if (m%seat%form == seat_rigid_beam) then
         ! C.2: under the apparent gravity at t = 0 in the interior frame
         call rigid_beam_statics(m%seat, m%environment%gravity*cos(m%vehicle%phi0), statics)
         if (statics%failed()) call rigid_beam_problem(m%seat, orig, statics, err)
      end if
      call check_interior(m%interior, m%options%nbody, orig, err)
      call check_scene(m, orig, err)
      call check_printer_plot(m%printer_plot, m%time, orig, err)
   end subroutine check_model
end module model_builder
