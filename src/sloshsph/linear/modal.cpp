#include "sloshsph/linear/modal.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/linear/fluid_mesh.hpp"

namespace sloshsph {
namespace {

// Dunavant's 7-point rule on the reference triangle (degree 5), weights summing to 1/2.
struct QuadraturePoint {
  double l1, l2, l3, weight;
};
const std::array<QuadraturePoint, 7>& triangle_rule() {
  constexpr double a = 0.059715871789770, b = 0.470142064105115;
  constexpr double c = 0.797426985353087, d = 0.101286507323456;
  constexpr double w0 = 0.225 / 2, wa = 0.132394152788506 / 2, wc = 0.125939180544827 / 2;
  static const std::array<QuadraturePoint, 7> rule{{{1.0 / 3, 1.0 / 3, 1.0 / 3, w0},
                                                    {a, b, b, wa},
                                                    {b, a, b, wa},
                                                    {b, b, a, wa},
                                                    {c, d, d, wc},
                                                    {d, c, d, wc},
                                                    {d, d, c, wc}}};
  return rule;
}

// Gradients (rows d/dx, d/dy) of the six shape functions and the Jacobian determinant at a
// quadrature point of a 6-node isoparametric triangle.
struct ShapeGradients {
  Eigen::Matrix<double, 2, 6> grad;
  double det = 0.0;
};
ShapeGradients shape_gradients(const std::array<Vec2, 6>& x, const QuadraturePoint& q) {
  // Derivatives of the shape functions with respect to (xi, eta) = (l2, l3), l1 = 1 - xi - eta.
  const double l1 = q.l1, l2 = q.l2, l3 = q.l3;
  Eigen::Matrix<double, 2, 6> dn;
  dn << -(4 * l1 - 1), 4 * l2 - 1, 0.0, 4 * (l1 - l2), 4 * l3, -4 * l3,  //
      -(4 * l1 - 1), 0.0, 4 * l3 - 1, -4 * l2, 4 * l2, 4 * (l1 - l3);
  Eigen::Matrix2d jac = Eigen::Matrix2d::Zero();  // d(x, y) / d(xi, eta)
  for (int i = 0; i < 6; ++i) {
    jac(0, 0) += x[i].x * dn(0, i);
    jac(0, 1) += x[i].x * dn(1, i);
    jac(1, 0) += x[i].y * dn(0, i);
    jac(1, 1) += x[i].y * dn(1, i);
  }
  const double det = jac.determinant();
  if (!(det > 0.0)) throw std::runtime_error("sloshing_modes: inverted element in the fluid mesh");
  return {jac.inverse().transpose() * dn, det};
}

// Stiffness matrix int grad N_i . grad N_j of a 6-node isoparametric triangle.
Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Vec2, 6>& x) {
  Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
  for (const QuadraturePoint& q : triangle_rule()) {
    const ShapeGradients s = shape_gradients(x, q);
    k.noalias() += (q.weight * s.det) * s.grad.transpose() * s.grad;
  }
  return k;
}

// int dN_i/dx dA and int 1 dA of a 6-node isoparametric triangle: the element's share of
// int_fluid dphi/dx dA (the horizontal participation of a mode) and of the fluid area.
Eigen::Matrix<double, 6, 1> element_x_derivative_integral(const std::array<Vec2, 6>& x, double& area) {
  Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
  for (const QuadraturePoint& q : triangle_rule()) {
    const ShapeGradients s = shape_gradients(x, q);
    g += (q.weight * s.det) * s.grad.row(0).transpose();
    area += q.weight * s.det;
  }
  return g;
}

// Mass matrix of a straight quadratic surface edge, nodes (end, middle, end).
Eigen::Matrix3d edge_mass(double length) {
  Eigen::Matrix3d m;
  m << 4, 2, -1, 2, 16, 2, -1, 2, 4;
  return m * (length / 30.0);
}

double element_size(const std::vector<Vec2>& section, int resolution) {
  double y_low = section[0].y;
  for (const Vec2& p : section) y_low = std::min(y_low, p.y);
  const double level = section[0].y;
  const double width = std::abs(section.back().x - section.front().x);
  const double n = std::max(4, resolution);
  // Thin sections get several elements across the depth, but at most 4n along the surface.
  return std::max(std::min(width, 4.0 * (level - y_low)) / n, width / (4.0 * n));
}

}  // namespace

