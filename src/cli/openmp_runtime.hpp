// How long an idle OpenMP thread spins before it sleeps. libgomp's default spins for a long time (300,000 rounds,
// or indefinitely with OMP_WAIT_POLICY=active) so that it wakes fast, which is right on a machine of its own. Beside
// other work, the default makes mistfall 20 times slower: a thread spinning on a busy core
// holds the core its partner needs. Measured on the 2-core machine (waterfall_small, 2 threads):
//
//   | GOMP_SPINCOUNT        | idle: steps/s, 0-0.5 s | one core busy: steps/s, 0-0.2 s |
//   |-----------------------|------------------------|---------------------------------|
//   | unset (libgomp's)     | 69-71                  | 4.2                             |
//   | 100000                | 70                     | 7.5                             |
//   | 10000                 | 72                     | 38                              |
//   | 1000 (mistfall's)     | 71-72                  | 73                              |
//   | OMP_WAIT_POLICY=passive | 64                   | 81                              |
//
// libgomp reads its settings when it loads, before main(): so when neither GOMP_SPINCOUNT nor OMP_WAIT_POLICY is
// set, mistfall sets GOMP_SPINCOUNT=1000 and executes itself again (a user's own setting is left alone).
#pragma once

namespace mistfall {

// Call first in main(). Returns only when nothing had to change (or re-executing failed: then it carries on with
// libgomp's defaults).
void useShortOpenMpSpin(char** argv);

}  // namespace mistfall
