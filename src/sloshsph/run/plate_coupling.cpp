#include "sloshsph/run/plate_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/prism_tank.hpp"

namespace sloshsph {
namespace {

BeamSupport beam_support(PlateSupport s) {
  return s == PlateSupport::clamped ? BeamSupport::kClamped
         : s == PlateSupport::pinned ? BeamSupport::kPinned
                                     : BeamSupport::kFree;
}

// A vector of the store in the plate's plane (the section: (x, y) in 2D, (x, z) in 3D), and back
// (at breadth y in 3D: geometry/prism_tank.hpp's in_section and at_breadth).
template <int D>
Vec2 in_plate_plane(const Vec<D>& v) {
  if constexpr (D == 2) return v;
  else return in_section(v);
}
template <int D>
Vec<D> from_plate_plane(Vec2 v, double y) {
  if constexpr (D == 2) return v;
  else return at_breadth(v, y);
}

}  // namespace

BeamSpec plate_beam_spec(const PlateSpec& spec) {
  BeamSpec b;
  b.start = spec.from;
  b.end = spec.to;
  b.elements = spec.elements;
  b.thickness = spec.thickness;
  b.width = 1.0;  // loads, masses and energies per metre of out-of-plane width, as the fluid's
  b.youngs_modulus = spec.youngs_modulus;
  b.poisson_ratio = spec.poisson_ratio;
  b.density = spec.density;
  b.rayleigh_mass = spec.rayleigh_mass;
  b.rayleigh_stiffness = spec.rayleigh_stiffness;
  b.start_support = beam_support(spec.from_support);
  b.end_support = beam_support(spec.to_support);
  // HHT-alpha rather than the energy-conserving rule: the particle loads are noisy and excite the
  // plate's highest modes (omega dt >> 1 at the fluid step), which the conserving rule keeps for
  // ever and feeds back as wall accelerations (measured: the hydrostatic plate diverged at 1.3 s).
  // alpha < 0 damps them and leaves the resolved modes second-order accurate.
  b.integrator = BeamIntegrator::kHHT;
  b.hht_alpha = spec.hht_alpha;
  b.gravity = {};  // the tank-frame body force (gravity included) comes with each step's loads
  return b;
}

template <int D>
BasicPlateCoupling<D>::BasicPlateCoupling(const PlateLayout& layout, std::size_t first_wall, std::vector<double> planes,
                                          double dp)
    : layout_(layout), first_wall_(first_wall), planes_(std::move(planes)), dp_(dp), beam_(plate_beam_spec(layout.spec)) {
  if (D == 3 && planes_.empty()) throw InputError("plates", "plates", "a 3D plate needs the planes across the breadth");
  const std::size_t n = layout_.walls.size();
  points_.reserve(n);
  for (const WallSample& w : layout_.walls) points_.push_back(beam_.material_point(w.position));
  force_.assign(n, Vec2{});
  velocity_.assign(n, Vec2{});
  acceleration_.assign(n, Vec2{});
  contact_force_.assign(static_cast<std::size_t>(beam_.node_count()), Vec2{});
}

template <int D>
void BasicPlateCoupling<D>::place(Particles& p) const {
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const Vec2 position = beam_.position(points_[k]);
    const Vec2 normal = rotated(layout_.walls[k].normal, beam_.rotation(points_[k]));
    for (std::size_t m = 0; m < plane_count(); ++m) {
      const double y = D == 2 ? 0.0 : planes_[m];
      const std::size_t w = store_index(p, k, m);
      p.position[w] = from_plate_plane<D>(position, y);
      p.normal[w] = from_plate_plane<D>(normal, 0.0);
      p.wall_motion_velocity[w - p.n_fluid] = from_plate_plane<D>(velocity_[k], 0.0);
      p.wall_motion_acceleration[w - p.n_fluid] = from_plate_plane<D>(acceleration_[k], 0.0);
    }
  }
}

