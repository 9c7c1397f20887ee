#pragma once
/// \file
/// OpenMP's waiting policy for the tissu programs.

namespace tissu {

/// libgomp's spin count for the tissu programs: an idle OpenMP thread spins this many times
/// (about 0.1 ms here) before it sleeps. That carries it through a step's back-to-back parallel
/// loops, which passive waiting (0) woke it for one by one at about 80 µs each on a virtual
/// machine, while it still sleeps between frames. libgomp's default, 300,000, spins for
/// milliseconds: beside a busy process the spinning threads take the cores from the working ones.
/// Beside such a process the programs run one thread (FrameThreadChooser), which nothing waits
/// for. Measured in docs/benchmarks.md, "2026-12-07".
inline constexpr const char* tissu_spin_count = "10000";

/// Makes the program run with GOMP_SPINCOUNT=tissu_spin_count unless the user chose a policy
/// (OMP_WAIT_POLICY or GOMP_SPINCOUNT is set): sets it and executes the program again
/// (/proc/self/exe, same arguments), since libgomp reads it once, before main. Returns normally
/// if the user chose, or if the program cannot be executed again (it then runs with OpenMP's
/// default). Call first in main, before any OpenMP call.
void prefer_short_openmp_spin(char** argv);

}  // namespace tissu
