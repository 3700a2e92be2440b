#pragma once
// Output files appear whole or not at all: written under path + ".tmp", then renamed into place,
// so a run killed at any moment never leaves a half-written file under the real name.

#include <filesystem>
#include <string_view>

namespace revsph {

// Throws std::runtime_error if the temporary file cannot be written.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

} // namespace revsph
