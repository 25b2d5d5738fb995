#pragma once
// Quadratic (6-node) triangle mesh of a still-water section, for the linear sloshing
// modal solver. Built here, without an external mesher: boundary nodes at equal arc
// length between corners, interior nodes on a (slightly jittered) triangular lattice,
// a Delaunay triangulation (Bowyer-Watson), boundary edges recovered by splitting, and
// mid-edge nodes placed on the true (finely discretised) boundary curve, so curved
// walls are represented to third order (isoparametric elements).
#include <array>
#include <vector>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

struct FluidMesh {
  std::vector<Vec2> nodes;  // the triangle vertices first, then the mid-edge nodes
  std::size_t vertex_count = 0;
  // Per element: vertices v0 v1 v2 (counter-clockwise), then the mid-edge nodes of
  // (v0, v1), (v1, v2), (v2, v0).
  std::vector<std::array<int, 6>> elements;
  // The free surface (the still level) as quadratic edges (end, middle, end), left to right.
  std::vector<std::array<int, 3>> surface_edges;
};

// Meshes the counter-clockwise polygon `section` whose closing edge (from the last
// point back to the first) is the free surface, with elements of size about `size`.
// Throws std::runtime_error if the triangulation fails (it should not for a simple polygon).
FluidMesh mesh_section(const std::vector<Vec2>& section, double size);

}  // namespace sloshsph