// The face pressure is the wall pressure carried from the particle to its face along the face's
// normal, p_face = p_w + rho0 (g - a_w) . n d (the hydrostatic part of Adami's extrapolation,
// eq. 27), kept >= 0 as the wall pressure is; a face with no fluid on it (wall pressure 0: nothing
// to extrapolate from) carries nothing.
template <int D>
Vec2 BasicPlateCoupling<D>::fluid_force(const Particles& p, const FrameForce& frame, double rho0) {
  Vec2 total;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    force_[k] = {};
    const double angle = beam_.rotation(points_[k]);
    for (std::size_t m = 0; m < plane_count(); ++m) {
      const std::size_t w = store_index(p, k, m);
      const double p_w = p.pressure[w];
      if (p_w <= 0.0) continue;
      const Vec2 g = in_plate_plane<D>(frame.at(p.position[w], Vec<D>{})) - acceleration_[k];
      for (const PlateFace* face : {&layout_.side_face[k], &layout_.end_face[k]}) {
        if (face->length <= 0.0) continue;
        const Vec2 n = rotated(face->normal, angle);
        const double p_face = std::max(0.0, p_w + rho0 * dot(g, n) * face->distance);
        force_[k] += (-p_face * face->length) * n;
      }
    }
    force_[k] = force_[k] / static_cast<double>(plane_count());  // per metre: the planes' mean (2D: / 1, exact)
    total += force_[k];
  }
  last_force_ = total;
  return total;
}

template <int D>
void BasicPlateCoupling<D>::advance(Particles& p, double dt, const FrameForce& frame) {
  BeamLoads loads = beam_.zero_loads();
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (force_[k].x != 0.0 || force_[k].y != 0.0) beam_.add_force(points_[k], force_[k], loads);
  // The contact impulses of the last step, as forces.
  if (loads.nodal_forces.empty()) loads.nodal_forces.assign(contact_force_.size(), Vec2{});
  for (std::size_t n = 0; n < contact_force_.size(); ++n) loads.nodal_forces[n] += contact_force_[n];
  std::fill(contact_force_.begin(), contact_force_.end(), Vec2{});
  // The body force of the tank frame (gravity, the base's acceleration, pitch terms) at the
  // middle of the undeformed plate: uniform over the plate.
  // In 3D at the middle of the breadth too.
  const double mid_y = D == 2 ? 0.0 : 0.5 * (planes_.front() + planes_.back());
  loads.body_acceleration =
      in_plate_plane<D>(frame.at(from_plate_plane<D>(0.5 * (layout_.spec.from + layout_.spec.to), mid_y), Vec<D>{}));
  beam_.step(dt, loads);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const Vec2 v = beam_.velocity(points_[k]);
    acceleration_[k] = (v - velocity_[k]) / dt;
    velocity_[k] = v;
  }
  max_abs_tip_dx_ = std::max(max_abs_tip_dx_, std::abs(tip_displacement().x));
  place(p);
}

template <int D>
void BasicPlateCoupling<D>::damp(Particles& p, double factor) {
  beam_.scale_velocities(factor);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    velocity_[k] = beam_.velocity(points_[k]);
    acceleration_[k] = {};
  }
  place(p);
}

template <int D>
void BasicPlateCoupling<D>::restart() {
  max_abs_tip_dx_ = std::abs(tip_displacement().x);
  crossings_ = 0;
  contacts_ = 0;
  first_crossing_ = {};
}

template <int D>
Vec2 BasicPlateCoupling<D>::displacement_at(double fraction) const {
  const std::vector<Vec2> u = beam_.node_displacements();
  const double x = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(u.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(x), u.size() - 2);
  const double xi = x - static_cast<double>(k);
  return (1.0 - xi) * u[k] + xi * u[k + 1];
}

template <int D>
typename BasicPlateCoupling<D>::CentreLineOffset BasicPlateCoupling<D>::locate(Vec2 r, const std::vector<Vec2>& nodes) const {
  CentreLineOffset best;
  double best_d2 = std::numeric_limits<double>::infinity(), s0 = 0.0;
  const std::size_t last = nodes.size() - 2;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const Vec2 a = nodes[k], e = nodes[k + 1] - a;
    const double len2 = norm2(e), len = std::sqrt(len2);
    const double t_raw = dot(r - a, e) / len2;
    const double t = std::clamp(t_raw, 0.0, 1.0);
    const Vec2 foot = a + t * e;
    const double d2 = norm2(r - foot);
    if (d2 < best_d2) {
      best_d2 = d2;
      best.offset = cross(e, r - a) / len;  // + to the left of the centre line: the `across` side
      best.s = s0 + t * len;
      best.in_span = !((k == 0 && t_raw <= 0.0) || (k == last && t_raw >= 1.0));
      best.segment = k;
      best.t = t;
    }
    s0 += len;
  }
  return best;
}

