#include "sloshsph/structure/beam.hpp"

#include <Eigen/Eigenvalues>  // the modal analysis (GeneralizedSelfAdjointEigenSolver)

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

namespace {

constexpr int kDofsPerNode = 3;
constexpr int kMaxSubstepLevels = 5;  // a failed step is retried as 2, 4, ..., 32 sub-steps
constexpr int kMaxBisections = 12;    // static load increments may be halved this often

// The director (across the thickness, towards face +1) of a section at angle beta.
Vec2 director_at(double beta) { return {-std::sin(beta), std::cos(beta)}; }

void require(bool ok, const char* key, const std::string& what) {
  if (!ok) throw InputError("beam spec", key, what);
}

void validate(const BeamSpec& s) {
  require(s.thickness > 0.0, "structure.thickness", "must be > 0");
  require(s.width > 0.0, "structure.width", "must be > 0");
  require(s.youngs_modulus > 0.0, "structure.youngs_modulus", "must be > 0");
  require(s.poisson_ratio >= 0.0 && s.poisson_ratio < 0.5, "structure.poisson_ratio", "must be in [0, 0.5)");
  require(s.density > 0.0, "structure.density", "must be > 0");
  require(s.shear_correction > 0.0, "structure.shear_correction", "must be > 0");
  require(s.rayleigh_mass >= 0.0, "structure.rayleigh_mass", "must be >= 0");
  require(s.rayleigh_stiffness >= 0.0, "structure.rayleigh_stiffness", "must be >= 0");
  require(s.hht_alpha >= -1.0 / 3.0 && s.hht_alpha <= 0.0, "structure.hht_alpha", "must be in [-1/3, 0]");
  require(s.newton_tolerance > 0.0, "structure.newton_tolerance", "must be > 0");
  require(s.newton_increment_tolerance > 0.0, "structure.newton_increment_tolerance", "must be > 0");
  require(s.newton_max_iterations >= 1, "structure.newton_max_iterations", "must be >= 1");
  if (s.node_points.empty()) {
    require(s.elements >= 1, "structure.elements", "must be >= 1");
    require(norm(s.end - s.start) > 0.0, "structure.end", "must differ from structure.start");
  } else {
    require(s.node_points.size() >= 2, "structure.node_points", "needs at least two points");
  }
}

std::vector<Vec2> node_points_of(const BeamSpec& s) {
  if (!s.node_points.empty()) return s.node_points;
  std::vector<Vec2> points(static_cast<std::size_t>(s.elements) + 1);
  for (int i = 0; i <= s.elements; ++i) {
    points[static_cast<std::size_t>(i)] = s.start + (static_cast<double>(i) / s.elements) * (s.end - s.start);
  }
  return points;
}

double inf_norm(const Eigen::VectorXd& v) { return v.size() == 0 ? 0.0 : v.cwiseAbs().maxCoeff(); }

// Element mass matrix, DOF order x1 y1 theta1 x2 y2 theta2. Consistent: linear shape functions,
// integral N_i N_j = L/6 [2 1; 1 2]; lumped: half of the element to each node. Translational mass
// rho A per length, rotary inertia rho I per length (Simo & Vu-Quoc 1986: in 2D the kinetic energy
// 1/2 int (rho A |x'|^2 + rho I theta'^2) ds is exactly quadratic, so M is constant).
BeamElementMatrix element_mass(double length, double mass_per_length, double inertia_per_length, BeamMass kind) {
  BeamElementMatrix m = BeamElementMatrix::Zero();
  const double per_dof[3] = {mass_per_length, mass_per_length, inertia_per_length};
  for (int c = 0; c < 3; ++c) {
    const double total = per_dof[c] * length;
    if (kind == BeamMass::kConsistent) {
      m(c, c) = m(c + 3, c + 3) = total / 3.0;
      m(c, c + 3) = m(c + 3, c) = total / 6.0;
    } else {
      m(c, c) = m(c + 3, c + 3) = total / 2.0;
    }
  }
  return m;
}

}  // namespace

struct Beam::Assembly {
  Eigen::VectorXd internal;  // f_int, all DOFs
  Eigen::VectorXd damping;   // f_damp = b0 M v + b1 sum L0 B^T D B v
  Eigen::VectorXd external;  // f_ext (nodal loads, body forces, follower pressure)
  std::vector<Eigen::Triplet<double>> triplets;  // effective tangent on the free DOFs
};

