#pragma once
// Two-way coupling of an elastic plate ([[plates]]) with the fluid (Dincer 2019, sec. 2.3; the
// choice of method is argued in docs/physics.md, "Elastic plates").
//
// The plate is a geometrically exact beam (structure/beam.hpp) in the tank frame. Its wall
// particles (geometry/plates.hpp) are material points of the beam: each step they take the
// beam's position, section rotation (for their normal), velocity and acceleration, and the
// fluid sees them as moving Adami walls (physics/walls.hpp). The fluid acts back through the
// pressure on the plate's faces: each face particle w carries the load
//   f_w = -p_face n_w ds_w,   p_face = p_w + rho0 (g - a_w) . n_w d_w
// (the wall pressure extrapolated from the particle to its face, d_w the distance, ds_w the face
// length it stands for, per metre of width), added to the beam's nodes work-consistently. The walls
// are free-slip, so the fluid exerts no shear on them. Staggered in time: the fluid step sees the
// plate at t, the plate then advances to t + dt under the loads of that step (HHT-alpha, which
// damps the plate's unresolved high modes). Stable with the weakly compressible scheme; with ISPH
// a plate much lighter than the fluid it moves is noisy (the added-mass effect of staggered
// couplings, measured in docs/physics.md).
//
// In 3D (issue 31) a plate spans the breadth of a box or prism: the same beam, per metre of
// breadth, bends in the plane (x, z) of the section (cylindrical bending), its section's particles
// standing on each lattice plane across the breadth (`planes`: their y). Its loads are the mean over
// the planes of each section particle's face load (per metre of breadth, as in 2D); the fluid's
// load along y is taken by the plate's supports and does not enter the beam.
#include <cstddef>
#include <string>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/state_io.hpp"
#include "sloshsph/geometry/plates.hpp"
#include "sloshsph/physics/frame.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "sloshsph/structure/beam.hpp"

namespace sloshsph {

// The first fluid particle seen to pass through a plate (PlateCoupling::keep_fluid_out).
struct PlateCrossing {
  double time = -1.0;     // s (-1: none)
  std::int32_t id = -1;   // particle id
  Vec2 position;          // m, where it was seen on the other side (in 3D its (x, z))
  double arc_length = 0;  // m from the plate's `from` end
};

// The beam of a plate (SI, per metre of out-of-plane width; gravity enters as the frame force).
BeamSpec plate_beam_spec(const PlateSpec& spec);

template <int D>
class BasicPlateCoupling {
 public:
  using Particles = BasicParticles<D>;
  using FrameForce = BasicFrameForce<D>;
  using NeighbourList = BasicNeighbourList<D>;

  // `first_wall` is the index of the plate's first particle among the wall particles (its store
  // index less n_fluid: it stays valid when leaked fluid particles are removed). 3D: `planes` are
  // the y of the lattice planes across the breadth, `dp` their spacing; section particle k stands
  // on plane m as particle first_wall + k * planes.size() + m (geometry/prism_tank.hpp's
  // on_planes_across order).
  BasicPlateCoupling(const PlateLayout& layout, std::size_t first_wall, std::vector<double> planes = {}, double dp = 0.0);

  const PlateSpec& spec() const { return layout_.spec; }
  const Beam& beam() const { return beam_; }
  std::size_t first_wall() const { return first_wall_; }
  std::size_t count() const { return points_.size() * plane_count(); }  // wall particles
  // The breadth the beam's per-metre quantities are multiplied by for whole ones: 1 m in 2D (the
  // 2D outputs are per metre), planes x dp in 3D.
  double width() const { return D == 2 ? 1.0 : static_cast<double>(planes_.size()) * dp_; }

  // Writes the plate's configuration into its wall particles: position, normal, and the wall
  // motion (velocity, acceleration) of the store (which must be sized for the walls).
  void place(Particles& p) const;

  // The fluid's force on each face particle from the wall pressures now in the store (N/m; in 3D
  // the mean over the planes), and their sum (the force of the fluid on the plate, per metre).
  Vec2 fluid_force(const Particles& p, const FrameForce& frame, double rho0);

  // One plate step of dt under the fluid loads of fluid_force() and the frame's body force
  // (at the plate's root), then place(). Throws RunFailure if the beam's Newton iteration fails.
  void advance(Particles& p, double dt, const FrameForce& frame);

  // Damped settling before t = 0 (Simulation::settle): scales the plate's velocities by `factor`
  // and moves its particles accordingly. restart() then zeroes the counters kept from t = 0.
  void damp(Particles& p, double factor);
  void restart();

