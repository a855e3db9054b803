#include "hecal/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <random>
#include <stdexcept>
#include <utility>

#include "hecal/core/error.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;

std::string ErrnoText(int error) {
  return std::strerror(error);
}

// The directory that will hold `path` ("." for a bare file name).
std::string ParentDirectory(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// A temporary name next to `path` that no other writer (thread or process) picks.
std::string TemporaryName(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  thread_local std::mt19937_64 rng{std::random_device{}()};
  return path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + "-" +
         std::to_string(rng() % 1000000);
}

// "give --output a path ..." or "give a path ..." when no flag named it.
std::string Give(const std::string& flag) {
  return flag.empty() ? std::string("give a path") : "give " + flag + " a path";
}

std::string KindName(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void ThrowWriteError(const std::string& flag, const std::string& path, int error) {
  if (error == ENOENT || error == ENOTDIR) {
    throw InputError(path, 0,
                     "cannot write: the directory '" + ParentDirectory(path) + "' does not exist",
                     "create the directory first, or " + Give(flag) + " in an existing directory");
  }
  throw InputError(path, 0, "cannot write: " + ErrnoText(error),
                   "check that the directory is writable and the disk is not full");
}

// The file an output path replaces: the path itself (new or a regular file) or, for a symbolic
// link to a regular file, that file. Throws for everything the rules of atomic_file.h refuse.
std::string OutputTarget(const std::string& flag, const std::string& path) {
  if (path.empty()) {
    throw InputError(flag.empty() ? std::string("<output>") : flag, 0, "empty output path",
                     "name an output file");
  }
  struct stat link;
  if (lstat(path.c_str(), &link) != 0) {
    const int error = errno;
    if (error != ENOENT) ThrowWriteError(flag, path, error);
    struct stat parent;
    if (stat(ParentDirectory(path).c_str(), &parent) != 0 || !S_ISDIR(parent.st_mode)) {
      ThrowWriteError(flag, path, ENOENT);
    }
    return path;
  }
  if (S_ISREG(link.st_mode)) return path;
  if (S_ISDIR(link.st_mode)) {
    throw InputError(
        path, 0, "cannot write: it is a directory",
        "name a file, not a directory" + (flag.empty() ? std::string() : " (" + flag + " FILE)"));
  }
  const std::string fix = "give " + (flag.empty() ? std::string("the output") : flag) +
                          " a regular file (hecal replaces only regular files; leave the "
                          "option out to write nothing)";
  if (!S_ISLNK(link.st_mode)) {
    throw InputError(path, 0, "cannot write: it is " + KindName(link.st_mode) + ", not a file",
                     fix);
  }
  struct stat pointed;
  if (stat(path.c_str(), &pointed) != 0) {
    throw InputError(path, 0, "cannot write: it is a symbolic link to nothing (a broken link)",
                     fix);
  }
  if (!S_ISREG(pointed.st_mode)) {
    throw InputError(
        path, 0,
        "cannot write: it is a symbolic link to " + KindName(pointed.st_mode) + ", not to a file",
        fix);
  }
  char resolved[PATH_MAX];
  if (realpath(path.c_str(), resolved) == nullptr) ThrowWriteError(flag, path, errno);
  return resolved;
}

// Who a path is, for "same file" checks: device and inode when it exists, else its canonical
// spelling.
struct Identity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string canonical;

  bool SameFile(const Identity& other) const {
    if (exists && other.exists) return device == other.device && inode == other.inode;
    return !exists && !other.exists && canonical == other.canonical;
  }
};

Identity IdentityOf(const std::string& path) {
  Identity identity;
  struct stat info;
  if (stat(path.c_str(), &info) == 0) {
    identity.exists = true;
    identity.device = info.st_dev;
    identity.inode = info.st_ino;
  }
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path, error), error);
  identity.canonical = error ? fs::path(path).lexically_normal().string() : canonical.string();
  return identity;
}

