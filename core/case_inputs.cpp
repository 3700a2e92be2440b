#include "core/case_inputs.hpp"

#include "core/sha256.hpp"

#include <fstream>
#include <sstream>

namespace revsph {

InputFile read_input_file(const std::filesystem::path& path, std::string name) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputFileError(path.string() + ": no such file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputFileError(path.string() + ": cannot be read");
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) {
    throw InputFileError(path.string() + ": read error");
  }
  InputFile file{std::move(name), path.string(), "", bytes.str()};
  file.sha256 = sha256_hex(file.bytes);
  return file;
}

const InputFile& CaseInputs::get(const std::string& name, const std::filesystem::path& path) {
  for (std::size_t i = 0; i < files_.size(); ++i) {
    if (files_[i].name == name) {
      asked_[i] = true;
      return files_[i];
    }
  }
  files_.push_back(read_input_file(path, name));
  asked_.push_back(true);
  return files_.back();
}

void CaseInputs::give(InputFile file) {
  files_.push_back(std::move(file));
  asked_.push_back(false);
}

std::vector<InputFile> CaseInputs::used() const {
  std::vector<InputFile> files;
  for (std::size_t i = 0; i < files_.size(); ++i) {
    if (asked_[i]) {
      files.push_back(files_[i]);
    }
  }
  return files;
}

} // namespace revsph
