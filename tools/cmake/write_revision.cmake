# Run at build time (the target sloshsph_revision in CMakeLists.txt): writes OUTPUT, a source file
# defining sloshsph::kGitRevision as the checkout's current git revision, and rewrites it only
# when the revision changed, so that a build after a new commit records that commit (a revision
# taken when CMake configured would go stale) and recompiles one file.
# Variables: SOURCE_DIR (the checkout), OUTPUT (the file to write).
execute_process(COMMAND git rev-parse --short=12 HEAD
  WORKING_DIRECTORY "${SOURCE_DIR}"
  OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT revision)
  set(revision "unknown")
endif()
set(text "// Generated at build time by tools/cmake/write_revision.cmake.\n#include \"sloshsph/core/version.hpp\"\nnamespace sloshsph {\nconst char* const kGitRevision = \"${revision}\";\n}  // namespace sloshsph\n")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
  if(old STREQUAL text)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${text}")