std::string Named(const PathArgument& argument) {
  return argument.flag.empty() ? argument.path : argument.flag + " " + argument.path;
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

// Writes `contents` to a new file `temporary` (exclusive create), flushed to disk, with `mode`
// when given. Returns 0 or the errno of the failure (the file then removed).
int WriteNewFile(const std::string& temporary, std::string_view contents,
                 std::optional<mode_t> mode) {
  const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  int error = 0;
  if (mode && fchmod(fd, *mode) != 0) error = errno;
  if (error == 0 && !WriteAll(fd, contents)) error = errno;
  if (error == 0 && fsync(fd) != 0) error = errno;
  if (close(fd) != 0 && error == 0) error = errno;
  if (error != 0) unlink(temporary.c_str());
  return error;
}

// A copy of the existing `target` to restore it by rename: a hard link, or a copy where the file
// system has none. nullopt (and the errno in `error`) when it could not be made.
std::optional<std::string> Backup(const std::string& target, int* error) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string backup = TemporaryName(target);
    if (link(target.c_str(), backup.c_str()) == 0) return backup;
    *error = errno;
    if (*error == EEXIST) continue;
    struct stat info;
    if (stat(target.c_str(), &info) != 0) {
      *error = errno;
      return std::nullopt;
    }
    try {
      *error = WriteNewFile(backup, ReadFile(target), info.st_mode & 07777);
    } catch (const InputError&) {
      *error = EIO;
    }
    if (*error == 0) return backup;
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

void CheckOutputs(const std::vector<PathArgument>& outputs,
                  const std::vector<PathArgument>& inputs) {
  std::vector<Identity> seen;
  std::vector<const PathArgument*> seen_outputs;
  for (const PathArgument& output : outputs) {
    if (output.path.empty()) continue;
    OutputTarget(output.flag, output.path);
    const Identity identity = IdentityOf(output.path);
    for (const PathArgument& input : inputs) {
      if (input.path.empty()) continue;
      const Identity other = IdentityOf(input.path);
      if (identity.exists && identity.SameFile(other)) {
        throw InputError(output.path, 0,
                         output.flag + " names the input " + Named(input) +
                             ": the command would overwrite the file it reads",
                         "give " + output.flag +
                             " another file name (hecal never overwrites "
                             "its inputs)");
      }
    }
    for (size_t k = 0; k < seen.size(); ++k) {
      if (identity.SameFile(seen[k])) {
        throw InputError(output.path, 0,
                         output.flag + " names the same file as " + Named(*seen_outputs[k]),
                         "give each output its own file");
      }
    }
    seen.push_back(identity);
    seen_outputs.push_back(&output);
  }
}

StagedFiles::~StagedFiles() {
  if (!committed_) Discard();
}

void StagedFiles::Discard() {
  for (const Staged& file : staged_) unlink(file.temporary.c_str());
  staged_.clear();
}

void StagedFiles::Stage(const std::string& flag, const std::string& path,
                        std::string_view contents) {
  if (committed_) throw std::logic_error("StagedFiles::Stage after Commit");
  const std::string target = OutputTarget(flag, path);
  const Identity identity = IdentityOf(target);
  for (const Staged& file : staged_) {
    if (identity.SameFile(IdentityOf(file.target))) {
      const std::string name = file.flag.empty() ? file.path : file.flag + " " + file.path;
      throw InputError(path, 0, (flag.empty() ? "" : flag + " ") + "names the same file as " + name,
                       "give each output its own file");
    }
  }
  std::optional<mode_t> mode;
  struct stat existing;
  if (stat(target.c_str(), &existing) == 0) mode = existing.st_mode & 07777;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string temporary = TemporaryName(target);
    const int error = WriteNewFile(temporary, contents, mode);
    if (error == 0) {
      staged_.push_back({flag, path, target, temporary});
      return;
    }
    if (error != EEXIST) ThrowWriteError(flag, path, error);
  }
  ThrowWriteError(flag, path, EEXIST);
}

