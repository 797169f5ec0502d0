// file_write.cpp — the temporary-then-rename writer (see file_write.h).
#include "conformesh/intrinsic/io/file_write.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "conformesh/intrinsic/errors.h"

namespace conformesh::intrinsic {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& temp, const char* what, int err) {
  std::remove(temp.c_str());
  throw InputError(path + ": " + what + ": " + std::strerror(err));
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& bytes, bool sync) {
  static std::atomic<unsigned> counter{0};
  const std::string temp =
      path + ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" + std::to_string(counter++);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      fail(path, temp, "cannot write", err);
    }
    done += static_cast<size_t>(n);
  }
  if (sync && ::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    fail(path, temp, "cannot flush to disk", err);
  }
  if (::close(fd) != 0) fail(path, temp, "cannot write", errno);
  if (std::rename(temp.c_str(), path.c_str()) != 0) fail(path, temp, "cannot replace with the written file", errno);
}

}  // namespace conformesh::intrinsic
