#pragma once
// The one fault every process of a distributed run reports when some of them found faults at
// the same point of a step (FaultRecorder::throw_if_any, a shared SimulationFault): the one of
// the lowest particle index in the whole state (then the set's name, the variable, the reason),
// so that the message is the same for any decomposition, as one process keeps its lowest index
// (docs/design/distributed.md, piece 6).

#include "core/fault.hpp"

#include <optional>

namespace revsph::distributed {

// `mine`: this process's fault with its particle's global index, or none (collective).
FaultDescription agreed_fault(const std::optional<FaultDescription>& mine);

} // namespace revsph::distributed
