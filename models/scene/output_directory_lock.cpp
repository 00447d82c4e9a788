#include "models/scene/output_directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "assembly/error.hpp"

namespace pc {

OutputDirectoryLock::OutputDirectoryLock(const std::string& directory) {
  namespace fs = std::filesystem;
  require(!directory.empty(), "the output directory (--out) is empty: name the directory to write the results into");
  std::error_code error;
  if (fs::exists(directory, error)) {
    require(fs::is_directory(directory, error), "the output directory (--out) '", directory,
            "' exists and is not a directory");
  } else {
    fs::create_directories(directory, error);
    require(!error, "cannot create the output directory (--out) '", directory, "': ", error.message());
  }
  const std::string lock = (fs::path(directory) / ".piezocontact.lock").string();
  fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  require(fd_ >= 0, "the output directory (--out) '", directory, "' is not writable: cannot create '", lock,
          "': ", std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int reason = errno;
    std::string owner;
    std::ifstream in(lock);
    std::getline(in, owner);
    ::close(fd_);
    fd_ = -1;
    require(reason != EWOULDBLOCK, "the output directory (--out) '", directory, "' is in use by another run (pid ",
            owner.empty() ? "unknown" : owner, "); wait for it to end or choose another --out");
    fail("cannot lock the output directory (--out) '", directory, "' (", lock, "): ", std::strerror(reason));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  const bool written = ::ftruncate(fd_, 0) == 0 && ::write(fd_, pid.data(), pid.size()) == ssize_t(pid.size());
  // The lock file alone does not show that results can be written (it may be left from an earlier run):
  // a file is created and removed in the directory, before any step is computed.
  const std::string probe_file =
      (fs::path(directory) / (".piezocontact.write_test." + std::to_string(::getpid()))).string();
  const int probe_fd = ::open(probe_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int probe_errno = errno;
  if (probe_fd >= 0) {
    ::close(probe_fd);
    ::unlink(probe_file.c_str());
  }
  if (!written || probe_fd < 0) {
    ::close(fd_);
    fd_ = -1;
    fail("the output directory (--out) '", directory,
         "' is not writable: ", probe_fd < 0 ? std::strerror(probe_errno) : "cannot write the lock file");
  }
}

OutputDirectoryLock::~OutputDirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock; the file stays, so that no run locks an unlinked one
}

}  // namespace pc
