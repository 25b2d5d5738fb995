#pragma once
// The linear sloshing modes of the 3D tanks that have a closed form (issue 31): the box and the
// upright cylinder, for `sloshsph modes` and the tests.
//  box (length L along x, breadth B along y, depth h): omega^2 = g k tanh(k h),
//      k = pi sqrt((m / L)^2 + (n / B)^2), m, n = 0, 1, 2, ... not both 0 (e.g. Ibrahim 2005, ch. 2);
//  cylinder (radius R): omega^2 = g k tanh(k h), k = j'_{m,n} / R, j'_{m,n} the n-th positive zero
//      of J_m' (Abramowitz & Stegun 1964, Table 9.5): m is the number of nodal diameters, n of
//      nodal circles plus one; the (1, 1) mode is the one a lateral motion excites first.
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"

namespace sloshsph {

struct ThreeDMode {
  int m = 0, n = 0;    // box: half-waves along x and y; cylinder: nodal diameters, radial order
  double omega = 0.0;  // rad/s
};

// The first `count` modes of the case's 3D tank, by increasing frequency (a box's or a cylinder's;
// a prism's section has no 3D closed form: InputError naming tank.shape). Modes of equal frequency
// (a square box's (1,0) and (0,1)) are both listed.
std::vector<ThreeDMode> three_d_modes(const CaseSpec& spec, int count);

}  // namespace sloshsph
