#include "core/model_registry.hpp"
#include "models/shtc/parameters.hpp"
#include "models/shtc/setup.hpp"

namespace revsph {

void register_model_shtc(ModelRegistry& registry) {
  registry.add({"shtc",
                "SHTC-SPH for elastic solids and viscous fluids with a bit-reversible distortion "
                "step (Kincl, Peshkov, Pavelka, Klika 2023)",
                &shtc::create, &shtc::case_keys,
                "its distortion update is exact in integers (models/shtc/README.md)"});
}

} // namespace revsph
