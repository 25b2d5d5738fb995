#pragma once
// Small cases for the structure-TLD coupling tests.
#include <string>

namespace sloshsph::test {

// A 0.1 m x 0.1 m water section (depth 0.1 m in a 0.2 m high tank), dp = 5 mm (20 x 20 fluid
// particles) unless given, kinematic viscosity `viscosity`, fixed dt = 1 ms (the reader's bound
// is 2.0 ms at dp = 5 mm), followed by `rest` (the [structure] tables and any other section).
inline std::string small_tank_case(const std::string& rest, double end = 1.0, double viscosity = 1.0e-6,
                                   double dp = 0.005) {
  return "[fluid]\nviscosity = " + std::to_string(viscosity) + R"(

[tank]
shape = "rectangle"
length = 0.1
height = 0.2

[fill]
depth = 0.1

[particles]
dp = )" + std::to_string(dp) + R"(

[time]
dt = 0.001
settle = 0.2
end = )" + std::to_string(end) +
         "\n\n[output]\nsample_interval = 0.01\n" + rest;
}

}  // namespace sloshsph::test
