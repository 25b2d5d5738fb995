#include "sloshsph/io/files.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"

namespace sloshsph {

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp + ": " + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw std::runtime_error("write failed for " + tmp + ": " + std::strerror(errno));
  }
  std::filesystem::rename(tmp, path);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot read the file: ") + std::strerror(errno));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

RunDirectoryLock::RunDirectoryLock(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / "run.lock").string();
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(dir, "", "cannot open run.lock in the run directory: " + std::string(std::strerror(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    char owner[32] = {0};
    const ssize_t n = ::pread(fd_, owner, sizeof owner - 1, 0);
    ::close(fd_);
    fd_ = -1;
    if (error != EWOULDBLOCK) {
      // A file system without locks (some network mounts): run unguarded rather than not at all.
      std::fprintf(stderr, "sloshsph: warning: %s: cannot lock run.lock (%s); nothing keeps a second process out of this run directory\n",
                   dir.c_str(), std::strerror(error));
      return;
    }
    std::string pid = n > 0 ? std::string(owner, static_cast<std::size_t>(n)) : std::string("unknown");
    while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
    throw InputError(dir, "",
                     "another process (pid " + pid + ") is running in this run directory and holds run.lock; wait for "
                     "it to end, or stop it first (kill -INT " + pid + " writes a checkpoint)");
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  // The id is only a hint for the message above: the lock holds without it.
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, pid.data(), pid.size(), 0);
  }
}

RunDirectoryLock::~RunDirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the lock
}

long run_directory_lock_holder(const std::string& dir) {
  struct stat lock_file {};
  if (::stat((std::filesystem::path(dir) / "run.lock").c_str(), &lock_file) != 0) return 0;
  std::ifstream locks("/proc/locks");
  if (!locks) return -1;
  // A line: "1: FLOCK  ADVISORY  WRITE 20559 fe:00:5333006 0 EOF" (the device's major and minor
  // in hexadecimal, the inode in decimal); a process waiting for a lock has "->" before FLOCK.
  char device[32];
  std::snprintf(device, sizeof device, "%02x:%02x:", ::major(lock_file.st_dev), ::minor(lock_file.st_dev));
  const std::string file_id = device + std::to_string(lock_file.st_ino);
  std::string line;
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string number, type, mode, access, pid, id;
    fields >> number >> type;
    if (type != "FLOCK") continue;
    if (fields >> mode >> access >> pid >> id && id == file_id) return std::stol(pid);
  }
  return 0;
}

}  // namespace sloshsph