Beam::Beam(const BeamSpec& spec) : spec_(spec) {
  validate(spec_);
  initial_positions_ = node_points_of(spec_);
  const int nodes = node_count();

  const double youngs = spec_.plane_strain
                            ? spec_.youngs_modulus / (1.0 - spec_.poisson_ratio * spec_.poisson_ratio)
                            : spec_.youngs_modulus;
  const double shear_modulus = spec_.youngs_modulus / (2.0 * (1.0 + spec_.poisson_ratio));
  const double area = spec_.width * spec_.thickness;
  const double second_moment = spec_.width * std::pow(spec_.thickness, 3) / 12.0;
  section_ = {youngs * area, spec_.shear_correction * shear_modulus * area, youngs * second_moment};
  mass_per_length_ = spec_.density * area;
  rotary_inertia_per_length_ = spec_.density * second_moment;

  for (int e = 0; e + 1 < nodes; ++e) {
    const auto first = static_cast<std::size_t>(e);
    const Vec2 d = initial_positions_[first + 1] - initial_positions_[first];
    const double length = norm(d);
    require(length > 0.0, "structure.node_points",
            "consecutive points must differ (element " + std::to_string(e) + ")");
    elements_.push_back({length, std::atan2(d.y, d.x)});
    total_length_ += length;
  }
  // Node director: mean of the adjacent element directors (they differ only at kinks of the polyline).
  initial_directors_.assign(static_cast<std::size_t>(nodes), Vec2{});
  for (int e = 0; e < element_count(); ++e) {
    const Vec2 director = director_at(elements_[static_cast<std::size_t>(e)].angle);
    initial_directors_[static_cast<std::size_t>(e)] += director;
    initial_directors_[static_cast<std::size_t>(e) + 1] += director;
  }
  for (auto& d : initial_directors_) d = normalized(d);

  // Constraints -> equation numbers.
  std::vector<bool> fixed(static_cast<std::size_t>(kDofsPerNode * nodes), false);
  auto fix = [&](int node, bool x, bool y, bool rotation) {
    require(node >= 0 && node < nodes, "structure.constraints", "node index out of range: " + std::to_string(node));
    const auto base = static_cast<std::size_t>(kDofsPerNode * node);
    if (x) fixed[base] = true;
    if (y) fixed[base + 1] = true;
    if (rotation) fixed[base + 2] = true;
  };
  auto support = [&](int node, BeamSupport s) {
    if (s == BeamSupport::kPinned) fix(node, true, true, false);
    if (s == BeamSupport::kClamped) fix(node, true, true, true);
  };
  support(0, spec_.start_support);
  support(nodes - 1, spec_.end_support);
  for (const auto& c : spec_.constraints) fix(c.node, c.fix_x, c.fix_y, c.fix_rotation);
  equation_.assign(fixed.size(), -1);
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    if (!fixed[i]) equation_[i] = free_dofs_++;
  }
  require(free_dofs_ > 0, "structure.constraints", "every DOF is constrained");
  int bandwidth = 0;  // largest equation distance within one element
  for (int e = 0; e < element_count(); ++e) {
    int low = free_dofs_, high = -1;
    for (int i = 0; i < 6; ++i) {
      const int eq = equation_[static_cast<std::size_t>(kDofsPerNode * e + i)];
      if (eq < 0) continue;
      low = std::min(low, eq);
      high = std::max(high, eq);
    }
    if (high >= 0) bandwidth = std::max(bandwidth, high - low);
  }
  solver_ = BandedLu(free_dofs_, bandwidth, bandwidth);

  // Constant mass matrix.
  std::vector<Eigen::Triplet<double>> mass_triplets;
  for (int e = 0; e < element_count(); ++e) {
    const BeamElementMatrix m = element_mass(elements_[static_cast<std::size_t>(e)].length, mass_per_length_,
                                             rotary_inertia_per_length_, spec_.mass);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        if (m(i, j) != 0.0) mass_triplets.emplace_back(kDofsPerNode * e + i, kDofsPerNode * e + j, m(i, j));
      }
    }
  }
  const int dofs = kDofsPerNode * nodes;
  mass_.resize(dofs, dofs);
  mass_.setFromTriplets(mass_triplets.begin(), mass_triplets.end());

  state_.q.setZero(dofs);
  state_.v.setZero(dofs);
  state_.a.setZero(dofs);
  state_.previous_force_balance.setZero(dofs);
  state_.previous_external.setZero(dofs);
  state_.previous_damping.setZero(dofs);
}

BeamLoads Beam::zero_loads() const {
  BeamLoads loads;
  loads.nodal_forces.assign(static_cast<std::size_t>(node_count()), Vec2{});
  loads.nodal_moments.assign(static_cast<std::size_t>(node_count()), 0.0);
  return loads;
}

void Beam::check_loads(const BeamLoads& loads) const {
  const auto nodes = static_cast<std::size_t>(node_count());
  auto sized = [&](std::size_t size, const char* key) {
    if (size != 0 && size != nodes) {
      throw InputError("beam loads", key,
                       "expected " + std::to_string(nodes) + " values (one per node), got " + std::to_string(size));
    }
  };
  sized(loads.nodal_forces.size(), "nodal_forces");
  sized(loads.nodal_moments.size(), "nodal_moments");
  sized(loads.nodal_pressure.size(), "nodal_pressure");
  if (loads.pressure_side != 1 && loads.pressure_side != -1) {
    throw InputError("beam loads", "pressure_side", "must be +1 or -1");
  }
}

BeamElementState Beam::element_state(const Eigen::VectorXd& q, int element) const {
  const int base = kDofsPerNode * element;
  return {{q[base + 3] - q[base], q[base + 4] - q[base + 1]}, q[base + 2], q[base + 5]};
}

void Beam::scatter(int element, const BeamElementMatrix& k_eff, std::vector<Eigen::Triplet<double>>& triplets) const {
  const int base = kDofsPerNode * element;
  for (int i = 0; i < 6; ++i) {
    const int row = equation_[static_cast<std::size_t>(base + i)];
    if (row < 0) continue;
    for (int j = 0; j < 6; ++j) {
      const int col = equation_[static_cast<std::size_t>(base + j)];
      if (col >= 0) triplets.emplace_back(row, col, k_eff(i, j));
    }
  }
}

