#include "verify/state_hash.hpp"

#include "core/distributed/index_order_stream.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <array>
#include <bit>
#include <memory>
#include <stdexcept>

namespace revsph {

namespace {

class Sha256 {
public:
  Sha256() : context_(EVP_MD_CTX_new(), &EVP_MD_CTX_free) {
    if (!context_ || EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr) != 1) {
      throw std::runtime_error("SHA-256 initialisation failed");
    }
  }
  void add(const void* data, std::size_t size) {
    if (EVP_DigestUpdate(context_.get(), data, size) != 1) {
      throw std::runtime_error("SHA-256 update failed");
    }
  }
  void add_string(const std::string& text) {
    add_integer(static_cast<std::int64_t>(text.size()));
    add(text.data(), text.size());
  }
  void add_integer(std::int64_t value) {
    std::array<unsigned char, 8> bytes{};
    const auto bits = static_cast<std::uint64_t>(value);
    for (int i = 0; i < 8; ++i) {
      bytes[static_cast<std::size_t>(i)] = static_cast<unsigned char>(bits >> (8 * i));
    }
    add(bytes.data(), bytes.size());
  }
  std::string hex_digest() {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(context_.get(), digest.data(), &length) != 1) {
      throw std::runtime_error("SHA-256 finalisation failed");
    }
    static constexpr char hex[] = "0123456789abcdef";
    std::string text;
    for (unsigned int i = 0; i < length; ++i) {
      text += hex[digest[i] >> 4];
      text += hex[digest[i] & 15];
    }
    return text;
  }

private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context_;
};

void add_layout(Sha256& sha, const FieldSnapshot& field, std::uint64_t count) {
  sha.add_string(field.info.particle_set);
  sha.add_string(field.info.name);
  sha.add_integer(field.info.components);
  sha.add_integer(static_cast<std::int64_t>(count));
  sha.add_integer(field.info.scale.exponent());
  sha.add_integer(field.kind == RawKind::fixed_point ? 0 : 1);
}

void add_values(Sha256& sha, std::span<const std::int64_t> values) {
  if constexpr (std::endian::native == std::endian::little) {
    sha.add(values.data(), values.size() * sizeof(std::int64_t));
  } else {
    for (const std::int64_t value : values) {
      sha.add_integer(value);
    }
  }
}

} // namespace

std::string state_hash(const StateSnapshot& state) {
  Sha256 sha;
  if (state.pieces.empty()) {
    for (const FieldSnapshot& field : state.fields) {
      add_layout(sha, field, field.count);
      add_values(sha, field.raw());
    }
    return sha.hex_digest();
  }
  // Component-major, like the one-process hash: each component streamed in index order to
  // process 0, which alone hashes (the others' digest is discarded).
  constexpr std::size_t chunk = std::size_t{1} << 16;
  for (const FieldSnapshot& field : state.fields) {
    const SetRows* rows = state.rows_of(field.info.particle_set);
    if (rows == nullptr || rows->indices.size() != field.count) {
      throw std::invalid_argument("state_hash: no rows of particle set " + field.info.particle_set +
                                  " for field " + field.info.name);
    }
    add_layout(sha, field, rows->total);
    for (int c = 0; c < field.info.components; ++c) {
      distributed::stream_in_index_order(
          rows->indices,
          field.raw().subspan(static_cast<std::size_t>(c) * field.count, field.count), rows->total,
          chunk, [&sha](std::span<const std::int64_t> values) { add_values(sha, values); });
    }
  }
  return distributed::broadcast_from_first(sha.hex_digest());
}

} // namespace revsph
