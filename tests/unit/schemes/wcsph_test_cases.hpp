#pragma once
// Cases built in code for the WCSPH tests.
#include "sloshsph/core/case_spec.hpp"

namespace sloshsph::test {

// Rectangular tank 0.5 m x 0.4 m, water 0.25 m deep, dp = 0.01 m (h = 1.4 dp), at rest.
inline CaseSpec rest_tank_case(WallTreatment walls = WallTreatment::adami) {
  CaseSpec spec;
  spec.source = "<test>";
  spec.name = "wcsph_rest";
  spec.tank.shape = "rectangle";
  spec.tank.length = 0.5;
  spec.tank.height = 0.4;
  spec.fill.depth = 0.25;
  spec.particles.dp = 0.01;
  spec.scheme.type = "wcsph";
  spec.scheme.wcsph.walls = walls;
  return spec;
}

}  // namespace sloshsph::test