template <int D>
template <class F>
void BasicPlateCoupling<D>::for_each_near_fluid(const Particles& p, const NeighbourList& nl, F&& f) {
  if (stamp_.size() < p.size()) stamp_.resize(p.size(), 0);
  ++calls_;
  const std::size_t base = p.n_fluid + first_wall_;
  for (std::size_t k = 0; k < count(); ++k)
    for (auto it = nl.begin(base + k); it != nl.end(base + k); ++it) {
      const std::uint32_t i = *it;
      if (i >= p.n_fluid || stamp_[i] == calls_) continue;
      stamp_[i] = calls_;
      f(i);
    }
}

template <int D>
std::size_t BasicPlateCoupling<D>::keep_fluid_out(Particles& p, const NeighbourList& nl, double dp, double dt,
                                                  double time) {
  const std::vector<Vec2> nodes = beam_.node_positions();
  const std::vector<Vec2> node_velocity = beam_.node_velocities();
  const double half = 0.5 * layout_.spec.thickness;
  const double contact = half + 0.25 * dp;
  const double band = nl.search_radius();
  struct Near {
    std::int32_t id;
    std::int8_t side;
    Vec2 position;
    double s;
  };
  std::vector<Near> now;
  std::size_t corrected = 0;
  for_each_near_fluid(p, nl, [&](std::size_t i) {
    const CentreLineOffset c = locate(in_plate_plane<D>(p.position[i]), nodes);
    if (!c.in_span) return;
    double offset = c.offset;
    if (std::abs(offset) < contact && contact_correction(p, i, c, nodes, node_velocity, half, contact, dt, offset))
      ++corrected;
    if (std::abs(offset) <= band)
      now.push_back({p.id[i], static_cast<std::int8_t>(offset >= 0.0 ? 1 : -1), in_plate_plane<D>(p.position[i]), c.s});
  });
  contacts_ += corrected;

  // Crossings: a particle seen on the other side than last step.
  std::int32_t max_id = 0;
  for (const Near& n : now) max_id = std::max(max_id, n.id);
  if (side_.size() <= static_cast<std::size_t>(max_id)) side_.resize(static_cast<std::size_t>(max_id) + 1, 0);
  for (const Near& n : now) {
    const std::int8_t before = side_[static_cast<std::size_t>(n.id)];
    if (before != 0 && before != n.side) {
      if (crossings_ == 0) first_crossing_ = {time, n.id, n.position, n.s};
      ++crossings_;
    }
  }
  for (std::int32_t id : near_ids_) side_[static_cast<std::size_t>(id)] = 0;  // left the band: forgotten
  near_ids_.clear();
  for (const Near& n : now) {
    side_[static_cast<std::size_t>(n.id)] = n.side;
    near_ids_.push_back(n.id);
  }
  return corrected;
}

