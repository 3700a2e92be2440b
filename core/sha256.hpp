#pragma once
// SHA-256 by OpenSSL, fed piece by piece (the state hash, verify/state_hash.hpp) or over one
// buffer at once (a case's input files, core/case_inputs.hpp).

#include <openssl/evp.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace revsph {

class Sha256 {
public:
  Sha256();
  void add(const void* data, std::size_t size);
  // Length-prefixed, so that "ab" + "c" and "a" + "bc" differ.
  void add_string(const std::string& text);
  // 8 bytes, little-endian.
  void add_integer(std::int64_t value);
  // Lower-case hexadecimal; ends the digest.
  std::string hex_digest();

private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context_;
};

// The hexadecimal SHA-256 of `bytes`.
std::string sha256_hex(std::string_view bytes);

} // namespace revsph
