!> Helpers shared by the tests: models built from card images (the same
!! path a user's deck takes), a small deterministic random generator, and
!! an independent kinetic-energy function written from section B.
!!
!! Two built-in decks: the program's default deck (decks/default.deck, the
!! belted driver on the spring seat in the sled pulse) and the body-only
!! deck (decks/body_only.deck, the default deck before the seat and belts:
!! the body alone in the pulse). Tests of the free body - energy
!! conservation, momentum invariants, convergence orders, two occupants,
!! failures - build on the body-only deck.
module test_support
   use kinds, only: wp
   use error_handling, only: error_t
   use text_io, only: string_t
   use deck_reader, only: deck_t, deck_init, deck_add_lines, deck_add_file, deck_finish
   use model_builder, only: build_model
   use model, only: model_t
   use default_deck, only: default_deck_lines
   use body_only_deck, only: body_only_deck_lines
   use loading_curves, only: loading_curve_t, curve_table
   implicit none
   private

   public :: default_model, model_from_cards, model_with_changes, rng_t, kinetic_energy_section_b
   public :: cards_of_default, body_only_model, body_only_with_changes, cards_of_body_only
   public :: shipped_model, shipped_deck_names, table_curve

   !> A linear congruential generator: the same numbers on every machine.
   type :: rng_t
      integer(kind=8) :: state = 12345
   contains
      procedure :: uniform => rng_uniform
   end type rng_t

