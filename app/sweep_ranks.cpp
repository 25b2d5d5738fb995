#include "sweep_ranks.hpp"

#include <cstdlib>

#ifdef SLOSHSPH_HAVE_MPI
#include <mpi.h>
#endif

namespace sloshsph::app {
namespace {

// mpirun (OpenMPI) tells its processes the world size; a plain start has no such variable, and
// then MPI is not initialised at all (a singleton MPI_Init would start a runtime daemon).
int launcher_world_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(name); v && *v) return std::atoi(v);
  return 1;
}

}  // namespace

SweepRanks::SweepRanks() {
#ifdef SLOSHSPH_HAVE_MPI
  if (launcher_world_size() > 1) {
    MPI_Init(nullptr, nullptr);
    initialised_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
#endif
}

SweepRanks::~SweepRanks() {
#ifdef SLOSHSPH_HAVE_MPI
  if (initialised_) MPI_Finalize();
#endif
}

std::vector<std::string> SweepRanks::gather_to_root(const std::vector<std::string>& texts_of_my_points,
                                                    std::size_t total_points) const {
  std::vector<std::string> by_point(total_points);
#ifdef SLOSHSPH_HAVE_MPI
  if (!initialised_) return by_point;
  MPI_Barrier(MPI_COMM_WORLD);
  const int tag = 7;
  if (rank_ != 0) {
    for (const std::string& text : texts_of_my_points)
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag, MPI_COMM_WORLD);
    return {};
  }
  // Rank r sends the texts of its points in increasing point order.
  for (std::size_t k = 0; k < total_points; ++k) {
    const int owner = static_cast<int>(k % static_cast<std::size_t>(size_));
    if (owner == 0) continue;
    MPI_Status status;
    MPI_Probe(owner, tag, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_CHAR, &count);
    std::string text(static_cast<std::size_t>(count), '\0');
    MPI_Recv(text.data(), count, MPI_CHAR, owner, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    by_point[k] = text;
  }
#else
  (void)texts_of_my_points;
#endif
  return by_point;
}

}  // namespace sloshsph::app
