#include "core/model_registry.hpp"
#include "models/entropic/parameters.hpp"
#include "models/entropic/setup.hpp"

namespace revsph {

void register_model_entropic(ModelRegistry& registry) {
  registry.add(
      {"entropic", "entropic SPH: particles that carry entropy (Pavelka, Klika, Kincl 2024)",
       &entropic::create, &entropic::case_keys,
       "its kick adds exact pair impulses to integer momenta (models/entropic/model.hpp)"});
}

} // namespace revsph