// Follower pressure on one element (beam_loads.hpp): F_a = c_a perp(x2 - x1), c_1 = -side b (2p1+p2)/6,
// c_2 = -side b (p1+2p2)/6. Adds F to `external` and -tangent_factor dF/dq to k_eff (residual = ... - f_ext).
void Beam::add_pressure_loads(int element, const Eigen::VectorXd& q, const BeamLoads& loads, double load_factor,
                              double tangent_factor, BeamElementMatrix& k_eff, Eigen::VectorXd& external) const {
  const int base = kDofsPerNode * element;
  const auto e = static_cast<std::size_t>(element);
  const double p1 = load_factor * loads.nodal_pressure[e];
  const double p2 = load_factor * loads.nodal_pressure[e + 1];
  const double scale = -static_cast<double>(loads.pressure_side) * spec_.width;
  const double c[2] = {scale * (2.0 * p1 + p2) / 6.0, scale * (p1 + 2.0 * p2) / 6.0};
  const Vec2 chord =
      initial_positions_[e + 1] - initial_positions_[e] + element_state(q, element).relative_displacement;
  const Vec2 normal_times_length = perp(chord);
  for (int a = 0; a < 2; ++a) {
    external[base + 3 * a] += c[a] * normal_times_length.x;
    external[base + 3 * a + 1] += c[a] * normal_times_length.y;
    for (int b = 0; b < 2; ++b) {
      // d perp(x2 - x1)/d x_b = sign_b P with P = [[0, -1], [1, 0]], sign_1 = -1, sign_2 = +1.
      const double sign = b == 0 ? -1.0 : 1.0;
      k_eff(3 * a, 3 * b + 1) += tangent_factor * c[a] * sign;
      k_eff(3 * a + 1, 3 * b) -= tangent_factor * c[a] * sign;
    }
  }
}

void Beam::add_nodal_and_body_loads(const BeamLoads& loads, double load_factor, Eigen::VectorXd& external) const {
  // Body forces: the consistent nodal forces of a uniform acceleration field are M * g.
  const Vec2 acceleration = load_factor * (spec_.gravity + loads.body_acceleration);
  if (acceleration.x != 0.0 || acceleration.y != 0.0) {
    Eigen::VectorXd field = Eigen::VectorXd::Zero(external.size());
    for (int n = 0; n < node_count(); ++n) {
      field[kDofsPerNode * n] = acceleration.x;
      field[kDofsPerNode * n + 1] = acceleration.y;
    }
    external += mass_ * field;
  }
  for (std::size_t n = 0; n < loads.nodal_forces.size(); ++n) {
    external[kDofsPerNode * static_cast<int>(n)] += load_factor * loads.nodal_forces[n].x;
    external[kDofsPerNode * static_cast<int>(n) + 1] += load_factor * loads.nodal_forces[n].y;
  }
  for (std::size_t n = 0; n < loads.nodal_moments.size(); ++n) {
    external[kDofsPerNode * static_cast<int>(n) + 2] += load_factor * loads.nodal_moments[n];
  }
}

// Assembles internal, damping and external forces at (q, v) and the effective tangent
//   factors.mass M + factors.damping (b0 M + b1 K_mat) + factors.stiffness (K_T + df_damp/dq - df_ext/dq)
// on the free DOFs (static solve, HHT, modes).
void Beam::assemble(const Eigen::VectorXd& q, const Eigen::VectorXd& v, const BeamLoads& loads, double load_factor,
                    bool with_damping, const TangentFactors& factors, Assembly& out) const {
  const int dofs = static_cast<int>(q.size());
  out.internal.setZero(dofs);
  out.damping.setZero(dofs);
  out.external.setZero(dofs);
  out.triplets.clear();
  out.triplets.reserve(static_cast<std::size_t>(36 * element_count()));

  const double b0 = with_damping ? spec_.rayleigh_mass : 0.0;
  const double b1 = with_damping ? spec_.rayleigh_stiffness : 0.0;
  const Eigen::Vector3d stiffness{section_.axial, section_.shear, section_.bending};

  for (int e = 0; e < element_count(); ++e) {
    const int base = kDofsPerNode * e;
    const BeamElementGeometry& geometry = elements_[static_cast<std::size_t>(e)];
    const BeamElementKinematics kin = beam_element_kinematics(geometry, element_state(q, e));
    const BeamElementResponse response = beam_element_response(geometry, section_, kin);
    out.internal.segment<6>(base) += response.internal_force;

    BeamElementMatrix k_eff = factors.stiffness * response.tangent;
    k_eff += (factors.mass + factors.damping * b0) *
             element_mass(geometry.length, mass_per_length_, rotary_inertia_per_length_, spec_.mass);

    if (b1 > 0.0) {
      // Stiffness-proportional Rayleigh damping written on the strain rates: f = L0 B^T (b1 D B v).
      // For small motions this is b1 K v; it does not damp rigid rotations (B v = 0 for them).
      const BeamElementVector v_e = v.segment<6>(base);
      const Eigen::Vector3d damping_resultants = b1 * stiffness.cwiseProduct(kin.b_matrix * v_e);
      out.damping.segment<6>(base) += geometry.length * kin.b_matrix.transpose() * damping_resultants;
      // d f/dq = L0 (sum_k s_k H_k + B^T b1 D G), G row k = (H_k v)^T.
      Eigen::Matrix<double, 3, 6> g = Eigen::Matrix<double, 3, 6>::Zero();
      BeamElementMatrix d_dq = BeamElementMatrix::Zero();
      for (int k = 0; k < 2; ++k) {
        g.row(k) = (kin.hessian[k] * v_e).transpose();
        d_dq += damping_resultants[k] * kin.hessian[k];
      }
      d_dq += kin.b_matrix.transpose() * (b1 * stiffness).asDiagonal() * g;
      k_eff += factors.stiffness * geometry.length * d_dq;
      k_eff += factors.damping * b1 * response.material_tangent;
    }
    if (!loads.nodal_pressure.empty()) {
      add_pressure_loads(e, q, loads, load_factor, factors.stiffness, k_eff, out.external);
    }
    scatter(e, k_eff, out.triplets);
  }
  if (b0 > 0.0) out.damping += b0 * (mass_ * v);
  add_nodal_and_body_loads(loads, load_factor, out.external);
}

