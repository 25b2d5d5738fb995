#pragma once
// Macroscopic porous elements: screens, baffles and perforated floors as a line of dummy
// "screen particles" that exert a drag on the fluid around them (thesis 2.5, eqs. 2.21-2.28;
// ch. 3 eqs. 3.15-3.17; ch. 4 eqs. 4.15-4.19). The fluid moves through the screen particles
// freely; only the drag acts. Two closures:
//  * ergun   Ergun's equation with the Kozeny-Carman permeability of the screen seen as a
//            porous medium of porosity n_w = 1 - S and grain diameter D_c = dp_sc (thesis).
//  * morison the drag term of Morison's equation as used for slat screens by McNamara et al.
//            (2021): a pressure loss 1/2 rho C_l |u_n| u_n across the screen, with the loss
//            coefficient C_l of the screen (given, or from its solidity, see
//            slat_screen_loss_coefficient).
// Explicit slat screens (model explicit_slats) are rigid walls: geometry/screens.
//
// Sign convention: F_d,j is the drag the fluid exerts on screen particle j (along the local
// flow); the fluid receives -F_d,j, shared out by kernel weight. The per-element force reported
// (time series column F_screen:<name>) is the force of the element on the fluid, -sum_j F_d,j:
// it opposes the flow. The load on the tank through the screen supports is its negative.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/sph/neighbours.hpp"

namespace sloshsph {

// ---------------------------------------------------------------------------------------
// Closed forms.

// Kozeny-Carman permeability (thesis eq. 2.22 with sphericity phi_s = 1; Carman 1937), m^2:
//   K_P = n^3 D^2 / (150 (1 - n)^2).
double kozeny_carman_permeability(double porosity, double diameter);

// Ergun's equation (thesis eq. 2.21; Ergun & Orning 1949) in vector form: the pressure loss per
// unit length along the flow, Pa/m, for the superficial velocity u:
//   dP/L = mu / K u + 1.75 / sqrt(150) rho / (sqrt(K) n^1.5) |u| u.
// Directed along u (the fluid loses pressure in the direction it flows).
// (3D: the same with a 3D velocity.)
double ergun_inertial_factor(double permeability, double porosity);
template <int D>
Vec<D> ergun_pressure_gradient(double mu, double rho, double permeability, double porosity, Vec<D> velocity) {
  // Thesis eq. 2.21: viscous (Darcy) term + inertial (Forchheimer) term.
  const double viscous = mu / permeability;
  const double inertial = rho * ergun_inertial_factor(permeability, porosity);
  return (viscous + inertial * norm(velocity)) * velocity;
}

// The loss coefficient of an Ergun element of thickness t at high Reynolds number: the inertial
// term of eq. 2.24 written as 1/2 rho C_E |u| u,
//   C_E = 2 t 1.75 / (sqrt(150) sqrt(K_P) n^1.5)   (= 3.5 t (1 - n) / (n^3 D_c) with eq. 2.22).
// The viscous term adds 2 t mu / (K_P rho |u|), small at sloshing speeds. C_E is what a
// macroscopic Ergun screen resists like, to compare with a real screen's loss coefficient C_l
// (slat_screen_loss_coefficient): it scales with t / D_c, not with the slat geometry.
double ergun_inertial_loss_coefficient(double permeability, double porosity, double thickness);

// Loss coefficient of a sharp-edged slat screen of solidity S (Baines & Peterson 1951, in the form
// used for TLD slat screens by Tait et al. 2005, J. Fluids Struct. 20:1007):
//   C_l = (1 / (C_c (1 - S)) - 1)^2,   C_c = 0.405 exp(-pi S) + 0.595,
// C_c being the contraction coefficient of the jets through the gaps (1 at S = 0; at S -> 1 it
// tends to 0.6125, the free-streamline slot value pi / (pi + 2) = 0.611). The coefficient refers
// to the approach (superficial) velocity. Valid for 0 <= S < 1.
double slat_screen_loss_coefficient(double solidity);

// Pressure loss across a screen of loss coefficient C_l (Pa), the drag term of Morison's
// equation per unit area: 1/2 rho C_l |u| u, directed along u.
Vec2 morison_pressure_drop(double rho, double loss_coefficient, Vec2 velocity);

// ---------------------------------------------------------------------------------------
// Screen particles.

// One porous element as discretised. Index = index in the CaseSpec::screens list.
struct ScreenElement {
  std::string name;
  ScreenModel model = ScreenModel::ergun;
  Vec2 from, to;             // m, the centre line clipped to the tank section
  Vec2 normal;               // unit normal of the centre line, perp(to - from)
  double length = 0.0;       // m, clipped length
  double nominal_spacing = 0.0;  // m, dp_sc as asked (D_c of the permeability, thesis 2.5.2)
  double spacing = 0.0;      // m, actual spacing = length / count <= dp_sc (A_p per unit width)
  double spacing_across = 0.0;    // m, 3D: the spacing across the breadth (A_p = spacing x spacing_across)
  std::size_t count_across = 1;   // 3D: the rows across the breadth
  // 3D: a screen in the plane y = plane_y (ScreenSpec::plane_y): its section element is the
  // vertical column of particles, repeated along the length instead (count_across columns
  // spacing_across apart), normal (0, 1, 0).
  std::optional<double> plane_y;
  // 3D: a screen in the vertical plane through the plan segment (ScreenSpec::plan): the section's
  // column repeated along the segment, normal horizontal and perpendicular to it.
  std::optional<std::pair<Vec2, Vec2>> plan;
  // 3D: the unit normal of the extruded element, set by extrude_screen_particles: (n_x, 0, n_z) of
  // the section's element, (0, 1, 0) in the plane y = plane_y, horizontal across a plan segment.
  Vec3 normal3;
  double thickness = 0.0;    // m, t_sc (L of eq. 2.24)
  double smoothing_length = 0.0;  // m, h_sc of the screen's Wendland kernel (support 2 h_sc)
  double solidity = 0.0;     // S
  double porosity = 1.0;     // n_w = 1 - S (eq. 2.23)
  double permeability = 0.0; // m^2, K_P (eq. 2.22), ergun
  double loss_coefficient = 0.0;  // C_l, morison
  double undisturbed_weight = 1.0;  // sum_f V_f W_jf of a full fluid lattice of spacing dp (3D: cubic)
  bool shepard_velocity = false;    // U_j Shepard-normalised (see ScreenParticles)
  std::size_t first = 0, count = 0; // particle range [first, first + count); count 0 for explicit slats
};

// Screen particles, structure of arrays, element by element. In 3D (issue 31) each element is the
// section's centre line extruded over the tank's breadth: the particles of the 2D element repeated
// on count_across rows across it (extrude_screen_particles).
template <int D>
struct BasicScreenParticles {
  std::vector<Vec<D>> position;         // m, tank frame (fixed)
  std::vector<std::uint32_t> element;   // index into `elements`
  std::vector<ScreenElement> elements;  // every element of the case, explicit slats included
  // A screen particle is "in contact with the fluid" (wet, thesis 2.5.3) when the fluid covers at
  // least this fraction of the part of its kernel not taken by wall particles (see screen_drag).
  double wet_fraction = 0.5;
  // Per element (ScreenElement::shepard_velocity, from ScreenSpec):
  // false (thesis eq. 2.26): U_j = sum_f V_f u_f W_jf, truncated near walls and the surface.
  // true: Shepard-normalised, U_j = sum_f V_f u_f W_jf / sum_f V_f W_jf.

