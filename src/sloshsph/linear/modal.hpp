#pragma once
// Linear (potential-flow) sloshing modes of a tank section of any shape, by finite elements.
//
// Small motions of an inviscid, incompressible fluid: a velocity potential phi with
// Laplace(phi) = 0 in the still-water section, dphi/dn = 0 on the walls, and on the still
// free surface the combined kinematic and dynamic condition dphi/dy = (omega^2 / g) phi
// (e.g. Faltinsen & Timokha, Sloshing, 2009, ch. 4; Ibrahim, Liquid Sloshing Dynamics, 2005).
// The surface elevation of a mode is proportional to phi on the surface.
//
// Discretisation: quadratic isoparametric triangles (linear/fluid_mesh) give
// K phi = lambda M_s phi, lambda = omega^2 / g, K the stiffness (Laplacian) matrix and M_s
// the mass matrix of the free surface only. The interior unknowns are condensed out
// (Schur complement S = K_ss - K_si K_ii^-1 K_is, a discrete Dirichlet-to-Neumann map) and
// the small dense symmetric problem S v = lambda M_s v is solved with Eigen.
#include <vector>

#include "sloshsph/geometry/tank.hpp"

namespace sloshsph {

struct SloshingMode {
  double omega = 0.0;      // rad/s, natural angular frequency
  double frequency = 0.0;  // Hz
  // Mode shape of the free surface: x of the surface nodes (left to right) and the
  // elevation there, scaled to max |eta| = 1, positive at the left wall.
  std::vector<double> surface_x, surface_eta;
  // Share of the liquid that sloshes in this mode under a horizontal motion of the tank: the
  // effective (convective) mass of the mode's mechanical analogue divided by the liquid mass,
  //   m_n / m_w = (int_fluid dphi/dx dA)^2 / (lambda int_surface phi^2 dx) / A_fluid,
  // lambda = omega^2 / g (e.g. Ibrahim 2005, ch. 7; Faltinsen & Timokha 2009, ch. 7). For a
  // rectangle it is 8 tanh(n pi h / L) / (n^3 pi^3 h / L) for odd n and 0 for even n
  // (Graham & Rodriguez 1952); summed over all modes it is 1 minus the impulsive share.
  double effective_mass_fraction = 0.0;
  // The mode under a horizontal base acceleration a(t) (tank frame; linear/forced_response.hpp):
  // with the elevation eta = q(t) * surface_eta (the shape above, max 1), the modal coordinate
  // q (m) obeys q'' + omega^2 q = -horizontal_forcing * a(t). horizontal_forcing = Gamma / s, where
  // Gamma = int_fluid dphi/dx dA of the mode normalised to int_surface phi^2 dx = 1 and s the
  // scale from that phi to the shape above (surface_eta = s phi); dimensionless.
  // For a rectangle of length L, depth h:
  // -4 tanh(n pi h / L) / (n pi) for odd n, 0 for even n.
  double horizontal_forcing = 0.0;
  // int_surface x * surface_eta dx (m^2): the first moment of the shape, which shifts the
  // liquid's centre of mass, so that the liquid's horizontal momentum relative to the tank is
  // rho * sum_n q_n' * surface_moment_n (per metre of width). Equal to s Gamma / lambda by
  // Green's second identity (lambda = omega^2 / g); -2 L^2 / (n pi)^2 for odd n of a rectangle
  // (x from its left wall).
  double surface_moment = 0.0;
};

struct ModalOptions {
  // Elements per min(surface width, 4 x max depth): the element size is that length
  // divided by `resolution` (but never more than 4 x resolution elements along the surface).
  // 16 gives relative errors below 1e-5 on omega_1 and 1e-3 on omega_3 for the thesis's
  // tanks (rectangle, V, parabola, circle; see tests/unit/linear), about 1e-4 on omega_1
  // when a wall corner lies just below the surface; the error falls as resolution^-4 for
  // smooth sections.
  int resolution = 16;
};

// The first `count` sloshing modes (fewer if the mesh has fewer), in increasing frequency,
// of the section of `tank` filled to `depth` (m above tank.y_bottom). The constant
// potential (omega = 0) is not a mode and is not returned. For a symmetric tank mode 1 is
// the first antisymmetric one. Throws InputError (fill.depth) if the still-water region
// is not a single pool below the top of the walls (see still_water_polygon).
std::vector<SloshingMode> sloshing_modes(const TankGeometry& tank, double depth, double gravity, int count,
                                         const ModalOptions& options = {});

// Area (m^2) of the still-water section of `tank` filled to `depth`: the liquid mass per metre of
// width divided by the density.
double still_water_area(const TankGeometry& tank, double depth);

// omega_1 (rad/s), the lowest sloshing frequency.
double first_sloshing_omega(const TankGeometry& tank, double depth, double gravity, const ModalOptions& options = {});

}  // namespace sloshsph