// The energy-conserving step's forces from q0 to q1 (beam_element_midpoint_response) and the tangent of
//   R(q1) = M (v1 - v0)/dt + f_alg + f_damp,alg + b0 M vmid - (f_ext(q0) + f_ext(q1))/2,
// vmid = (q1 - q0)/dt, v1 = 2 vmid - v0. `external` is f_ext(q1).
void Beam::assemble_midpoint(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, const BeamLoads& loads, double dt,
                             Assembly& out) const {
  const int dofs = static_cast<int>(q1.size());
  out.internal.setZero(dofs);
  out.damping.setZero(dofs);
  out.external.setZero(dofs);
  out.triplets.clear();
  out.triplets.reserve(static_cast<std::size_t>(36 * element_count()));
  const double b0 = spec_.rayleigh_mass;
  const double b1_over_dt = spec_.rayleigh_stiffness / dt;
  const double mass_factor = 2.0 / (dt * dt) + b0 / dt;

  for (int e = 0; e < element_count(); ++e) {
    const int base = kDofsPerNode * e;
    const BeamElementGeometry& geometry = elements_[static_cast<std::size_t>(e)];
    const BeamElementMidpointResponse response = beam_element_midpoint_response(
        geometry, section_, element_state(q0, e), element_state(q1, e), b1_over_dt);
    out.internal.segment<6>(base) += response.elastic_force;
    out.damping.segment<6>(base) += response.damping_force;
    BeamElementMatrix k_eff = response.tangent;
    k_eff += mass_factor * element_mass(geometry.length, mass_per_length_, rotary_inertia_per_length_, spec_.mass);
    if (!loads.nodal_pressure.empty()) add_pressure_loads(e, q1, loads, 1.0, 0.5, k_eff, out.external);
    scatter(e, k_eff, out.triplets);
  }
  if (b0 > 0.0) out.damping += (b0 / dt) * (mass_ * (q1 - q0));
  add_nodal_and_body_loads(loads, 1.0, out.external);
}

Eigen::VectorXd Beam::expand(const Eigen::VectorXd& free) const {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(equation_.size()));
  for (std::size_t i = 0; i < equation_.size(); ++i) {
    if (equation_[i] >= 0) full[static_cast<Eigen::Index>(i)] = free[equation_[i]];
  }
  return full;
}

Eigen::VectorXd Beam::free_part(const Eigen::VectorXd& full) const {
  Eigen::VectorXd part(free_dofs_);
  for (std::size_t i = 0; i < equation_.size(); ++i) {
    if (equation_[i] >= 0) part[equation_[i]] = full[static_cast<Eigen::Index>(i)];
  }
  return part;
}

bool Beam::solve_linear(const std::vector<Eigen::Triplet<double>>& triplets, const Eigen::VectorXd& rhs,
                        Eigen::VectorXd& solution) {
  solver_.set_zero();
  for (const auto& t : triplets) solver_.add(t.row(), t.col(), t.value());
  if (!solver_.factorize()) return false;
  solution = rhs;
  solver_.solve(solution);
  return solution.allFinite();
}

namespace {

// Largest Newton correction, positions relative to the beam length, rotations in radians.
double scaled_increment(const Eigen::VectorXd& delta_full, double length) {
  double largest = 0.0;
  for (Eigen::Index i = 0; i < delta_full.size(); ++i) {
    const double scale = (i % kDofsPerNode == 2) ? 1.0 : 1.0 / length;
    largest = std::max(largest, std::abs(delta_full[i]) * scale);
  }
  return largest;
}

}  // namespace

bool Beam::newton_correction(const Assembly& assembly, const Eigen::VectorXd& residual, Eigen::VectorXd& q,
                             bool& small_increment) {
  Eigen::VectorXd delta;
  if (!solve_linear(assembly.triplets, -residual, delta)) return false;
  const Eigen::VectorXd delta_full = expand(delta);
  q += delta_full;
  small_increment = scaled_increment(delta_full, total_length_) <= spec_.newton_increment_tolerance;
  return true;
}

