#pragma once
// How long an idle OpenMP thread spins at a barrier before it sleeps: long on an idle machine,
// short on a shared one.
//
// A step crosses a dozen barriers or more. libgomp's default spins about 300 000 times before
// sleeping; on a machine shared with another run, a spinning thread then holds a core while the
// thread it waits for has none, and two concurrent 2-thread runs of dambreak-small on 2 cores took
// 4 to 10 times as long as one after the other (so did `ctest -j2`: two 2-thread test programs at
// once). No single spin count suits both cases. Measured on a 2-core VM with the 2-thread test
// Superfluid.SecondSoundReturnsBitwiseOnOneAndTwoThreads
// (tools/bench/results/issue31-ctest-2026-11-27.md):
//   spins     alone    two at once (both)   beside a busy 1-thread loop
//   1 000     7.3 s    15.1 s               14.0 s
//   100       11.3 s   10.3 s               10.8 s
//   0         11.7 s   10.1 s               10.4 s
// Alone, a thread that sleeps at once wakes slowly (an idle core's wake-up); shared, one that
// spins holds the core its partner needs. So the program looks before it starts: if another task
// stays runnable over a few samples of /proc/loadavg (a run, a test program beside it), its
// threads spin 100 times, else 1 000.
//
// libgomp reads GOMP_SPINCOUNT once, when it loads, before main: so if the user set neither it
// nor OMP_WAIT_POLICY, the program sets it and executes itself again (same pid, same arguments).
// Every program that links revsph_core does this before main (openmp_waiting.cpp: the core's
// link options pull it in), the revsph command, the test programs and a user's own alike; set
// GOMP_SPINCOUNT or OMP_WAIT_POLICY yourself to keep your own choice.

#include <string>

namespace revsph {

// The spin count for a machine on which `other_runnable` tasks besides this program want a core.
const char* openmp_spin_count_for(int other_runnable);

// The fewest runnable tasks other than this one seen in a few samples of /proc/loadavg a
// millisecond apart (0 where it cannot be read).
int other_runnable_tasks();

// How this program's threads wait, for the run's log: "spin count N" (GOMP_SPINCOUNT, chosen
// here or by the user), "OMP_WAIT_POLICY=..." or "libgomp's default".
std::string openmp_waiting_description();

// Returns only if nothing had to be changed or the re-execution failed (then the program goes on
// with libgomp's defaults).
void choose_openmp_spinning(char** argv);

} // namespace revsph
