#pragma once
// The files a case reads besides itself (particles[].file: point files, STL surfaces), held as
// bytes: read from disk once by a new run, or given by the snapshot a run continues, so that a
// snapshot restarts without them (docs/restart.md). The readers parse these bytes, never the disk.

#include <deque>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace revsph {

struct InputFile {
  std::string name;   // as the case writes it: "tank.stl"
  std::string path;   // where it was read: for messages, and (absolute) in snapshots
  std::string sha256; // of `bytes`, hexadecimal
  std::string bytes;

  bool operator==(const InputFile&) const = default;
};

// One line: the file and what is wrong ("tank.stl: no such file").
class InputFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The bytes of the file at `path`, named `name`. Throws InputFileError.
InputFile read_input_file(const std::filesystem::path& path, std::string name);

class CaseInputs {
public:
  // The file the case names `name`: the one given by that name, else read from `path` (and
  // kept: read once however many blocks name it). Throws InputFileError.
  const InputFile& get(const std::string& name, const std::filesystem::path& path);
  // Makes `file` the one of its name (from a snapshot).
  void give(InputFile file);
  // Every file asked for so far (a given one the case no longer names is not): what a snapshot
  // keeps.
  std::vector<InputFile> used() const;

private:
  std::deque<InputFile> files_; // stable addresses: get() returns references into it
  std::vector<bool> asked_;
};

} // namespace revsph