void Beam::prepare_initial_acceleration(const BeamLoads& loads) {
  // M a0 = f_ext - f_int - f_damp at the start of the motion (the loads of the first step are taken as
  // the loads at t0).
  Assembly assembly;
  assemble(state_.q, state_.v, loads, 1.0, true, {0.0, 0.0, 1.0}, assembly);
  const Eigen::VectorXd balance = assembly.internal + assembly.damping - assembly.external;
  Eigen::VectorXd a_free;
  if (!solve_linear(assembly.triplets, -free_part(balance), a_free)) {
    throw RunFailure("beam: singular mass matrix when computing the initial acceleration");
  }
  state_.a = expand(a_free);
  state_.previous_force_balance = balance;
  state_.previous_external = assembly.external;
  state_.previous_damping = assembly.damping;
  state_.acceleration_ready = true;
}

bool Beam::try_step(double dt, const BeamLoads& loads, int& iterations) {
  return spec_.integrator == BeamIntegrator::kHHT ? try_step_hht(dt, loads, iterations)
                                                   : try_step_midpoint(dt, loads, iterations);
}

// One HHT-alpha step (Hilber, Hughes & Taylor 1977; Hughes, "The Finite Element Method", 2000, sec. 9.3):
//   M a1 + (1 + alpha) g(q1, v1) - alpha g(q0, v0) = 0,   g = f_int + f_damp - f_ext,
//   q1 = q0 + dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),  v1 = v0 + dt ((1 - gamma) a0 + gamma a1),
// beta = (1 - alpha)^2 / 4, gamma = 1/2 - alpha; alpha = 0 is Newmark's average acceleration rule.
// Newton on q1. The state changes only if the iteration converges.
bool Beam::try_step_hht(double dt, const BeamLoads& loads, int& iterations) {
  const double alpha = spec_.hht_alpha;
  const double beta = 0.25 * (1.0 - alpha) * (1.0 - alpha);
  const double gamma = 0.5 - alpha;
  const State& s = state_;

  Eigen::VectorXd q = s.q + dt * s.v + (0.5 * dt * dt) * s.a;  // predictor: a1 = a0
  const TangentFactors factors{1.0 + alpha, (1.0 + alpha) * gamma / (beta * dt), 1.0 / (beta * dt * dt)};
  const double force_floor = 1e-6 * section_.bending / (total_length_ * total_length_);
  Assembly assembly;
  bool small_increment = false;
  for (int it = 0; it <= spec_.newton_max_iterations; ++it) {
    const Eigen::VectorXd a1 = (q - s.q - dt * s.v) / (beta * dt * dt) - (0.5 / beta - 1.0) * s.a;
    const Eigen::VectorXd v1 = s.v + dt * ((1.0 - gamma) * s.a + gamma * a1);
    assemble(q, v1, loads, 1.0, true, factors, assembly);
    const Eigen::VectorXd inertia = mass_ * a1;
    const Eigen::VectorXd balance = assembly.internal + assembly.damping - assembly.external;
    const Eigen::VectorXd residual = free_part(inertia + (1.0 + alpha) * balance - alpha * s.previous_force_balance);
    if (!residual.allFinite()) return false;
    const double reference = std::max({inf_norm(inertia), inf_norm(assembly.internal), inf_norm(assembly.external),
                                       inf_norm(assembly.damping), force_floor});
    if (inf_norm(residual) <= spec_.newton_tolerance * reference || small_increment) {
      iterations += it;
      State next = s;
      next.external_work += 0.5 * (s.previous_external + assembly.external).dot(q - s.q);
      next.dissipated += 0.5 * (s.previous_damping + assembly.damping).dot(q - s.q);
      next.q = q;
      next.v = v1;
      next.a = a1;
      next.previous_force_balance = balance;
      next.previous_external = assembly.external;
      next.previous_damping = assembly.damping;
      next.time += dt;
      state_ = std::move(next);
      return true;
    }
    if (it == spec_.newton_max_iterations) break;
    if (!newton_correction(assembly, residual, q, small_increment)) return false;
  }
  return false;
}

