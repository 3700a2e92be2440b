#include "core/model_registry.hpp"
#include "models/wcsph/parameters.hpp"
#include "models/wcsph/setup.hpp"

namespace revsph {

void register_model_wcsph(ModelRegistry& registry) {
  registry.add({"wcsph",
                "symplectic weakly compressible SPH with conservative walls (Kincl & Pavelka 2023)",
                &wcsph::create, &wcsph::case_keys});
}

} // namespace revsph
