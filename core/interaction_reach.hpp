#pragma once
// How far a particle's influence reaches in one pair pass: the largest radius any pair or
// neighbour list of this process was built for. A distributed run (docs/design/distributed.md)
// gives each process the other processes' particles within that reach as ghosts; it reads the
// reach after the setup has built every list once, and from then on a list over a larger radius
// would miss ghosts, so it is refused (a logic error, never a silently wrong sum).

namespace revsph {

// Called by every list build (core/pair_list.cpp, core/neighbour_list.cpp). Throws
// std::logic_error for a radius beyond the limit, once one is set.
void note_interaction_radius(double radius);
double largest_interaction_radius();
// From now on, a list over a radius larger than `reach` is refused (0: no limit).
void limit_interaction_radius(double reach);
// No limit and no radius seen: a new simulation in the same program (a test's next case, say)
// starts from nothing another one left behind.
void forget_interaction_radii();

} // namespace revsph
