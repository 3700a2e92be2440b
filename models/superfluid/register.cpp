#include "core/model_registry.hpp"
#include "models/superfluid/parameters.hpp"
#include "models/superfluid/setup.hpp"

namespace revsph {

void register_model_superfluid(ModelRegistry& registry) {
  registry.add({"superfluid",
                "superfluid helium-4, one particle with two velocities (Kincl, Schmoranzer & "
                "Pavelka 2023)",
                &superfluid::create, &superfluid::case_keys});
}

} // namespace revsph
