// libFuzzer target: one record file for both record readers (fuzz_inputs.hpp).
// Built only with a compiler that has -fsanitize=fuzzer (tests/fuzz/CMakeLists.txt).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The readers take a path: one file per process, rewritten for each input.
  static const std::string path =
      (std::filesystem::temp_directory_path() / ("sloshsph_fuzz_record_" + std::to_string(getpid()))).string();
  sloshsph::fuzz::check_record_bytes(std::string(reinterpret_cast<const char*>(data), size), path);
  return 0;
}
