#include "core/model_registry.hpp"
#include "models/two_fluid/parameters.hpp"
#include "models/two_fluid/setup.hpp"

namespace revsph {

void register_model_two_fluid(ModelRegistry& registry) {
  registry.add({"two_fluid", "helium II as superfluid and normal particles (Tsuzuki 2021)",
                &two_fluid::create, &two_fluid::case_keys});
}

} // namespace revsph
