#include "sloshsph/physics/porous.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/screens.hpp"
#include "sloshsph/sph/kernel.hpp"

namespace sloshsph {

// ---------------------------------------------------------------------------------------
// Closed forms.

double kozeny_carman_permeability(double porosity, double diameter) {
  // Thesis eq. 2.22, phi_s = 1.
  const double n = porosity;
  return n * n * n * diameter * diameter / (150.0 * (1.0 - n) * (1.0 - n));
}

// The inertial (Forchheimer) coefficient of thesis eq. 2.21 per rho |u| u, 1/m:
// 1.75 / (sqrt(150) sqrt(K) n^1.5).
double ergun_inertial_factor(double permeability, double porosity) {
  return 1.75 / (std::sqrt(150.0) * std::sqrt(permeability) * std::pow(porosity, 1.5));
}

double ergun_inertial_loss_coefficient(double permeability, double porosity, double thickness) {
  // Eq. 2.21's inertial loss times the thickness L = t_sc (eq. 2.24), per 1/2 rho u^2.
  return 2.0 * thickness * ergun_inertial_factor(permeability, porosity);
}

double slat_screen_loss_coefficient(double solidity) {
  // Baines & Peterson (1951) as used by Tait et al. (2005) for slat screens.
  const double s = solidity;
  const double contraction = 0.405 * std::exp(-std::numbers::pi * s) + 0.595;
  const double a = 1.0 / (contraction * (1.0 - s)) - 1.0;
  return a * a;
}

Vec2 morison_pressure_drop(double rho, double loss_coefficient, Vec2 velocity) {
  // Drag term of Morison's equation per unit area (McNamara et al. 2021).
  return (0.5 * rho * loss_coefficient * norm(velocity)) * velocity;
}

// ---------------------------------------------------------------------------------------
// Screen particles.

namespace {

void check_non_negative(double v, const std::string& where, const std::string& key) {
  if (!(v >= 0.0)) throw InputError(where, key, "must not be negative");
}

}  // namespace

ScreenParticles make_screen_particles(const std::vector<ScreenSpec>& specs, double dp, double h,
                                      const TankGeometry& tank, const std::string& where) {
  if (!(dp > 0.0)) throw InputError(where, "particles.dp", "must be positive");
  ScreenParticles out;
  for (std::size_t index = 0; index < specs.size(); ++index) {
    const ScreenSpec& spec = specs[index];
    const std::string key = "screens." + std::to_string(index);
    check_non_negative(spec.spacing, where, key + ".spacing");
    check_non_negative(spec.interaction_radius, where, key + ".interaction_radius");
    check_non_negative(spec.loss_coefficient, where, key + ".loss_coefficient");

    ScreenElement e;
    e.name = spec.name;
    e.model = spec.model;
    e.solidity = element_solidity(spec, where, key);
    e.porosity = 1.0 - e.solidity;
    e.thickness = spec.thickness;
    e.nominal_spacing = spec.spacing > 0.0 ? spec.spacing : dp;
    e.smoothing_length = spec.interaction_radius > 0.0 ? spec.interaction_radius : 2.5 * h;  // thesis 2.5.3
    const ClippedLine line = clip_to_section(tank, spec.from, spec.to, where, key);
    e.from = line.from;
    e.to = line.to;
    e.length = line.length;
    e.normal = perp(line.direction());
    e.first = out.position.size();

    if (spec.model == ScreenModel::explicit_slats) {  // rigid walls, geometry/screens
      out.elements.push_back(e);
      continue;
    }
    const bool needs_solidity = spec.model == ScreenModel::ergun || spec.loss_coefficient == 0.0;
    if (needs_solidity && !(e.solidity > 0.0))
      throw InputError(where, key + ".solidity",
                       "the element needs a solidity S in (0, 1), or slat_height and slat_gap" +
                           std::string(spec.model == ScreenModel::morison ? ", or a loss_coefficient" : ""));
    if (spec.model == ScreenModel::ergun) {
      if (!(spec.thickness > 0.0)) throw InputError(where, key + ".thickness", "must be positive");
      e.permeability = kozeny_carman_permeability(e.porosity, e.nominal_spacing);  // D_c = dp_sc, thesis 2.5.2
    } else {
      e.loss_coefficient =
          spec.loss_coefficient > 0.0 ? spec.loss_coefficient : slat_screen_loss_coefficient(e.solidity);
    }
    // sum_f V W_jf of a full fluid lattice at a node: a screen particle deep in undisturbed fluid.
    e.undisturbed_weight =
        times_particle_volume<2>(lattice_number_density(KernelType::wendland_c2, e.smoothing_length, dp, 2), dp);
    e.shepard_velocity = spec.shepard_velocity;

    // Equal spacing <= dp_sc; a length that is a whole number of dp_sc (to round-off) keeps dp_sc.
    const std::size_t n =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(e.length / e.nominal_spacing - 1e-9)));
    e.spacing = e.length / static_cast<double>(n);
    e.count = n;
    const Vec2 along = line.direction();
    for (std::size_t k = 0; k < n; ++k) {
      out.position.push_back(e.from + ((static_cast<double>(k) + 0.5) * e.spacing) * along);
      out.element.push_back(static_cast<std::uint32_t>(index));
    }
    out.elements.push_back(e);
  }
  return out;
}

