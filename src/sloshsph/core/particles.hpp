#pragma once
// Structure-of-arrays particle store. Fluid particles occupy [0, n_fluid),
// wall (dummy) particles [n_fluid, size()). Walls never move in the tank frame.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

enum class ParticleKind : std::uint8_t { fluid = 0, wall = 1 };

struct Particles {
  std::vector<Vec2> position;  // m, tank frame
  std::vector<Vec2> velocity;  // m/s, tank frame (walls: the free-slip image velocity)
  std::vector<double> pressure;  // Pa (walls: as seen from the side their normal points to)
  std::vector<double> pressure_back;  // Pa, walls: as seen from behind (thin walls: screen slats)
  std::vector<double> density;   // kg/m^3, kernel-summed (diagnostic for fluid)
  std::vector<Vec2> normal;      // inward unit wall normal (walls only; zero for fluid)
  std::vector<std::int32_t> id;  // stable identity across re-sorting
  std::size_t n_fluid = 0;
  double mass = 0.0;             // kg per metre of width, the same for every particle
  double volume = 0.0;           // m^2, dp^2

  std::size_t size() const { return position.size(); }
  std::size_t n_wall() const { return size() - n_fluid; }
  bool is_fluid(std::size_t i) const { return i < n_fluid; }

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

}  // namespace sloshsph
