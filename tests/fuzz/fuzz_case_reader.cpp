// libFuzzer target: one case file (TOML text) for the case reader (fuzz_inputs.hpp).
// Built only with a compiler that has -fsanitize=fuzzer (tests/fuzz/CMakeLists.txt).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // The source names a file in cases/, so relative record paths resolve as in the repository.
  // Anything but InputError escapes and is reported by libFuzzer as a crash.
  sloshsph::fuzz::check_case_text(text, SLOSHSPH_SOURCE_DIR "/cases/fuzz.toml");
  return 0;
}
