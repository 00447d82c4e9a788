#pragma once
// A run's output folder, owned for the run's duration. The constructor creates the directory (and its
// parents), checks that it is a directory this process can write into, and takes an exclusive lock,
// flock(2) on <directory>/.piezocontact.lock, which holds the owner's pid; the lock is released by the
// destructor or when the process exits, however it exits. Every failure is a pc::Error naming the path
// and "--out": not a directory, not writable, or "in use by another run (pid N)". An empty path is refused.
#include <string>

namespace pc {

class OutputDirectoryLock {
 public:
  explicit OutputDirectoryLock(const std::string& directory);
  ~OutputDirectoryLock();
  OutputDirectoryLock(const OutputDirectoryLock&) = delete;
  OutputDirectoryLock& operator=(const OutputDirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace pc