std::vector<SloshingMode> sloshing_modes(const TankGeometry& tank, double depth, double gravity, int count,
                                         const ModalOptions& options) {
  if (!(gravity > 0.0)) throw InputError("", "fluid.gravity", "gravity must be positive");
  const std::vector<Vec2> section = still_water_polygon(tank, depth);
  const FluidMesh mesh = mesh_section(section, element_size(section, options.resolution));

  // Free-surface unknowns first (numbered left to right), then the interior ones.
  const int n = static_cast<int>(mesh.nodes.size());
  std::vector<int> index(n, -1), surface_nodes;
  for (const auto& e : mesh.surface_edges)
    for (int k : {e[0], e[1], e[2]})
      if (index[k] < 0) {
        index[k] = static_cast<int>(surface_nodes.size());
        surface_nodes.push_back(k);
      }
  const int ns = static_cast<int>(surface_nodes.size());
  int next = ns;
  for (int k = 0; k < n; ++k)
    if (index[k] < 0) index[k] = next++;
  const int ni = n - ns;

  std::vector<Eigen::Triplet<double>> kii, kis;
  Eigen::MatrixXd kss = Eigen::MatrixXd::Zero(ns, ns);
  // int dN/dx dA per unknown (surface, interior) and the fluid area.
  Eigen::VectorXd gx_s = Eigen::VectorXd::Zero(ns), gx_i = Eigen::VectorXd::Zero(n - ns);
  double area = 0.0;
  for (const auto& e : mesh.elements) {
    std::array<Vec2, 6> x;
    for (int i = 0; i < 6; ++i) x[i] = mesh.nodes[e[i]];
    const Eigen::Matrix<double, 6, 1> ge = element_x_derivative_integral(x, area);
    for (int i = 0; i < 6; ++i) (index[e[i]] < ns ? gx_s(index[e[i]]) : gx_i(index[e[i]] - ns)) += ge(i);
    const Eigen::Matrix<double, 6, 6> ke = element_stiffness(x);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        const int r = index[e[i]], c = index[e[j]];
        if (r < ns && c < ns) kss(r, c) += ke(i, j);
        else if (r >= ns && c >= ns) kii.emplace_back(r - ns, c - ns, ke(i, j));
        else if (r >= ns) kis.emplace_back(r - ns, c, ke(i, j));
      }
  }
  Eigen::MatrixXd ms = Eigen::MatrixXd::Zero(ns, ns);
  for (const auto& e : mesh.surface_edges) {
    const Eigen::Matrix3d me = edge_mass(mesh.nodes[e[2]].x - mesh.nodes[e[0]].x);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ms(index[e[i]], index[e[j]]) += me(i, j);
  }

  // Schur complement onto the surface: S = K_ss - K_si K_ii^-1 K_is. K_ii is positive
  // definite (the interior problem with phi = 0 on the surface).
  Eigen::MatrixXd schur = kss;
  // The interior potential of a mode is phi_i = -K_ii^-1 K_is phi_s, so
  // int dphi/dx dA = (gx_s - (K_ii^-1 K_is)^T gx_i) . phi_s = participation . phi_s.
  Eigen::VectorXd participation = gx_s;
  if (ni > 0) {
    Eigen::SparseMatrix<double> a(ni, ni), b(ni, ns);
    a.setFromTriplets(kii.begin(), kii.end());
    b.setFromTriplets(kis.begin(), kis.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
    if (solver.info() != Eigen::Success) throw std::runtime_error("sloshing_modes: interior factorisation failed");
    // K_is is sparse (only interior nodes next to the surface couple to it): a sparse
    // product, not a dense one (also keeps Eigen's multithreaded GEMM out of this small job).
    const Eigen::MatrixXd x = solver.solve(Eigen::MatrixXd(b));
    schur -= Eigen::MatrixXd(b.transpose() * x);
    participation -= x.transpose() * gx_i;
  }
  schur = 0.5 * (schur + schur.transpose());

  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(schur, ms);
  if (eig.info() != Eigen::Success) throw std::runtime_error("sloshing_modes: eigen solver failed");

  // Eigenvalue 0 (the constant potential) comes first; modes follow in increasing order.
  std::vector<SloshingMode> modes;
  for (int k = 1; k < ns && static_cast<int>(modes.size()) < count; ++k) {
    SloshingMode mode;
    mode.omega = std::sqrt(std::max(0.0, gravity * eig.eigenvalues()(k)));
    mode.frequency = mode.omega / (2.0 * std::numbers::pi);
    std::vector<std::pair<double, double>> shape;
    for (int s = 0; s < ns; ++s) shape.push_back({mesh.nodes[surface_nodes[s]].x, eig.eigenvectors()(s, k)});
    std::sort(shape.begin(), shape.end());
    double largest = 0.0;
    for (const auto& [x, v] : shape) largest = std::max(largest, std::abs(v));
    const double scale = (shape.front().second < 0.0 ? -1.0 : 1.0) / largest;
    for (const auto& [x, v] : shape) {
      mode.surface_x.push_back(x);
      mode.surface_eta.push_back(v * scale);
    }
    // The eigenvectors are M_s-normalised (int_surface phi^2 dx = 1), so m_n / rho = Gamma^2 / lambda.
    const double gamma = participation.dot(eig.eigenvectors().col(k));
    const double lambda = eig.eigenvalues()(k);
    mode.effective_mass_fraction = gamma * gamma / lambda / area;
    // surface_eta = s phi with phi the M_s-normalised eigenvector and s = scale, so
    // eta = sum beta_n phi_n has beta_n = s q_n, and beta_n'' + omega^2 beta_n = -Gamma a.
    mode.horizontal_forcing = gamma / scale;
    mode.surface_moment = scale * gamma / lambda;
    modes.push_back(std::move(mode));
  }
  return modes;
}

double still_water_area(const TankGeometry& tank, double depth) {
  const std::vector<Vec2> section = still_water_polygon(tank, depth);
  double twice_area = 0.0;  // shoelace formula
  for (std::size_t i = 0; i < section.size(); ++i) {
    const Vec2& a = section[i];
    const Vec2& b = section[(i + 1) % section.size()];
    twice_area += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::abs(twice_area);
}

double first_sloshing_omega(const TankGeometry& tank, double depth, double gravity, const ModalOptions& options) {
  const std::vector<SloshingMode> modes = sloshing_modes(tank, depth, gravity, 1, options);
  if (modes.empty()) throw std::runtime_error("first_sloshing_omega: no mode");
  return modes.front().omega;
}

}  // namespace sloshsph
