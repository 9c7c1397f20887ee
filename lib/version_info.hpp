#pragma once
/// \file
/// Which tissu this is, for `tissu --version` and the run folder's run.json.

namespace tissu {

/// The project's version, "0.1.0" (CMakeLists.txt).
const char* tissu_version();
/// The git commit the program was built from, with "-dirty" when it had uncommitted changes;
/// "unknown" outside a git checkout.
const char* tissu_commit();

}  // namespace tissu
