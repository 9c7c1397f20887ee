#pragma once
/// \file
/// OpenMP's waiting policy for the tissu programs.

namespace tissu {

/// Makes the program run with OMP_WAIT_POLICY=passive unless the user chose a policy: sets it and
/// executes the program again (/proc/self/exe, same arguments), since libgomp reads it once,
/// before main. With the default (active) policy every idle OpenMP thread spins at each of the
/// solver's many short barriers; beside any other busy process on the machine the spinning
/// threads take the cores from the working ones, and two threads ran 2 to 3 times slower than
/// one (docs/benchmarks.md, "Threads beside a busy process, with passive waiting"). Returns
/// normally if OMP_WAIT_POLICY or GOMP_SPINCOUNT is already set, or if the program cannot be
/// executed again (it then runs with OpenMP's default).
/// Call first in main, before any OpenMP call.
void prefer_passive_openmp_waiting(char** argv);

}  // namespace tissu
