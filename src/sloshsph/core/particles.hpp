#pragma once
// Structure-of-arrays particle store, for 2 or 3 dimensions (Particles is the 2D one, Particles3
// the 3D one; the definitions are instantiated for both in particles.cpp). Fluid particles occupy [0, n_fluid),
// wall (dummy) particles [n_fluid, size()). Tank walls never move in the tank frame; the walls
// of an elastic plate (run/plate_coupling) move with it and carry their motion in wall_motion_*.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

enum class ParticleKind : std::uint8_t { fluid = 0, wall = 1 };

template <int D>
struct BasicParticles {
  std::vector<Vec<D>> position;  // m, tank frame
  std::vector<Vec<D>> velocity;  // m/s, tank frame (walls: the free-slip image velocity)
  std::vector<double> pressure;  // Pa (walls: as seen from the side their normal points to)
  std::vector<double> pressure_back;  // Pa, walls: as seen from behind (thin walls: screen slats)
  std::vector<double> density;   // kg/m^3, kernel-summed (diagnostic for fluid)
  std::vector<Vec<D>> normal;    // inward unit wall normal (walls only; zero for fluid)
  std::vector<std::int32_t> id;  // stable identity across re-sorting
  // Motion of the wall material in the tank frame, one entry per wall particle (index w - n_fluid),
  // or both empty when every wall is fixed (the common case: nothing to read). Set by the driver
  // for moving walls (elastic plates); the wall models use it for the image velocity and the
  // wall pressure (physics/walls.hpp).
  std::vector<Vec<D>> wall_motion_velocity;      // m/s
  std::vector<Vec<D>> wall_motion_acceleration;  // m/s^2
  std::size_t n_fluid = 0;
  double mass = 0.0;             // kg per metre of width (2D) or kg (3D), the same for every particle
  double volume = 0.0;           // dp^2 (m^2 per metre of width) or dp^3 (m^3)

  std::size_t size() const { return position.size(); }
  std::size_t n_wall() const { return size() - n_fluid; }
  bool is_fluid(std::size_t i) const { return i < n_fluid; }
  bool has_moving_walls() const { return !wall_motion_velocity.empty(); }
  // Velocity and acceleration of wall particle w (index into the store, w >= n_fluid).
  Vec<D> wall_velocity(std::size_t w) const {
    return has_moving_walls() ? wall_motion_velocity[w - n_fluid] : Vec<D>{};
  }
  Vec<D> wall_acceleration(std::size_t w) const {
    return has_moving_walls() ? wall_motion_acceleration[w - n_fluid] : Vec<D>{};
  }

  void resize(std::size_t n) {
    position.resize(n);
    velocity.resize(n);
    pressure.resize(n);
    pressure_back.resize(n);
    density.resize(n);
    normal.resize(n);
    id.resize(n);
  }

  // Reorders the fluid range by `order` (new index k holds old particle order[k]).
  void permute_fluid(const std::vector<std::uint32_t>& order);

  // Removes the fluid particles flagged in `remove` (size n_fluid), keeping order.
  void remove_fluid(const std::vector<std::uint8_t>& remove);
};

using Particles = BasicParticles<2>;
using Particles3 = BasicParticles<3>;

}  // namespace sloshsph
