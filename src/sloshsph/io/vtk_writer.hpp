#pragma once
// ParaView output without the VTK library: VTK XML UnstructuredGrid (.vtu) files with
// appended raw binary data, one per snapshot, and a .pvd collection indexing them by
// time. A 200-line writer of a documented format instead of the ~1 GB libvtk9-dev
// dependency tree (docs/physics.md, "Output").
#include <string>
#include <vector>

#include "sloshsph/core/particles.hpp"

namespace sloshsph {

// Writes the particles (fluid, and walls if include_walls) with point data velocity,
// pressure, density, kind (0 fluid, 1 wall) and id. Atomic (temporary file + rename). 2D
// particles lie in the plane z = 0 (x along the length, y up); 3D ones keep their (x, y, z).
template <int D>
void write_vtu(const std::string& path, const BasicParticles<D>& particles, bool include_walls);
extern template void write_vtu<2>(const std::string&, const BasicParticles<2>&, bool);
extern template void write_vtu<3>(const std::string&, const BasicParticles<3>&, bool);

// The .pvd index: rewritten (atomically) after each added snapshot.
class PvdIndex {
 public:
  explicit PvdIndex(std::string path) : path_(std::move(path)) {}
  void add(double time, const std::string& relative_file);
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }
  // A resumed run: the entries up to its checkpoint (the index is rewritten at the next add).
  void restore(std::vector<std::pair<double, std::string>> entries) { entries_ = std::move(entries); }

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace sloshsph