namespace {

// The interval [from, to] along which a 3D element is repeated (extrude_screen_particles): y over
// the breadth, x over the length in the plane y = plane_y; in a cylinder the chord of that plane.
std::pair<double, double> extrusion_interval(const ScreenElement& e, double breadth, double length,
                                             double cylinder_radius) {
  if (cylinder_radius <= 0.0) return {0.0, e.plane_y ? length : breadth};
  const double R = cylinder_radius, plane = e.plane_y ? *e.plane_y : e.from.x;
  const double w = std::sqrt(std::max(0.0, R * R - (plane - R) * (plane - R)));
  return {R - w, R + w};
}

}  // namespace

BasicScreenParticles<3> extrude_screen_particles(const ScreenParticles& section, double breadth, double dp,
                                                 const std::vector<ScreenSpec>& specs, double length,
                                                 double cylinder_radius) {
  BasicScreenParticles<3> out;
  out.wet_fraction = section.wet_fraction;
  for (std::size_t index = 0; index < section.elements.size(); ++index) {
    ScreenElement e = section.elements[index];
    const std::size_t first = e.first, count = e.count;
    e.first = out.position.size();
    if (index < specs.size()) {
      e.plane_y = specs[index].plane_y;
      e.plan = specs[index].plan;
    }
    const Vec2 plan_direction = e.plan ? normalized(e.plan->second - e.plan->first) : Vec2{};
    e.normal3 = e.plan      ? Vec3{plan_direction.y, -plan_direction.x, 0.0}
                : e.plane_y ? Vec3{0.0, 1.0, 0.0}
                            : Vec3{e.normal.x, 0.0, e.normal.y};
    if (count > 0) {
      const auto [start, end] = e.plan ? std::pair<double, double>{0.0, norm(e.plan->second - e.plan->first)}
                                       : extrusion_interval(e, breadth, length, cylinder_radius);
      const double extent = end - start;  // along which the element is repeated
      e.count_across = std::max<std::size_t>(
          1, static_cast<std::size_t>(std::ceil(extent / e.nominal_spacing - 1e-9)));
      e.spacing_across = extent / static_cast<double>(e.count_across);
      e.undisturbed_weight =
          times_particle_volume<3>(lattice_number_density(KernelType::wendland_c2, e.smoothing_length, dp, 3), dp);
      for (std::size_t k = first; k < first + count; ++k)
        for (std::size_t m = 0; m < e.count_across; ++m) {
          const Vec2 q = section.position[k];
          const double along = start + (static_cast<double>(m) + 0.5) * e.spacing_across;
          if (e.plan) {  // `along` from the segment's first end
            const Vec2 at = e.plan->first + along * plan_direction;
            out.position.push_back({at.x, at.y, q.y});
          } else {
            out.position.push_back(e.plane_y ? Vec3{along, *e.plane_y, q.y} : Vec3{q.x, along, q.y});
          }
          out.element.push_back(static_cast<std::uint32_t>(index));
        }
      e.count = count * e.count_across;
    }
    out.elements.push_back(e);
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// The drag stage.

namespace {

// The element's unit normal in D dimensions (3D: the extruded element's, ScreenElement::normal3).
template <int D>
Vec<D> element_normal(const ScreenElement& e) {
  if constexpr (D == 2) return e.normal;
  else return e.normal3;
}

template <int D>
Vec<D> particle_drag(const ScreenElement& e, Vec<D> u, double rho, double mu) {
  // A_p: the spacing per unit width in 2D, the spacing times the spacing across in 3D.
  const double area = D == 2 ? e.spacing : e.spacing * e.spacing_across;
  if (e.model == ScreenModel::ergun)  // eq. 2.25: (dP/L)(U) * t_sc * A_p
    return ergun_pressure_gradient(mu, rho, e.permeability, e.porosity, u) * (e.thickness * area);
  // Morison: only the component through the screen; |u_n| u_n n does not depend on the sign of n.
  const Vec<D> normal = element_normal<D>(e);
  const double un = dot(u, normal);
  return (0.5 * rho * e.loss_coefficient * std::abs(un) * un * area) * normal;
}

}  // namespace

template <int D>
void screen_drag(const BasicScreenParticles<D>& screens, const BasicParticles<D>& p,
                 const std::vector<Vec<D>>& velocity, double rho, double mu, BasicScreenDragWork<D>& work,
                 std::vector<Vec<D>>& acceleration_out, std::vector<BasicScreenElementLoad<D>>& loads_out) {
  const std::size_t ns = screens.size(), nf = p.n_fluid, n = p.size();
  acceleration_out.assign(nf, Vec<D>{});
  loads_out.assign(screens.elements.size(), BasicScreenElementLoad<D>{});
  work.velocity.assign(ns, Vec<D>{});
  work.drag.assign(ns, Vec<D>{});
  work.fluid_weight.assign(ns, 0.0);
  work.wet_weight.assign(ns, 0.0);
  work.wet.assign(ns, 0);
  if (ns == 0 || nf == 0) return;

  const double radius = screens.max_support();
  const double V = p.volume;

  // (a) Per screen particle: kernel sums over the fluid (and walls, for the wet test), drag.
  work.particle_grid.build(p.position, 0, n, radius);
#pragma omp parallel for schedule(static)
  for (std::size_t j = 0; j < ns; ++j) {
    const ScreenElement& e = screens.elements[screens.element[j]];
    const WendlandC2 k(e.smoothing_length, D);
    const double support2 = k.support() * k.support();
    const Vec<D> rj = screens.position[j];
    Vec<D> u;
    double s = 0.0, fluid = 0.0, wall = 0.0;
    work.particle_grid.for_each_candidate(rj, k.support(), [&](std::uint32_t f) {
      const double r2 = norm2(rj - p.position[f]);
      if (r2 >= support2) return;
      const double w = k.w(std::sqrt(r2));
      if (f < nf) {
        u += (V * w) * velocity[f];  // eq. 2.26
        s += w;                      // eq. 2.27 denominator
        fluid += V * w;
      } else {
        wall += V * w;
      }
    });
    const double uncovered = e.undisturbed_weight - wall;
    const bool wet = fluid > 0.0 && fluid >= screens.wet_fraction * std::max(0.0, uncovered);
    if (e.shepard_velocity && fluid > 0.0) u = u / fluid;
    work.velocity[j] = u;
    work.fluid_weight[j] = s;
    work.wet_weight[j] = fluid;
    work.wet[j] = wet ? 1 : 0;
    work.drag[j] = wet ? particle_drag<D>(e, u, rho, mu) : Vec<D>{};
  }

  // (b) Per fluid particle in the interface zone: its share of each screen particle's drag.
  work.screen_grid.build(screens.position, 0, ns, radius);
  Vec<D> lo, hi;  // the screen particles' bounding box
  for (int c = 0; c < D; ++c) {
    component_ref(lo, c) = std::numeric_limits<double>::max();
    component_ref(hi, c) = std::numeric_limits<double>::lowest();
  }
  for (const Vec<D>& q : screens.position)
    for (int c = 0; c < D; ++c) {
      component_ref(lo, c) = std::min(component(lo, c), component(q, c));
      component_ref(hi, c) = std::max(component(hi, c), component(q, c));
    }
  const double inv_m = 1.0 / p.mass;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec<D> ri = p.position[i];
    bool outside = false;
    for (int c = 0; c < D; ++c)
      outside = outside || component(ri, c) < component(lo, c) - radius || component(ri, c) > component(hi, c) + radius;
    if (outside) continue;
    Vec<D> f;
    work.screen_grid.for_each_candidate(ri, radius, [&](std::uint32_t j) {
      if (!work.wet[j] || work.fluid_weight[j] <= 0.0) return;
      const ScreenElement& e = screens.elements[screens.element[j]];
      const WendlandC2 k(e.smoothing_length, D);
      // Same expression as in (a), so that exactly the pairs of S_j share F_d,j.
      const double r2 = norm2(screens.position[j] - ri);
      if (r2 >= k.support() * k.support()) return;
      f += work.drag[j] * (k.w(std::sqrt(r2)) / work.fluid_weight[j]);  // eq. 2.27
    });
    acceleration_out[i] = -inv_m * f;  // eq. 2.28
  }

  // Per element, in particle order (deterministic).
  for (std::size_t j = 0; j < ns; ++j) {
    BasicScreenElementLoad<D>& l = loads_out[screens.element[j]];
    l.force_on_fluid -= work.drag[j];
    if (work.wet[j]) {
      l.mean_velocity += work.velocity[j];
      ++l.wet_particles;
    }
  }
  for (std::size_t e = 0; e < loads_out.size(); ++e) {
    BasicScreenElementLoad<D>& l = loads_out[e];
    if (l.wet_particles > 0) l.mean_velocity = l.mean_velocity / static_cast<double>(l.wet_particles);
    l.wet_length = static_cast<double>(l.wet_particles) * screens.elements[e].spacing;
    if constexpr (D == 3) l.wet_length /= static_cast<double>(screens.elements[e].count_across);
  }
}

template void screen_drag<2>(const BasicScreenParticles<2>&, const BasicParticles<2>&, const std::vector<Vec2>&,
                             double, double, BasicScreenDragWork<2>&, std::vector<Vec2>&,
                             std::vector<BasicScreenElementLoad<2>>&);
template void screen_drag<3>(const BasicScreenParticles<3>&, const BasicParticles<3>&, const std::vector<Vec3>&,
                             double, double, BasicScreenDragWork<3>&, std::vector<Vec3>&,
                             std::vector<BasicScreenElementLoad<3>>&);

void screen_drag(const ScreenParticles& screens, const Particles& p, double rho, double mu,
                 std::vector<Vec2>& acceleration_out, std::vector<Vec2>& force_per_element_out) {
  ScreenDragWork work;
  std::vector<ScreenElementLoad> loads;
  screen_drag(screens, p, p.velocity, rho, mu, work, acceleration_out, loads);
  force_per_element_out.resize(loads.size());
  for (std::size_t e = 0; e < loads.size(); ++e) force_per_element_out[e] = loads[e].force_on_fluid;
}

}  // namespace sloshsph
