// Files in and out of a command: never a partial output file, never an input or a device
// overwritten, several outputs all or nothing (docs/cli.md; docs/reliability.md).
//
// Output paths (CheckOutputs, and every write below):
//   - the directory must exist ("the directory 'x' does not exist");
//   - a path that exists must be a regular file, replaced atomically, or a symbolic link to a
//     regular file: the file it points to is replaced atomically through the link, which stays a
//     link. A directory, a FIFO, a character or block device, a socket and a link to one of those
//     or to nothing are refused: hecal never replaces a device node or a pipe by a file;
//   - an output must not be one of the command's inputs (the same device and inode, so hard
//     links and other spellings of the path count) nor the same file as another output.
// Writing: each file is written to a temporary name in its target's directory
// ("NAME.tmp-PID-N-R"), flushed to disk (fsync), and renamed over the target; a replaced file
// keeps its permission bits. StagedFiles stages any number of files and renames them together:
// when one stage or one rename fails, the staged files are removed and every target already
// replaced gets its previous file back (kept as a hard link, or a copy where the file system has
// no hard links, until the end), so the command leaves all its outputs or none. Failures throw
// hecal::InputError naming the path and the flag.
// Inputs (ReadFile): a regular file (or a link to one) of at most kMaxInputBytes; a directory,
// a FIFO (which would block), a device (/dev/zero would never end) or a larger file is refused.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hecal::io {

// The largest file ReadFile reads (256 MiB: a pose table of a million stations is ~100 MB).
constexpr std::uint64_t kMaxInputBytes = std::uint64_t{256} << 20;

// A path given on the command line, with the flag that gave it ("--output", "--robot"; an input
// named by position, e.g. import's INPUT, uses a description such as "input").
struct PathArgument {
  std::string flag;
  std::string path;
};

// Checks every output path against the rules above (directory, kind of file, not an input, not
// another output) before a command does its work. Outputs with an empty path are skipped (an
// optional output not given). Throws InputError naming the path and the flag.
void CheckOutputs(const std::vector<PathArgument>& outputs,
                  const std::vector<PathArgument>& inputs);

// Files staged now and renamed over their targets together by Commit (see above). Destroying an
// uncommitted StagedFiles removes its staged temporary files.
class StagedFiles {
 public:
  StagedFiles() = default;
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;

  // Writes `contents` to a temporary file next to `path` (the file a link points to). `flag`
  // names the path in messages ("" for none). Throws InputError for a path the rules refuse,
  // the same target staged twice, or a failed write.
  void Stage(const std::string& flag, const std::string& path, std::string_view contents);

  // Renames every staged file over its target, all or nothing (see above).
  void Commit();

 private:
  struct Staged {
    std::string flag;
    std::string path;       // as given, for messages
    std::string target;     // the file replaced: `path`, or the file a link points to
    std::string temporary;  // the staged contents
  };
  void Discard();
  std::vector<Staged> staged_;
  bool committed_ = false;
};

// A folder of files written all or none (`hecal contour render`'s frames and text files): the
// folder, with any missing parents, is created when the first file is staged; each file is staged
// in it (StagedFiles) and all are renamed together by Commit. Destroyed without a successful
// Commit (a failure midway), it removes its staged files and every folder it created, so the
// folder is left as it was, or not there. An existing folder is written into: files of the same
// names are replaced, others are kept. Errors (hecal::InputError, source the folder): the path
// exists and is not a folder, the folder cannot be created; those of StagedFiles (naming the
// file).
class StagedFolder {
 public:
  // `flag` names the folder in fixes ("--output"; "" for none), `what` its files in messages
  // ("the frames").
  StagedFolder(std::string flag, std::string folder, std::string what = "the files");
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Stages the file `name` (a file name, no folder) of the folder with `contents`.
  void Stage(const std::string& name, std::string_view contents);
  // Renames every staged file into place (StagedFiles::Commit); the folder then stays.
  void Commit();

 private:
  void Create();
  std::string flag_;
  std::string folder_;
  std::string what_;
  bool ready_ = false;   // the folder exists (found or created)
  std::string created_;  // the topmost folder created here, "" when none
  bool committed_ = false;
  StagedFiles files_;
};

struct OutputFile {
  std::string flag;
  std::string path;
  std::string contents;
};

// Every file or none (StagedFiles).
void WriteFilesAtomically(const std::vector<OutputFile>& files);

// One file (WriteFilesAtomically with one file).
void WriteFileAtomically(const std::string& path, std::string_view contents);

// Reads a whole file; throws InputError (path, "cannot read ...") when it cannot, or when it is
// not a regular file or larger than kMaxInputBytes.
std::string ReadFile(const std::string& path);

}  // namespace hecal::io