void StagedFiles::Commit() {
  if (committed_) throw std::logic_error("StagedFiles::Commit twice");
  // Every replaced target is kept until all renames succeeded (one file needs no copy: its
  // rename either happens or leaves the target as it was).
  std::vector<std::optional<std::string>> backups(staged_.size());
  const auto remove_backups = [&backups] {
    for (const std::optional<std::string>& backup : backups) {
      if (backup) unlink(backup->c_str());
    }
  };
  if (staged_.size() > 1) {
    for (size_t i = 0; i < staged_.size(); ++i) {
      struct stat info;
      if (lstat(staged_[i].target.c_str(), &info) != 0) continue;  // a new file
      int error = 0;
      backups[i] = Backup(staged_[i].target, &error);
      if (!backups[i]) {
        const std::string path = staged_[i].path;  // Discard clears staged_
        remove_backups();
        Discard();
        throw InputError(path, 0,
                         "cannot keep a copy of the existing file while replacing it with the "
                         "other outputs: " +
                             ErrnoText(error),
                         "check that the directory is writable and the disk is not full");
      }
    }
  }
  for (size_t i = 0; i < staged_.size(); ++i) {
    if (rename(staged_[i].temporary.c_str(), staged_[i].target.c_str()) == 0) continue;
    const int error = errno;
    for (size_t j = 0; j < i; ++j) {  // undo the renames done
      if (backups[j]) {
        if (rename(backups[j]->c_str(), staged_[j].target.c_str()) == 0) backups[j].reset();
      } else {
        unlink(staged_[j].target.c_str());
      }
    }
    for (size_t j = i; j < staged_.size(); ++j) unlink(staged_[j].temporary.c_str());
    remove_backups();
    const Staged failed = staged_[i];
    staged_.clear();
    ThrowWriteError(failed.flag, failed.path, error);
  }
  remove_backups();
  staged_.clear();
  committed_ = true;
}

StagedFolder::StagedFolder(std::string flag, std::string folder, std::string what)
    : flag_(std::move(flag)), folder_(std::move(folder)), what_(std::move(what)) {}

StagedFolder::~StagedFolder() {
  if (committed_ || created_.empty()) return;
  std::error_code ignored;
  fs::remove_all(created_, ignored);  // the staged files in it too
}

void StagedFolder::Create() {
  const std::string give =
      flag_.empty() ? std::string("give a folder") : "give " + flag_ + " a folder";
  std::error_code error;
  const fs::file_status status = fs::status(folder_, error);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) {
      throw InputError(folder_, 0, "cannot write " + what_ + ": it exists and is not a folder",
                       give + " (created when missing)");
    }
    ready_ = true;
    return;
  }
  fs::path topmost = fs::absolute(folder_, error);
  while (topmost.has_parent_path() && topmost.parent_path() != topmost &&
         !fs::exists(topmost.parent_path(), error)) {
    topmost = topmost.parent_path();
  }
  fs::create_directories(folder_, error);
  if (error || !fs::is_directory(folder_)) {
    throw InputError(folder_, 0, "cannot create the output folder: " + error.message(),
                     give + " that can be created or written");
  }
  created_ = topmost.string();
  ready_ = true;
}

void StagedFolder::Stage(const std::string& name, std::string_view contents) {
  if (!ready_) Create();
  files_.Stage(flag_, (fs::path(folder_) / name).string(), contents);
}

void StagedFolder::Commit() {
  if (!ready_) Create();
  files_.Commit();
  committed_ = true;
}

void WriteFilesAtomically(const std::vector<OutputFile>& files) {
  StagedFiles staged;
  for (const OutputFile& file : files) staged.Stage(file.flag, file.path, file.contents);
  staged.Commit();
}

void WriteFileAtomically(const std::string& path, std::string_view contents) {
  StagedFiles staged;
  staged.Stage("", path, contents);
  staged.Commit();
}

std::string ReadFile(const std::string& path) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused below).
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    const int error = errno;
    const std::string fix =
        error == ENOENT ? "check the file name and path" : "check the file's permissions";
    throw InputError(path, 0, "cannot read: " + ErrnoText(error), fix);
  }
  struct stat info;
  if (fstat(fd, &info) != 0) {
    const int error = errno;
    close(fd);
    throw InputError(path, 0, "cannot read: " + ErrnoText(error), "check the file");
  }
  if (S_ISDIR(info.st_mode)) {
    close(fd);
    throw InputError(path, 0, "cannot read: it is a directory", "name a file, not a directory");
  }
  if (!S_ISREG(info.st_mode)) {
    close(fd);
    throw InputError(path, 0, "cannot read: it is " + KindName(info.st_mode) + ", not a file",
                     "give a regular file (hecal reads whole files, not pipes or devices)");
  }
  const auto too_large = [&path] {
    return InputError(path, 0,
                      "cannot read: the file is larger than " +
                          std::to_string(kMaxInputBytes >> 20) + " MiB, the most hecal reads",
                      "check that it is the right file, or split it");
  };
  if (static_cast<std::uint64_t>(info.st_size) > kMaxInputBytes) {
    close(fd);
    throw too_large();
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
    if (contents.size() > kMaxInputBytes) {  // a file that grows while it is read
      close(fd);
      throw too_large();
    }
  }
  close(fd);
  return contents;
}

}  // namespace hecal::io
