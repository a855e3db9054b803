#include "hecal/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>

#include "hecal/core/error.h"

namespace hecal::io {
namespace {

std::string ErrnoText(int error) {
  return std::strerror(error);
}

// The directory that will hold `path` ("." for a bare file name).
std::string ParentDirectory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// A temporary name next to `path` that no other writer (thread or process) picks.
std::string TemporaryName(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  thread_local std::mt19937_64 rng{std::random_device{}()};
  return path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + "-" +
         std::to_string(rng() % 1000000);
}

bool WriteAll(int fd, std::string_view contents) {
  while (!contents.empty()) {
    const ssize_t written = write(fd, contents.data(), contents.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    contents.remove_prefix(static_cast<size_t>(written));
  }
  return true;
}

[[noreturn]] void ThrowWriteError(const std::string& path, int error) {
  if (error == ENOENT || error == ENOTDIR) {
    throw InputError(path, 0,
                     "cannot write: the directory '" + ParentDirectory(path) + "' does not exist",
                     "create the directory first or choose another output path");
  }
  throw InputError(path, 0, "cannot write: " + ErrnoText(error),
                   "check that the directory is writable and the disk is not full");
}

}  // namespace

void WriteFileAtomically(const std::string& path, std::string_view contents) {
  if (path.empty()) throw InputError("<output>", 0, "empty output path", "name an output file");
  struct stat target;
  if (stat(path.c_str(), &target) == 0 && S_ISDIR(target.st_mode)) {
    throw InputError(path, 0, "cannot write: it is a directory", "name a file, not a directory");
  }
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = TemporaryName(path);
    fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) ThrowWriteError(path, errno);
  }
  if (fd < 0) ThrowWriteError(path, EEXIST);

  int error = 0;
  if (!WriteAll(fd, contents)) error = errno;
  if (error == 0 && fsync(fd) != 0) error = errno;
  if (close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    unlink(temporary.c_str());
    ThrowWriteError(path, error);
  }
}

std::string ReadFile(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    const std::string fix =
        error == ENOENT ? "check the file name and path" : "check the file's permissions";
    throw InputError(path, 0, "cannot read: " + ErrnoText(error), fix);
  }
  struct stat info;
  if (fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
    close(fd);
    throw InputError(path, 0, "cannot read: it is a directory", "name a file, not a directory");
  }
  std::string contents;
  if (info.st_size > 0) contents.reserve(static_cast<size_t>(info.st_size));
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = read(fd, buffer, sizeof(buffer));
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      close(fd);
      throw InputError(path, 0, "cannot read: " + ErrnoText(error), "check the file");
    }
    if (n == 0) break;
    contents.append(buffer, static_cast<size_t>(n));
  }
  close(fd);
  return contents;
}

}  // namespace hecal::io
