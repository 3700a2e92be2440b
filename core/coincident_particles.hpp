#pragma once
// Particles of two [[particles]] blocks at the same place: overlapping blocks. Fluid over fluid
// would double the mass there without a word, fluid over a wall ends in an overflow that does not
// say why; both are refused at set-up with one line naming the two blocks.

#include "core/case_file.hpp"
#include "core/particle_blocks.hpp"

#include <vector>

namespace revsph {

// Fails (CaseError on the later block's key) if a particle of one block lies closer than
// 1e-6 of the smaller block spacing to a particle of another.
template <int D>
void refuse_coincident_particles(const CaseFile& case_file,
                                 const std::vector<ParticleBlock<D>>& blocks);

} // namespace revsph