// One particle of keep_fluid_out() closer than `contact` to the centre line (c: where it is).
// Returns true if it was corrected; `offset` is then its new signed offset.
template <int D>
bool BasicPlateCoupling<D>::contact_correction(Particles& p, std::size_t i, const CentreLineOffset& c,
                                               const std::vector<Vec2>& nodes, const std::vector<Vec2>& node_velocity,
                                               double half, double contact, double dt, double& offset) {
  const auto id = static_cast<std::size_t>(p.id[i]);
  const int known = id < side_.size() ? side_[id] : 0;
  const double side = known != 0 ? known : (c.offset >= 0.0 ? 1.0 : -1.0);
  const std::size_t k = c.segment;
  const Vec2 a = nodes[k], e = normalized(nodes[k + 1] - a);
  const Vec2 n = side * perp(e);  // out of the plate, towards the particle's side
  const Vec2 v_plate = (1.0 - c.t) * node_velocity[k] + c.t * node_velocity[k + 1];
  const double approach = dot(in_plate_plane<D>(p.velocity[i]) - v_plate, n);
  const bool inside = side * c.offset < half;
  if (approach >= 0.0 && !inside) return false;  // close, but leaving: nothing to do
  if (approach < 0.0) {  // stop the approach (slip: the tangential velocity is kept)
    p.velocity[i] -= from_plate_plane<D>(approach * n, 0.0);
    // The momentum the fluid lost into the plate, per metre of breadth (2D: the width is 1 m, and
    // the particle's mass is already per metre).
    const Vec2 impulse_on_plate = ((p.mass * approach) * n) / width();
    contact_force_[k] += ((1.0 - c.t) / dt) * impulse_on_plate;
    contact_force_[k + 1] += (c.t / dt) * impulse_on_plate;
  }
  // A particle already inside the plate goes back out of its face, halfway to the contact
  // distance. (Putting every close particle onto the contact surface squeezed pairs of them
  // together: non-finite at 0.40 s of the pulse case.)
  if (inside) {
    const double target = half + 0.5 * (contact - half);
    p.position[i] += from_plate_plane<D>((target - side * c.offset) * n, 0.0);
    offset = side * target;
  }
  return true;
}

template <int D>
std::size_t BasicPlateCoupling<D>::fluid_inside(const Particles& p, const NeighbourList& nl) {
  const std::vector<Vec2> nodes = beam_.node_positions();
  const double half = 0.5 * layout_.spec.thickness;
  std::size_t inside = 0;
  for_each_near_fluid(p, nl, [&](std::size_t i) {
    const CentreLineOffset c = locate(in_plate_plane<D>(p.position[i]), nodes);
    if (c.in_span && std::abs(c.offset) < half) ++inside;
  });
  return inside;
}

template <int D>
void BasicPlateCoupling<D>::save_state(StateWriter& w, const std::string& prefix) const {
  beam_.save_state(w, prefix + ".beam");
  w.array(prefix + ".force", force_);
  w.array(prefix + ".velocity", velocity_);
  w.array(prefix + ".acceleration", acceleration_);
  w.value(prefix + ".last_force", last_force_);
  w.value(prefix + ".max_abs_tip_dx", max_abs_tip_dx_);
  w.array(prefix + ".side", side_);
  w.array(prefix + ".near_ids", near_ids_);
  w.value(prefix + ".crossings", static_cast<std::uint64_t>(crossings_));
  w.value(prefix + ".contacts", static_cast<std::uint64_t>(contacts_));
  w.array(prefix + ".contact_force", contact_force_);
  w.value(prefix + ".first_crossing", first_crossing_);
}

template <int D>
void BasicPlateCoupling<D>::load_state(StateReader& r, const std::string& prefix) {
  beam_.load_state(r, prefix + ".beam");
  force_ = r.array<Vec2>(prefix + ".force");
  velocity_ = r.array<Vec2>(prefix + ".velocity");
  acceleration_ = r.array<Vec2>(prefix + ".acceleration");
  if (force_.size() != points_.size() || velocity_.size() != points_.size() || acceleration_.size() != points_.size())
    throw InputError("checkpoint", prefix, "the plate in the checkpoint has another particle count than the case's");
  last_force_ = r.value<Vec2>(prefix + ".last_force");
  max_abs_tip_dx_ = r.value<double>(prefix + ".max_abs_tip_dx");
  side_ = r.array<std::int8_t>(prefix + ".side");
  near_ids_ = r.array<std::int32_t>(prefix + ".near_ids");
  crossings_ = static_cast<std::size_t>(r.value<std::uint64_t>(prefix + ".crossings"));
  contacts_ = static_cast<std::size_t>(r.value<std::uint64_t>(prefix + ".contacts"));
  contact_force_ = r.array<Vec2>(prefix + ".contact_force");
  first_crossing_ = r.value<PlateCrossing>(prefix + ".first_crossing");
}

template class BasicPlateCoupling<2>;
template class BasicPlateCoupling<3>;

}  // namespace sloshsph
