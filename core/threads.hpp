#pragma once
// Thread count of the parallel loops (OpenMP). Results never depend on it: every parallel loop
// writes per-particle results whose value is computed by one thread in a fixed order, and sums
// across particles are exact integers or done serially.

namespace revsph {

void set_thread_count(int threads);
int thread_count();

} // namespace revsph
