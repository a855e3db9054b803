// How a job of this layer tells its caller what happens while it runs, printing nothing itself
// (docs/architecture.md#layers: jobs above report and vision). Three kinds of text, each handed out as
// it arises, in the order the job meets it; each callback may be empty (that text is dropped):
//   progress  text for the reader, whole lines each ending in '\n' (a command line prints it on
//             standard output: the folder read, the intrinsics, the per-image table);
//   note      one fact the reader should know, without prefix or line break (how rows were
//             paired, a sub-folder hidden by top-level images);
//   warning   one thing that may be wrong, likewise (intrinsics that fit the images poorly).
// A command line prints notes and warnings on standard error ("hecal: note: ...",
// "hecal: warning: ..."); the same texts that go into a result document go there, not here.
#pragma once

#include <functional>
#include <string>

namespace hecal::jobs {

struct JobCallbacks {
  std::function<void(const std::string&)> progress;
  std::function<void(const std::string&)> note;
  std::function<void(const std::string&)> warning;

  // Hand out one text of each kind (nothing when that callback is empty).
  void Progress(const std::string& text) const {
    if (progress) progress(text);
  }
  void Note(const std::string& text) const {
    if (note) note(text);
  }
  void Warning(const std::string& text) const {
    if (warning) warning(text);
  }
};

}  // namespace hecal::jobs
