#pragma once
// The pieces a model's class is written with, in one include: the Model concept and its parts
// (simulation.hpp, model_parts.hpp), the step (step_composition.hpp, step_splitting.hpp), the
// state's fields, the ones many models share and the slot layout (carrier_field.hpp,
// common_fields.hpp, slot_layout.hpp), the kernel and the
// pair loop (kernel_wendland.hpp, pair_sum.hpp), energies, their exact totals and output views
// (energy.hpp, global_totals.hpp, particle_view.hpp). docs/adding-a-model.md walks through them.

#include "core/carrier_field.hpp"
#include "core/common_fields.hpp"
#include "core/energy.hpp"
#include "core/global_totals.hpp"
#include "core/kernel_wendland.hpp"
#include "core/model_parts.hpp"
#include "core/pair_sum.hpp"
#include "core/particle_view.hpp"
#include "core/simulation.hpp"
#include "core/slot_layout.hpp"
#include "core/step_composition.hpp"
#include "core/step_splitting.hpp"
