#include "engine/io/output_set.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <system_error>

#include "engine/io/atomic_file.hpp"

namespace curvefold {

namespace fs = std::filesystem;

bool sameFile(const fs::path& a, const fs::path& b) {
  std::error_code error;
  // Both there: the same inode is the same file, whichever links lead to it.
  if (fs::exists(a, error) && fs::exists(b, error)) {
    const bool same = fs::equivalent(a, b, error);
    if (!error) return same;
  }
  const fs::path x = fs::weakly_canonical(fs::absolute(a, error), error);
  const fs::path y = fs::weakly_canonical(fs::absolute(b, error), error);
  return x == y;
}

void refuseOutputsOverInputs(const std::vector<fs::path>& outputs,
                             const std::vector<NamedInput>& inputs) {
  for (const fs::path& output : outputs) {
    if (output.empty() || output == "-") continue;
    for (const NamedInput& input : inputs)
      if (!input.path.empty() && sameFile(output, input.path))
        throw FileError(output.string() + " is " + input.what + "; write to another file");
  }
}

void OutputSet::add(const fs::path& path, std::function<void(const fs::path&)> writer) {
  outputs_.push_back({path, std::move(writer)});
}

void OutputSet::checkWritable() const {
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    for (std::size_t j = i + 1; j < outputs_.size(); ++j)
      if (outputs_[i].path != "-" && sameFile(outputs_[i].path, outputs_[j].path))
        throw FileError("cannot write " + outputs_[j].path.string() +
                        ": another output names the same file");
  for (const Output& output : outputs_) {
    if (output.path == "-") continue;
    const fs::path target = resolveOutputPath(output.path);
    if (fs::is_directory(target))
      throw FileError("cannot write " + output.path.string() + ": it is a folder");
    if (writesInPlace(target)) continue;
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(folder))
      throw FileError("cannot write " + output.path.string() + ": no folder " + folder.string());
    if (::access(folder.c_str(), W_OK) != 0)
      throw FileError("cannot write " + output.path.string() + ": " + std::strerror(errno));
  }
}

void OutputSet::write(const fs::path& folder) {
  bool created = false;
  if (!folder.empty() && !fs::is_directory(folder)) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw FileError("cannot create " + folder.string() + ": " + error.message());
    created = true;
  }
  struct Staged {
    const Output* output;
    fs::path target;  // symbolic links followed
    fs::path stage;   // empty once renamed
    bool inPlace;     // a device, a FIFO, standard output: written last
  };
  std::vector<Staged> staged;
  auto discard = [&] {
    std::error_code ignored;
    for (const Staged& entry : staged)
      if (!entry.stage.empty()) fs::remove(entry.stage, ignored);
    if (created) fs::remove(folder, ignored);  // only if still empty
  };
  auto run = [](const Output& output, const fs::path& at) {
    try {
      output.writer(at);
    } catch (const std::bad_alloc&) {
      throw;  // not the file's fault: the command says what ran out
    } catch (const std::exception& e) {
      // The writers name the staging file; the user knows the target.
      std::string message = e.what();
      const std::string stage = at.string();
      if (stage != output.path.string())
        for (auto found = message.find(stage); found != std::string::npos;
             found = message.find(stage, found + output.path.string().size()))
          message.replace(found, stage.size(), output.path.string());
      throw FileError(message);
    }
  };
  try {
    // A target that cannot be written (a folder, a folder missing) is found before any target is
    // replaced: otherwise the renames below would commit the outputs before it.
    checkWritable();
    for (const Output& output : outputs_) {
      const fs::path target = resolveOutputPath(output.path);
      if (writesInPlace(target)) {
        staged.push_back({&output, target, {}, true});
        continue;
      }
      removeStaleTemporaries(target);
      staged.push_back({&output, target, stagingPathFor(target), false});
      run(output, staged.back().stage);
    }
    // What cannot be staged (a device, a FIFO, standard output) is written once every file is
    // staged and before any is committed: a device that fails (/dev/full) leaves every file as
    // it was.
    for (const Staged& entry : staged)
      if (entry.inPlace) run(*entry.output, entry.target);
    for (Staged& entry : staged) {
      if (entry.inPlace) continue;
      keepPermissions(entry.target, entry.stage);
      std::error_code error;
      fs::rename(entry.stage, entry.target, error);
      if (error)
        throw FileError("cannot write " + entry.output->path.string() + ": " + error.message());
      entry.stage.clear();
    }
  } catch (...) {
    discard();
    throw;
  }
}

}  // namespace curvefold