contains

   !> The model of the built-in default deck.
   function default_model() result(m)
      type(model_t) :: m
      type(error_t) :: err
      call model_from_lines(default_deck_lines(), m, err)
      if (err%failed()) error stop 'the default deck does not parse'
   end function default_model

   !> The default deck's card images.
   function cards_of_default() result(lines)
      type(string_t), allocatable :: lines(:)
      lines = default_deck_lines()
   end function cards_of_default

   !> The model of the body-only deck (decks/body_only.deck): the default
   !! occupant alone in the default pulse, no seat, no belts.
   function body_only_model() result(m)
      type(model_t) :: m
      type(error_t) :: err
      call model_from_lines(body_only_deck_lines(), m, err)
      if (err%failed()) error stop 'the body-only deck does not parse'
   end function body_only_model

   !> The body-only deck's card images.
   function cards_of_body_only() result(lines)
      type(string_t), allocatable :: lines(:)
      lines = body_only_deck_lines()
   end function cards_of_body_only

   !> A model from the default deck followed by extra card groups (which
   !! replace the default's groups of the same kind).
   subroutine model_with_changes(cards, m, err)
      character(len=*), intent(in) :: cards(:)
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      call model_from_base(default_deck_lines(), 'default', cards, m, err)
   end subroutine model_with_changes

   !> A model from the body-only deck followed by extra card groups (which
   !! replace its groups of the same kind).
   subroutine body_only_with_changes(cards, m, err)
      character(len=*), intent(in) :: cards(:)
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      call model_from_base(body_only_deck_lines(), 'body_only', cards, m, err)
   end subroutine body_only_with_changes

   subroutine model_from_base(base, base_name, cards, m, err)
      type(string_t), intent(in) :: base(:)
      character(len=*), intent(in) :: base_name
      character(len=*), intent(in) :: cards(:)
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      type(deck_t) :: deck
      call deck_init(deck)
      call deck_add_lines(deck, base_name, '', base, err)
      call deck_add_lines(deck, 'changes', '', to_strings(cards), err)
      call deck_finish(deck, err)
      if (.not. err%failed()) call build_model(deck, m, err)
   end subroutine model_from_base

   !> The model of a shipped deck (decks/<name>; the directory is the
   !! environment variable HSRI2D_DECKS, which CMake sets for the unit
   !! tests) followed by extra card groups, which replace the deck's groups
   !! of the same kind.
   subroutine shipped_model(name, cards, m, err)
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: cards(:)
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      type(deck_t) :: deck
      character(len=4096) :: dir
      integer :: length, status
      call get_environment_variable('HSRI2D_DECKS', dir, length, status)
      if (status /= 0) dir = '../../../decks'    ! (from build/<config>/tests)
      call deck_init(deck)
      call deck_add_file(deck, trim(dir)//'/'//name, err)
      if (size(cards) > 0) call deck_add_lines(deck, 'changes', '', to_strings(cards), err)
      call deck_finish(deck, err)
      if (.not. err%failed()) call build_model(deck, m, err)
   end subroutine shipped_model

   !> The file names of every shipped deck (decks/*.deck), from the
   !! environment variable HSRI2D_DECK_NAMES (comma-separated; CMake sets it
   !! from the folder for the unit tests); none when it is not set.
   function shipped_deck_names() result(names)
      character(len=:), allocatable :: names(:)
      character(len=8192) :: list
      integer :: length, status, start, comma, n, k
      call get_environment_variable('HSRI2D_DECK_NAMES', list, length, status)
      if (status /= 0 .or. length == 0) then
         allocate (character(len=1) :: names(0))
         return
      end if
      n = count([(list(k:k) == ',', k=1, length)]) + 1
      allocate (character(len=64) :: names(n))
      start = 1
      do k = 1, n
         comma = index(list(start:length), ',')
         if (comma == 0) then
            names(k) = list(start:length)
         else
            names(k) = list(start:start + comma - 2)
            start = start + comma
         end if
      end do
   end function shipped_deck_names

   !> A model from card images alone.
   subroutine model_from_cards(cards, m, err)
      character(len=*), intent(in) :: cards(:)
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      call model_from_lines(to_strings(cards), m, err)
   end subroutine model_from_cards

   subroutine model_from_lines(lines, m, err)
      type(string_t), intent(in) :: lines(:)
      type(model_t), intent(out) :: m
      type(error_t), intent(inout) :: err
      type(deck_t) :: deck
      call deck_init(deck)
      call deck_add_lines(deck, 'test', '', lines, err)
      call deck_finish(deck, err)
      if (.not. err%failed()) call build_model(deck, m, err)
   end subroutine model_from_lines

   function to_strings(cards) result(lines)
      character(len=*), intent(in) :: cards(:)
      type(string_t), allocatable :: lines(:)
      integer :: k
      allocate (lines(size(cards)))
      do k = 1, size(cards)
         lines(k)%s = trim(cards(k))
      end do
   end function to_strings

   !> Uniform in [a, b).
   real(wp) function rng_uniform(this, a, b)
      class(rng_t), intent(inout) :: this
      real(wp), intent(in) :: a, b
      this%state = modulo(this%state*6364136223846793005_8 + 1442695040888963407_8, huge(1_8))
      rng_uniform = a + (b - a)*real(modulo(this%state/1024_8, 2_8**40), wp)/2.0_wp**40
   end function rng_uniform

   !> Kinetic energy of the body written out from section B (with errata
   !! E-B1, E-B2), independently of the program's body_kinematics: the
   !! velocity of every centre of gravity, link by link.
   pure real(wp) function kinetic_energy_section_b(m, q, qd) result(ke)
      type(model_t), intent(in) :: m
      real(wp), intent(in) :: q(10), qd(10)
      real(wp) :: vx(8), vy(8), l(8), r(8)
      real(wp) :: j2x, j2y, j3x, j3y, sx, sy, ex, ey, kx, ky
      l = m%body%length
      r = m%body%rho
      ! joint velocities
      j2x = qd(9) - l(1)*qd(1)*sin(q(1))
      j2y = qd(10) + l(1)*qd(1)*cos(q(1))
      j3x = j2x - l(2)*qd(2)*sin(q(2))
      j3y = j2y + l(2)*qd(2)*cos(q(2))
      sx = j3x - l(4)*qd(3)*sin(q(3))          ! shoulder, offset L4 along segment 3
      sy = j3y + l(4)*qd(3)*cos(q(3))
      ex = sx - l(5)*qd(5)*sin(q(5))           ! elbow
      ey = sy + l(5)*qd(5)*cos(q(5))
      kx = qd(9) - l(7)*qd(7)*sin(q(7))        ! knee
      ky = qd(10) + l(7)*qd(7)*cos(q(7))
      vx(1) = qd(9) - r(1)*qd(1)*sin(q(1))
      vy(1) = qd(10) + r(1)*qd(1)*cos(q(1))
      vx(2) = j2x - r(2)*qd(2)*sin(q(2))
      vy(2) = j2y + r(2)*qd(2)*cos(q(2))
      vx(3) = j3x - r(3)*qd(3)*sin(q(3))
      vy(3) = j3y + r(3)*qd(3)*cos(q(3))
      vx(4) = j3x - l(3)*qd(3)*sin(q(3)) - r(4)*qd(4)*sin(q(4))   ! neck at L3 along segment 3
      vy(4) = j3y + l(3)*qd(3)*cos(q(3)) + r(4)*qd(4)*cos(q(4))
      vx(5) = sx - r(5)*qd(5)*sin(q(5))
      vy(5) = sy + r(5)*qd(5)*cos(q(5))
      vx(6) = ex - r(6)*qd(6)*sin(q(6))
      vy(6) = ey + r(6)*qd(6)*cos(q(6))
      vx(7) = qd(9) - r(7)*qd(7)*sin(q(7))
      vy(7) = qd(10) + r(7)*qd(7)*cos(q(7))
      vx(8) = kx - r(8)*qd(8)*sin(q(8))
      vy(8) = ky + r(8)*qd(8)*cos(q(8))
      ke = 0.5_wp*sum(m%body%mass*(vx**2 + vy**2) + m%body%inertia*qd(1:8)**2)
   end function kinetic_energy_section_b
   !> A tabulated loading curve (NLOAD = 2) through the points (d, f).
   pure function table_curve(d, f) result(c)
      real(wp), intent(in) :: d(:), f(:)
      type(loading_curve_t) :: c
      c%form = curve_table
      allocate (c%defl(size(d)), c%force(size(f)))
      c%defl = d
      c%force = f
   end function table_curve

end module test_support
