#include "core/model_registry.hpp"

namespace revsph {

// SHTC-SPH (issue 6) is being built: so far the exactly invertible distortion update
// (distortion.hpp). The model registers itself here once its time step and cases exist; until
// then `revsph cases` does not list it.
void register_model_shtc(ModelRegistry&) {}

} // namespace revsph
