#pragma once
// How long an idle OpenMP thread spins at a barrier before it sleeps.
//
// A step crosses a dozen barriers or more. libgomp's default spins about 300 000 times before
// sleeping; on a machine shared with another run, a spinning thread then holds a core while the
// thread it waits for has none, and two concurrent 2-thread runs of dambreak-small on 2 cores took
// 4 to 10 times as long as one after the other (so did `ctest -j2`: two 2-thread test programs at
// once). OMP_WAIT_POLICY=passive fixes that but makes a run alone 2.5 times slower (every barrier
// a sleep and a wake-up). Spinning 1 000 times keeps a run alone as fast as the default and two
// concurrent runs within about 1.2-1.7 times the sequential time
// (tools/bench/results/issue15-core-redesign-2026-11-23.md).
//
// libgomp reads GOMP_SPINCOUNT once, when it loads, before main: so if the user set neither it
// nor OMP_WAIT_POLICY, the program sets it and executes itself again (same pid, same arguments).
// Every program that links revsph_core does this before main (openmp_waiting.cpp: the core's
// link options pull it in), the revsph command, the test programs and a user's own alike; set
// GOMP_SPINCOUNT or OMP_WAIT_POLICY yourself to keep your own choice.

namespace revsph {

// Returns only if nothing had to be changed or the re-execution failed (then the program goes on
// with libgomp's defaults).
void use_short_openmp_spinning(char** argv);

} // namespace revsph
