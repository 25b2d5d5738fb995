#pragma once
// Small file helpers: atomic writes (temporary file + rename) so that no output is
// ever half-written, and the run directory guard.
#include <string>

namespace sloshsph {

// Writes `content` to `path` through `path.tmp` and a rename.
void write_file_atomic(const std::string& path, const std::string& content);

// Reads a whole file; throws InputError(path) when it cannot.
std::string read_file(const std::string& path);

// An exclusive lock on a run directory, held while the object lives: flock() on DIR/run.lock,
// which also holds the owner's process id. Why: two processes in one run directory (a run and a
// resume, two resumes, two long tests) would interleave their rows in timeseries.csv and
// overwrite each other's checkpoints. The kernel drops the lock when the process ends, however
// it ends, so no stale lock is ever left behind. Throws InputError naming the directory and the
// other process when it is taken; the directory must exist. On a file system without locks it
// warns and guards nothing.
class RunDirectoryLock {
 public:
  explicit RunDirectoryLock(const std::string& dir);
  ~RunDirectoryLock();
  RunDirectoryLock(const RunDirectoryLock&) = delete;
  RunDirectoryLock& operator=(const RunDirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

// The process that holds DIR/run.lock: its id when a process holds it, 0 when none does (or
// there is no run.lock), -1 when this cannot be told (no /proc/locks: not Linux). It only reads
// /proc/locks, which lists every flock() with its owner and the file's device and inode: it
// never takes the lock itself, so asking cannot make a run that starts at that moment fail.
long run_directory_lock_holder(const std::string& dir);

}  // namespace sloshsph