  // Once per step, over the fluid particles listed by the neighbour rows of the plate's particles:
  //  * contact (Dincer 2019, sec. 2.3: the fluid may not invade the structure): a fluid particle
  //    closer to the deformed centre line than t/2 + dp/4, within the span, on the side it was last
  //    seen on, that moves towards the plate (relative to it) loses that normal velocity (slip: the
  //    tangential part is kept); one already inside the plate is moved back out of its face. The
  //    momentum taken from the fluid acts on the plate in its next step;
  //  * crossings: a particle within the search radius of the span that is now on the other side
  //    than last step passed through the plate; the count since the start and the first are kept.
  // Returns the number of particles the contact corrected this step.
  std::size_t keep_fluid_out(Particles& p, const NeighbourList& nl, double dp, double dt, double time);
  std::size_t contacts() const { return contacts_; }  // since t = 0
  std::size_t crossings() const { return crossings_; }
  const PlateCrossing& first_crossing() const { return first_crossing_; }
  // Fluid particles now inside the deformed plate (closer than t/2 to its centre line, within its span).
  std::size_t fluid_inside(const Particles& p, const NeighbourList& nl);

  Vec2 last_force() const { return last_force_; }                 // N/m, fluid on plate, last step
  Vec2 displacement_at(double fraction) const;                    // m, centre line at s = fraction L (3D: x, z)
  Vec2 tip_displacement() const { return displacement_at(1.0); }  // the `to` end
  double strain_energy() const { return beam_.strain_energy(); }
  double kinetic_energy() const { return beam_.kinetic_energy(); }
  double max_abs_tip_dx() const { return max_abs_tip_dx_; }

  void save_state(StateWriter& w, const std::string& prefix) const;
  void load_state(StateReader& r, const std::string& prefix);

 private:
  // Position of a fluid point relative to the deformed centre line: signed offset across it
  // (+ towards the side of the initial `across` normal) and the arc length of its foot.
  struct CentreLineOffset {
    double offset = 0.0;
    double s = 0.0;
    bool in_span = false;  // the foot lies on the centre line, not at (or beyond) an end
    std::size_t segment = 0;  // element of the foot, and its position along it in [0, 1]
    double t = 0.0;
  };
  CentreLineOffset locate(Vec2 r, const std::vector<Vec2>& nodes) const;
  bool contact_correction(Particles& p, std::size_t i, const CentreLineOffset& c, const std::vector<Vec2>& nodes,
                          const std::vector<Vec2>& node_velocity, double half, double contact, double dt,
                          double& offset);
  // Calls f(i) once for each fluid particle listed by the neighbour rows of the plate's particles.
  template <class F> void for_each_near_fluid(const Particles& p, const NeighbourList& nl, F&& f);
  std::size_t plane_count() const { return D == 2 ? 1 : planes_.size(); }
  // Store index of section particle k on plane m.
  std::size_t store_index(const Particles& p, std::size_t k, std::size_t m) const {
    return p.n_fluid + first_wall_ + k * plane_count() + m;
  }

  PlateLayout layout_;
  std::size_t first_wall_;
  std::vector<double> planes_;  // 3D: y of each plane across the breadth
  double dp_ = 0.0;
  Beam beam_;
  std::vector<BeamMaterialPoint> points_;
  std::vector<Vec2> force_;         // per section particle, N/m
  std::vector<Vec2> velocity_;      // per section particle, m/s (tank frame)
  std::vector<Vec2> acceleration_;  // per section particle, m/s^2
  Vec2 last_force_;
  double max_abs_tip_dx_ = 0.0;
  // Crossing watch: the side (+1/-1, 0 unknown) of each fluid particle id near the plate.
  std::vector<std::int8_t> side_;
  std::vector<std::int32_t> near_ids_;
  std::vector<std::uint32_t> stamp_;  // per store index: last call that listed it (candidate dedup)
  std::uint32_t calls_ = 0;
  std::size_t crossings_ = 0;
  std::size_t contacts_ = 0;
  std::vector<Vec2> contact_force_;  // per beam node, N/m: for the next step
  PlateCrossing first_crossing_;
};

using PlateCoupling = BasicPlateCoupling<2>;
using PlateCoupling3 = BasicPlateCoupling<3>;
extern template class BasicPlateCoupling<2>;
extern template class BasicPlateCoupling<3>;

}  // namespace sloshsph
