#pragma once
// Particles at the same place: two [[particles]] blocks overlapping, or two rows of one point
// file. Fluid over fluid would double the mass there without a word (and a point file's values
// reach only one of the two), fluid over a wall ends in an overflow that does not say why; all
// are refused at set-up with one line naming the blocks.

#include "core/case_file.hpp"
#include "core/particle_blocks.hpp"

#include <vector>

namespace revsph {

// Fails (CaseError on the later block's key) if a particle lies closer than 1e-6 of the smallest
// block spacing to another particle, of its own block or another.
template <int D>
void refuse_coincident_particles(const CaseFile& case_file,
                                 const std::vector<ParticleBlock<D>>& blocks);

} // namespace revsph
