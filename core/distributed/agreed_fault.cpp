#include "core/distributed/agreed_fault.hpp"

#include "core/distributed/records_of_every_process.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <tuple>

namespace revsph::distributed {

namespace {

// A fault as a fixed-size record: the texts one after the other, each ended by a zero (cut to
// fit: a set's name, a variable's and a reason are short).
struct FaultRecord {
  std::uint64_t particle = 0;
  std::uint32_t found = 0;
  std::array<char, 500> texts{};
};

FaultRecord record_of(const std::optional<FaultDescription>& fault) {
  FaultRecord record;
  if (!fault) {
    return record;
  }
  record.found = 1;
  record.particle = fault->particle;
  std::size_t at = 0;
  for (const std::string* text : {&fault->particle_set, &fault->variable, &fault->reason}) {
    const std::size_t room = record.texts.size() - at - 1;
    const std::size_t length = std::min(text->size(), room);
    std::copy_n(text->data(), length, record.texts.data() + at);
    at += length + 1; // the zero the array holds already
    if (at >= record.texts.size()) {
      break;
    }
  }
  return record;
}

FaultDescription description_of(const FaultRecord& record) {
  FaultDescription fault;
  fault.particle = record.particle;
  std::size_t at = 0;
  for (std::string* text : {&fault.particle_set, &fault.variable, &fault.reason}) {
    if (at >= record.texts.size()) {
      break;
    }
    *text = std::string(record.texts.data() + at);
    at += text->size() + 1;
  }
  return fault;
}

} // namespace

FaultDescription agreed_fault(const std::optional<FaultDescription>& mine) {
  const FaultRecord record = record_of(mine);
  const std::vector<FaultRecord> all =
      records_of_every_process(std::span<const FaultRecord>(&record, 1));
  std::optional<FaultDescription> lowest;
  for (const FaultRecord& other : all) {
    if (other.found == 0) {
      continue;
    }
    FaultDescription fault = description_of(other);
    const auto key = [](const FaultDescription& f) {
      return std::tie(f.particle, f.particle_set, f.variable, f.reason);
    };
    if (!lowest || key(fault) < key(*lowest)) {
      lowest = std::move(fault);
    }
  }
  return lowest.value_or(FaultDescription{"", 0, "", "a fault no process kept"});
}

} // namespace revsph::distributed
