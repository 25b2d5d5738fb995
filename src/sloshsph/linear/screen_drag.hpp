#pragma once
// Vertical screens in the linear modal model of a rectangular tank (linear/forced_response.hpp):
// the screens' pressure loss acting on the sloshing modes.
//
// A screen at x_s across the depth from z_a to z_b (above the bottom) takes from the flow through
// it the pressure loss
//   dp(u) = r u + 1/2 rho C_l |u| u
// (Morison's drag term with the screen's loss coefficient C_l, and for an Ergun element also the
// Darcy term r = t mu / K; physics/porous.hpp), u the horizontal velocity at the screen. With the
// modes of a rectangle of length L and depth h, eta_n = q_n cos(k_n x), k_n = n pi / L (the shapes
// of linear/modal.hpp for a rectangle: max 1, positive at the left wall), the velocity at the
// screen is u(z) = sum_n q_n' U_n(z), U_n(z) = -sin(k_n x_s) cosh(k_n z) / sinh(k_n h) (potential
// flow, z above the bottom). The screen's power -int dp(u) u dz is the work of the generalised
// forces Q_n = -int dp(u) U_n dz, so each mode gains the acceleration Q_n / m_n, with the modal
// mass m_n = rho L coth(k_n h) / (2 k_n) per metre of width (twice the mode's kinetic energy per
// q_n'^2). The integral over z is by Gauss-Legendre quadrature. This keeps the drag's quadratic
// law and couples the modes through it; the equivalent linearisation of the TLD literature
// (Tait et al. 2005, J. Fluids Struct. 20; Tait 2008, J. Fluids Struct. 24) replaces it by the
// linear damping that takes the same energy per cycle at the response amplitude.
#include <vector>

namespace sloshsph {

struct LinearScreen {
  double x = 0.0;                  // m from the tank's left wall
  double z_from = 0.0, z_to = 0.0; // m above the bottom: the part of the still depth it spans
  double loss_coefficient = 0.0;   // C_l (dimensionless)
  double linear_resistance = 0.0;  // r, Pa s/m (Ergun's Darcy term t mu / K; 0 for Morison)
};

class RectangularScreenDrag {
 public:
  // `modes` modes n = 1 .. modes of the rectangle of `length` and still `depth` (m), liquid of
  // `density`. Throws std::invalid_argument for a screen outside the tank or the depth.
  RectangularScreenDrag(double length, double depth, double density, std::vector<LinearScreen> screens, int modes);

  // acceleration[n] += Q_n / m_n for the modal velocities q_n' in `velocity`.
  void add_accelerations(const std::vector<double>& velocity, std::vector<double>& acceleration) const;

  // m_n (kg/m per metre of width, per unit q_n): the modal mass of mode n (1-based).
  double modal_mass(int n) const { return modal_mass_[static_cast<std::size_t>(n - 1)]; }

 private:
  struct Node {
    std::size_t screen;
    double weight;               // quadrature weight (m)
    std::vector<double> shape;   // U_n at the node, n = 1 .. modes
  };
  double density_;
  std::vector<LinearScreen> screens_;
  std::vector<double> modal_mass_;
  std::vector<Node> nodes_;
};

// Gauss-Legendre nodes and weights on [a, b] (points >= 1), for the quadrature above.
void gauss_legendre(int points, double a, double b, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace sloshsph