// One energy-conserving step: (q1 - q0)/dt = (v0 + v1)/2 and
//   M (v1 - v0)/dt + f_alg(q0, q1) + f_damp,alg + b0 M (v0 + v1)/2 = (f_ext(t0) + f_ext(t1))/2
// with the discrete-gradient forces of beam_element_midpoint_response. Multiplying by q1 - q0 gives the
// exact discrete balance  dKE + dU = W_ext - (damping work >= 0)  (Simo & Tarnow 1992), whatever dt.
bool Beam::try_step_midpoint(double dt, const BeamLoads& loads, int& iterations) {
  const State& s = state_;
  Eigen::VectorXd q = s.q + dt * s.v;  // predictor: constant velocity
  const double force_floor = 1e-6 * section_.bending / (total_length_ * total_length_);
  Assembly assembly;
  bool small_increment = false;
  for (int it = 0; it <= spec_.newton_max_iterations; ++it) {
    const Eigen::VectorXd v1 = (2.0 / dt) * (q - s.q) - s.v;
    assemble_midpoint(s.q, q, loads, dt, assembly);
    const Eigen::VectorXd inertia = mass_ * ((v1 - s.v) / dt);
    const Eigen::VectorXd external = 0.5 * (s.previous_external + assembly.external);
    const Eigen::VectorXd residual = free_part(inertia + assembly.internal + assembly.damping - external);
    if (!residual.allFinite()) return false;
    const double reference = std::max({inf_norm(inertia), inf_norm(assembly.internal), inf_norm(external),
                                       inf_norm(assembly.damping), force_floor});
    if (inf_norm(residual) <= spec_.newton_tolerance * reference || small_increment) {
      iterations += it;
      State next = s;
      next.external_work += external.dot(q - s.q);
      next.dissipated += assembly.damping.dot(q - s.q);
      next.q = q;
      next.v = v1;
      next.a = (v1 - s.v) / dt;
      next.previous_external = assembly.external;
      next.previous_damping = assembly.damping;
      next.time += dt;
      state_ = std::move(next);
      return true;
    }
    if (it == spec_.newton_max_iterations) break;
    if (!newton_correction(assembly, residual, q, small_increment)) return false;
  }
  return false;
}

BeamSolveReport Beam::step(double dt, const BeamLoads& loads) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("beam step", "dt", "must be a finite number > 0");
  check_loads(loads);
  if (!state_.acceleration_ready) prepare_initial_acceleration(loads);
  BeamSolveReport report;
  if (try_step(dt, loads, report.iterations)) return report;
  for (int level = 1; level <= kMaxSubstepLevels; ++level) {
    const State saved = state_;
    const int substeps = 1 << level;
    bool ok = true;
    for (int k = 0; k < substeps && ok; ++k) ok = try_step(dt / substeps, loads, report.iterations);
    if (ok) {
      report.substeps = substeps;
      return report;
    }
    state_ = saved;
  }
  throw RunFailure("beam: Newton iteration did not converge at t = " + std::to_string(state_.time) +
                   " s even with " + std::to_string(1 << kMaxSubstepLevels) + " sub-steps of dt = " +
                   std::to_string(dt) + " s");
}

BeamSolveReport Beam::step(double dt, const std::vector<Vec2>& nodal_forces, Vec2 body_acceleration) {
  BeamLoads loads;
  loads.nodal_forces = nodal_forces;
  loads.body_acceleration = body_acceleration;
  return step(dt, loads);
}

BeamSolveReport Beam::static_solve(const BeamLoads& loads, int load_steps) {
  if (load_steps < 1) throw InputError("beam static solve", "load_steps", "must be >= 1");
  check_loads(loads);
  const double force_floor = 1e-6 * section_.bending / (total_length_ * total_length_);
  const TangentFactors factors{1.0, 0.0, 0.0};
  const Eigen::VectorXd zero_velocity = Eigen::VectorXd::Zero(state_.q.size());
  BeamSolveReport report;
  report.substeps = 0;

  // Newton on f_int(q) = lambda f_ext(q) for one load factor lambda, from the current q;
  // changes state_.q only on success.
  auto solve_at = [&](double load_factor) {
    Eigen::VectorXd q = state_.q;
    Assembly assembly;
    bool small_increment = false;
    for (int it = 0; it <= spec_.newton_max_iterations; ++it) {
      assemble(q, zero_velocity, loads, load_factor, false, factors, assembly);
      const Eigen::VectorXd residual = free_part(assembly.internal - assembly.external);
      if (!residual.allFinite()) return false;
      const double reference = std::max({inf_norm(assembly.internal), inf_norm(assembly.external), force_floor});
      if (inf_norm(residual) <= spec_.newton_tolerance * reference || small_increment) {
        report.iterations += it;
        state_.q = q;
        return true;
      }
      if (it == spec_.newton_max_iterations) break;
      if (!newton_correction(assembly, residual, q, small_increment)) return false;
    }
    return false;
  };

  double reached = 0.0;
  double increment = 1.0 / load_steps;
  int bisections = 0;
  while (reached < 1.0) {
    const double target = reached + increment > 1.0 - 1e-12 ? 1.0 : reached + increment;
    if (solve_at(target)) {
      reached = target;
      ++report.substeps;
      continue;
    }
    if (++bisections > kMaxBisections) {
      throw RunFailure("beam: static Newton iteration did not converge at load factor " + std::to_string(target));
    }
    increment *= 0.5;
  }
  state_.v.setZero();
  state_.a.setZero();
  state_.acceleration_ready = false;
  return report;
}

std::vector<Vec2> Beam::node_positions() const {
  std::vector<Vec2> out = node_displacements();
  for (std::size_t n = 0; n < out.size(); ++n) out[n] += initial_positions_[n];
  return out;
}

std::vector<Vec2> Beam::node_displacements() const {
  std::vector<Vec2> out(static_cast<std::size_t>(node_count()));
  for (int n = 0; n < node_count(); ++n) {
    out[static_cast<std::size_t>(n)] = {state_.q[kDofsPerNode * n], state_.q[kDofsPerNode * n + 1]};
  }
  return out;
}

std::vector<Vec2> Beam::node_velocities() const {
  std::vector<Vec2> out(static_cast<std::size_t>(node_count()));
  for (int n = 0; n < node_count(); ++n) {
    out[static_cast<std::size_t>(n)] = {state_.v[kDofsPerNode * n], state_.v[kDofsPerNode * n + 1]};
  }
  return out;
}

