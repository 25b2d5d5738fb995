#pragma once
// The ranks of a sweep started by mpirun (OpenMPI): point k of the sweep runs on rank
// k mod size. Without MPI, or when not started by mpirun, there is one rank.
#include <string>
#include <vector>

namespace sloshsph::app {

class SweepRanks {
 public:
  SweepRanks();   // MPI_Init only when started by mpirun with more than one process
  ~SweepRanks();  // MPI_Finalize
  SweepRanks(const SweepRanks&) = delete;
  SweepRanks& operator=(const SweepRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool mine(std::size_t point) const { return static_cast<int>(point % static_cast<std::size_t>(size_)) == rank_; }

  // Waits for every rank; then rank 0 receives the texts the others pass (one per point of
  // theirs: the point's summary.json, "" when it has none) and returns them by point index
  // (its own entries are empty: rank 0 reads its own files). Other ranks return {}.
  std::vector<std::string> gather_to_root(const std::vector<std::string>& texts_of_my_points,
                                          std::size_t total_points) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool initialised_ = false;
};

}  // namespace sloshsph::app