  std::size_t size() const { return position.size(); }
  double max_support() const {
    double s = 0.0;
    for (const ScreenElement& e : elements)
      if (e.count > 0) s = std::max(s, 2.0 * e.smoothing_length);
    return s;
  }
};
using ScreenParticles = BasicScreenParticles<2>;

// Samples every ergun/morison element along its centre line, clipped to the tank section: n =
// ceil(length / dp_sc) particles at equal spacing length / n <= dp_sc, the end ones half a
// spacing from the ends. dp_sc = spec.spacing (0: dp); h_sc = spec.interaction_radius (0: 2.5 h,
// thesis 2.5.3); C_l = spec.loss_coefficient (0: slat_screen_loss_coefficient(S)).
// explicit_slats elements get an entry in `elements` with no particles (they are walls).
// Throws InputError(where, "screens.N.<key>") for an element outside the tank, crossing a wall,
// of zero length, or with bad values (solidity not in (0, 1) for the closures, thickness <= 0,
// negative spacing, radius or loss coefficient), N counted from 0.
ScreenParticles make_screen_particles(const std::vector<ScreenSpec>& specs, double dp, double h,
                                      const TankGeometry& tank, const std::string& where);

// 3D: the section's screen particles extruded over the breadth: rows at y = (m + 1/2) breadth / n,
// n = ceil(breadth / dp_sc) (spacing_across <= dp_sc), the section's particles on each, element by
// element; the undisturbed weight is the cubic lattice's sum. An element whose spec has plane_y
// (specs[k], empty specs: none) is the section's vertical column repeated along the length instead,
// at x = (m + 1/2) length / n, n = ceil(length / dp_sc), in the plane y = plane_y.
// An element whose spec has a plan segment is the section's column repeated along that segment
// (from its `first` end), on n = ceil(length / dp_sc) rows (length / n) apart, half a spacing from
// the ends, in a box or a cylinder alike.
// In an upright cylinder (cylinder_radius R > 0, axis at (R, R), breadth = length = 2R) a vertical
// element is repeated over the chord its plane cuts from the circle instead: |y - R| <= w (or
// |x - R| <= w in the plane y = plane_y), w = sqrt(R^2 - (c - R)^2), c the plane's x (or y), on rows
// at R - w + (m + 1/2) 2w / n, n = ceil(2w / dp_sc).
BasicScreenParticles<3> extrude_screen_particles(const ScreenParticles& section, double breadth, double dp,
                                                 const std::vector<ScreenSpec>& specs = {}, double length = 0.0,
                                                 double cylinder_radius = 0.0);

// The screen particles of a scene's screens in D dimensions (3D: extruded over `breadth`, or over
// the chords of an upright cylinder of radius cylinder_radius > 0, whose section `tank` is the
// rectangle 2R wide it stands in).
template <int D>
BasicScreenParticles<D> make_screen_particles_in(const std::vector<ScreenSpec>& specs, double dp, double h,
                                                 const TankGeometry& tank, double breadth, const std::string& where,
                                                 double cylinder_radius = 0.0) {
  ScreenParticles section = make_screen_particles(specs, dp, h, tank, where);
  if constexpr (D == 2) {
    (void)breadth;
    (void)cylinder_radius;
    return section;
  } else {
    return extrude_screen_particles(section, breadth, dp, specs, tank.x_max - tank.x_min, cylinder_radius);
  }
}

// ---------------------------------------------------------------------------------------
// The drag stage.

// What one element does this step (for the time series and validation).
template <int D>
struct BasicScreenElementLoad {
  Vec<D> force_on_fluid;     // N/m (3D: N), -sum_j F_d,j over the element's particles
  Vec<D> mean_velocity;      // m/s, mean of U_j over its wet particles (0 if none)
  double wet_length = 0.0;   // m, wet particles x spacing (3D: divided by the rows across)
  std::size_t wet_particles = 0;
};
using ScreenElementLoad = BasicScreenElementLoad<2>;

// Buffers reused from step to step, and the per-particle state of the last call.
template <int D>
struct BasicScreenDragWork {
  BasicCellGrid<D> particle_grid;  // fluid and wall particles
  BasicCellGrid<D> screen_grid;
  std::vector<Vec<D>> velocity;     // U_j, m/s
  std::vector<Vec<D>> drag;         // F_d,j, N/m (3D: N; 0 when dry)
  std::vector<double> fluid_weight; // S_j = sum_f W_jf (eq. 2.27 denominator), 1/m^2
  std::vector<double> wet_weight;   // sum_f V_f W_jf, fluid only
  std::vector<std::uint8_t> wet;
};
using ScreenDragWork = BasicScreenDragWork<2>;

// Two gather passes, deterministic and independent of the thread count:
//  (a) per screen particle j, over the fluid f within 2 h_sc (eq. 2.26):
//        U_j = sum_f V_f u_f W_jf,   S_j = sum_f W_jf,
//      wet when sum_f V_f W_jf >= wet_fraction (W0 - sum_w V_w W_jw) with W0 the undisturbed
//      lattice sum: the kernel truncation of thesis 2.5.3. Wall particles count as covered,
//      not as air, so a screen particle at the floor stays wet; at the still free surface the
//      fluid covers half the kernel, so the wet part of a screen ends at the surface.
//      Wet particles get F_d,j = dP(U_j) t_sc ds (ergun, eq. 2.25: dP/L from eq. 2.21 times the
//      thickness, A_p = ds per unit width) or 1/2 rho C_l |U_n| U_n n ds with U_n = U_j . n
//      (morison: only the flow through the screen is resisted).
//  (b) per fluid particle i within 2 h_sc of a screen particle (the interface zone, eq. 2.28):
//        psi_i = -(1/m) sum_j F_d,j W_ji / S_j                                   (eqs. 2.27-2.28)
//      and 0 elsewhere. Since the same pairs enter S_j, sum_i m psi_i = -sum_j F_d,j exactly
//      (to round-off): the drag is conserved.
// Positions are p.position (r(t)); `velocity` gives the fluid velocities to use (size >=
// n_fluid; the thesis uses the fluid state of the previous step, i.e. u(t)). V_f = p.volume,
// m = p.mass. mu is the dynamic viscosity (Pa s). acceleration_out is resized to n_fluid
// (m/s^2), loads_out to the number of elements.
// In 3D the same with the 3D kernel, the normal (n_x, 0, n_z) of the extruded element and the
// area A_p = spacing x spacing_across.
// The moment about the origin of the screens' drag on the fluid in the last screen_drag call that
// used `work`: -sum_j r_j x F_d,j, the drag of screen particle j acting on the fluid around it (eq.
// 2.28 spreads it over its kernel). In particle order (deterministic).
template <int D>
Moment<D> screen_moment_on_fluid(const BasicScreenParticles<D>& screens, const BasicScreenDragWork<D>& work) {
  Moment<D> m{};
  for (std::size_t j = 0; j < screens.size() && j < work.drag.size(); ++j) m -= cross(screens.position[j], work.drag[j]);
  return m;
}

template <int D>
void screen_drag(const BasicScreenParticles<D>& screens, const BasicParticles<D>& p,
                 const std::vector<Vec<D>>& velocity, double rho, double mu, BasicScreenDragWork<D>& work,
                 std::vector<Vec<D>>& acceleration_out, std::vector<BasicScreenElementLoad<D>>& loads_out);

// Convenience: velocities p.velocity, a fresh work area; force_per_element_out[e] =
// loads[e].force_on_fluid.
void screen_drag(const ScreenParticles& screens, const Particles& p, double rho, double mu,
                 std::vector<Vec2>& acceleration_out, std::vector<Vec2>& force_per_element_out);

}  // namespace sloshsph