std::vector<double> Beam::node_rotations() const {
  std::vector<double> out(static_cast<std::size_t>(node_count()));
  for (int n = 0; n < node_count(); ++n) out[static_cast<std::size_t>(n)] = state_.q[kDofsPerNode * n + 2];
  return out;
}

std::vector<double> Beam::node_angular_velocities() const {
  std::vector<double> out(static_cast<std::size_t>(node_count()));
  for (int n = 0; n < node_count(); ++n) out[static_cast<std::size_t>(n)] = state_.v[kDofsPerNode * n + 2];
  return out;
}

std::vector<Vec2> Beam::node_directors() const {
  std::vector<Vec2> out(static_cast<std::size_t>(node_count()));
  for (int n = 0; n < node_count(); ++n) {
    out[static_cast<std::size_t>(n)] =
        rotated(initial_directors_[static_cast<std::size_t>(n)], state_.q[kDofsPerNode * n + 2]);
  }
  return out;
}

std::vector<Vec2> Beam::surface(int side) const {
  if (side != 1 && side != -1) throw InputError("beam surface", "side", "must be +1 or -1");
  const double offset = 0.5 * side * spec_.thickness;
  std::vector<Vec2> out = node_positions();
  const std::vector<Vec2> directors = node_directors();
  for (std::size_t n = 0; n < out.size(); ++n) out[n] += offset * directors[n];
  return out;
}

std::vector<Vec2> Beam::surface_velocities(int side) const {
  if (side != 1 && side != -1) throw InputError("beam surface", "side", "must be +1 or -1");
  const double offset = 0.5 * side * spec_.thickness;
  std::vector<Vec2> out = node_velocities();
  const std::vector<Vec2> directors = node_directors();
  const std::vector<double> omega = node_angular_velocities();
  for (std::size_t n = 0; n < out.size(); ++n) out[n] += (offset * omega[n]) * perp(directors[n]);
  return out;
}

std::vector<Vec2> Beam::outline() const {
  std::vector<Vec2> out = surface(+1);
  const std::vector<Vec2> back = surface(-1);
  out.insert(out.end(), back.rbegin(), back.rend());
  return out;
}

double Beam::section_angle(int element, double xi) const {
  const int base = kDofsPerNode * element;
  return elements_[static_cast<std::size_t>(element)].angle + (1.0 - xi) * state_.q[base + 2] + xi * state_.q[base + 5];
}

BeamMaterialPoint Beam::material_point(Vec2 reference_point) const {
  BeamMaterialPoint best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int e = 0; e < element_count(); ++e) {
    const Vec2 x1 = initial_positions_[static_cast<std::size_t>(e)];
    const Vec2 d = initial_positions_[static_cast<std::size_t>(e) + 1] - x1;
    const double xi = std::clamp(dot(reference_point - x1, d) / norm2(d), 0.0, 1.0);
    const Vec2 foot = x1 + xi * d;
    const double distance = norm(reference_point - foot);
    if (distance < best_distance) {
      best_distance = distance;
      best = {e, xi, dot(reference_point - foot, director_at(elements_[static_cast<std::size_t>(e)].angle))};
    }
  }
  return best;
}

Vec2 Beam::position(const BeamMaterialPoint& p) const {
  const auto first = static_cast<std::size_t>(p.element);
  const int base = kDofsPerNode * p.element;
  const Vec2 x1 = initial_positions_[first] + Vec2{state_.q[base], state_.q[base + 1]};
  const Vec2 x2 = initial_positions_[first + 1] + Vec2{state_.q[base + 3], state_.q[base + 4]};
  return (1.0 - p.xi) * x1 + p.xi * x2 + p.offset * director_at(section_angle(p.element, p.xi));
}

Vec2 Beam::velocity(const BeamMaterialPoint& p) const {
  const int base = kDofsPerNode * p.element;
  const Vec2 v1{state_.v[base], state_.v[base + 1]};
  const Vec2 v2{state_.v[base + 3], state_.v[base + 4]};
  const double omega = (1.0 - p.xi) * state_.v[base + 2] + p.xi * state_.v[base + 5];
  const Vec2 director = director_at(section_angle(p.element, p.xi));
  return (1.0 - p.xi) * v1 + p.xi * v2 + (p.offset * omega) * perp(director);
}

// Work-consistent with position(): delta p = N1 dx1 + N2 dx2 + offset dtheta perp(director), so the
// force F gives N_i F on the nodes and the moments N_i cross(offset director, F).
void Beam::add_force(const BeamMaterialPoint& p, Vec2 force, BeamLoads& loads) const {
  const auto nodes = static_cast<std::size_t>(node_count());
  if (loads.nodal_forces.empty()) loads.nodal_forces.assign(nodes, Vec2{});
  if (loads.nodal_moments.empty()) loads.nodal_moments.assign(nodes, 0.0);
  check_loads(loads);
  if (p.element < 0 || p.element >= element_count()) {
    throw InputError("beam loads", "material_point.element", "out of range: " + std::to_string(p.element));
  }
  const auto first = static_cast<std::size_t>(p.element);
  const double moment = cross(p.offset * director_at(section_angle(p.element, p.xi)), force);
  loads.nodal_forces[first] += (1.0 - p.xi) * force;
  loads.nodal_forces[first + 1] += p.xi * force;
  loads.nodal_moments[first] += (1.0 - p.xi) * moment;
  loads.nodal_moments[first + 1] += p.xi * moment;
}

