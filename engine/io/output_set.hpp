// Files a command writes together, all or none (README: "no output file is touched" on failure):
// each regular file is first written whole to a hidden staging name next to its target, and only
// when every one has been written are they renamed into place. Outputs written in place (a
// device, a FIFO, standard output; see atomic_file.hpp) go last, once the staging has succeeded.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace curvefold {

// Whether two paths name one file: one file on the disk when both exist (symbolic links and hard
// links included: std::filesystem::equivalent), else the same path after symbolic links, "." and
// ".." (a file not written yet).
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

// A file a command reads, with how a message names it ("the target", "the design being
// exported").
struct NamedInput {
  std::filesystem::path path;
  std::string what;
};

// The one check of every command that reads and writes: throws FileError "<output> is <what>;
// write to another file" for the first output that names the same file as one of the inputs
// (sameFile), before anything is read or written. Empty paths and "-" (standard output) pass.
void refuseOutputsOverInputs(const std::vector<std::filesystem::path>& outputs,
                             const std::vector<NamedInput>& inputs);

class OutputSet {
 public:
  // writer writes the whole file at the path it is given (atomically, with writeFileAtomically or
  // a writer built on it); it is handed the staging path, or the target itself when written in
  // place.
  void add(const std::filesystem::path& path,
           std::function<void(const std::filesystem::path&)> writer);

  // Before a long computation: throws FileError naming the first target whose folder is missing
  // or cannot be written to, that is a folder itself, or that another output names too (write()
  // may still fail later: a full disk).
  void checkWritable() const;

  // Creates `folder` first when it is given and missing (and removes it again on failure), checks
  // every target (checkWritable), writes each to its staging name, writes what cannot be staged
  // (a device, a FIFO, standard output) in place, then renames them all. Throws FileError naming
  // the target, never the staging name, and std::bad_alloc as it is; on failure no file target has
  // changed (a device written in place may hold part of its output).
  void write(const std::filesystem::path& folder = {});

 private:
  struct Output {
    std::filesystem::path path;
    std::function<void(const std::filesystem::path&)> writer;
  };
  std::vector<Output> outputs_;
};

}  // namespace curvefold