void Beam::scale_velocities(double factor) {
  state_.v *= factor;
  state_.acceleration_ready = false;
}

double Beam::rotation(const BeamMaterialPoint& p) const {
  const int base = kDofsPerNode * p.element;
  return (1.0 - p.xi) * state_.q[base + 2] + p.xi * state_.q[base + 5];
}

namespace {
std::vector<double> to_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }
Eigen::VectorXd from_vector(const std::vector<double>& v, Eigen::Index size, const std::string& name) {
  if (static_cast<Eigen::Index>(v.size()) != size)
    throw InputError("checkpoint", name, "holds " + std::to_string(v.size()) + " values, the beam has " +
                                             std::to_string(size) + " degrees of freedom");
  return Eigen::Map<const Eigen::VectorXd>(v.data(), size);
}
}  // namespace

void Beam::save_state(StateWriter& w, const std::string& prefix) const {
  w.array(prefix + ".q", to_vector(state_.q));
  w.array(prefix + ".v", to_vector(state_.v));
  w.array(prefix + ".a", to_vector(state_.a));
  w.value(prefix + ".acceleration_ready", static_cast<std::uint8_t>(state_.acceleration_ready));
  w.array(prefix + ".previous_force_balance", to_vector(state_.previous_force_balance));
  w.array(prefix + ".previous_external", to_vector(state_.previous_external));
  w.array(prefix + ".previous_damping", to_vector(state_.previous_damping));
  w.value(prefix + ".time", state_.time);
  w.value(prefix + ".external_work", state_.external_work);
  w.value(prefix + ".dissipated", state_.dissipated);
}

void Beam::load_state(StateReader& r, const std::string& prefix) {
  const Eigen::Index n = state_.q.size();
  state_.q = from_vector(r.array<double>(prefix + ".q"), n, prefix + ".q");
  state_.v = from_vector(r.array<double>(prefix + ".v"), n, prefix + ".v");
  state_.a = from_vector(r.array<double>(prefix + ".a"), n, prefix + ".a");
  state_.acceleration_ready = r.value<std::uint8_t>(prefix + ".acceleration_ready") != 0;
  state_.previous_force_balance = from_vector(r.array<double>(prefix + ".previous_force_balance"), n, prefix);
  state_.previous_external = from_vector(r.array<double>(prefix + ".previous_external"), n, prefix);
  state_.previous_damping = from_vector(r.array<double>(prefix + ".previous_damping"), n, prefix);
  state_.time = r.value<double>(prefix + ".time");
  state_.external_work = r.value<double>(prefix + ".external_work");
  state_.dissipated = r.value<double>(prefix + ".dissipated");
}

BeamModes Beam::modes(int count) const {
  Assembly assembly;
  const BeamLoads none;
  assemble(state_.q, Eigen::VectorXd::Zero(state_.q.size()), none, 0.0, false, {1.0, 0.0, 0.0}, assembly);
  Eigen::SparseMatrix<double> k_sparse(free_dofs_, free_dofs_);
  k_sparse.setFromTriplets(assembly.triplets.begin(), assembly.triplets.end());
  const Eigen::MatrixXd k_dense = Eigen::MatrixXd(k_sparse);
  const Eigen::MatrixXd stiffness = 0.5 * (k_dense + k_dense.transpose());
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(free_dofs_, free_dofs_);
  for (int k = 0; k < mass_.outerSize(); ++k) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(mass_, k); it; ++it) {
      const int row = equation_[static_cast<std::size_t>(it.row())];
      const int col = equation_[static_cast<std::size_t>(it.col())];
      if (row >= 0 && col >= 0) mass(row, col) += it.value();
    }
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
  if (solver.info() != Eigen::Success) throw RunFailure("beam: generalised eigenvalue problem failed");
  BeamModes result;
  const int available = std::min(count, free_dofs_);
  for (int m = 0; m < available; ++m) {
    const double lambda = solver.eigenvalues()[m];
    // A negative eigenvalue means the current state is unstable (buckled); reported as -sqrt(|lambda|).
    result.omega.push_back(lambda >= 0.0 ? std::sqrt(lambda) : -std::sqrt(-lambda));
    result.shapes.push_back(expand(solver.eigenvectors().col(m)));
  }
  return result;
}

std::vector<double> Beam::natural_frequencies(int count) const { return modes(count).omega; }

double Beam::kinetic_energy() const { return 0.5 * state_.v.dot(mass_ * state_.v); }

double Beam::strain_energy() const {
  double energy = 0.0;
  for (int e = 0; e < element_count(); ++e) {
    const BeamElementGeometry& geometry = elements_[static_cast<std::size_t>(e)];
    const BeamElementKinematics kin = beam_element_kinematics(geometry, element_state(state_.q, e));
    energy += beam_element_response(geometry, section_, kin).strain_energy;
  }
  return energy;
}

}  // namespace sloshsph
