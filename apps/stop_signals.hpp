#pragma once
// SIGINT and SIGTERM as a request to stop after the current step, for the commands that run long
// (run, render): the first one sets a flag the library checks between steps and images
// (lib/stop_request.hpp), so that every file written is complete; a second one of either ends the
// process at once, as the signal would have without the handler.

#include "lib/stop_request.hpp"

namespace tissu {

/// Installs the handlers (once per process) and ignores SIGXFSZ, so that a file size limit
/// (ulimit -f) makes writes fail with EFBIG, which tissu reports, instead of killing the process.
/// Returns the request the handlers set: its flag holds the signal number once one arrived.
StopRequest install_stop_signals();

/// The exit status for a run stopped by signal `signal_number`: 128 + the number (130 for SIGINT,
/// 143 for SIGTERM), as a shell reports a process the signal ended.
int stopped_exit_status(int signal_number);

/// "SIGINT", "SIGTERM", or "a signal" for any other.
const char* signal_name(int signal_number);

}  // namespace tissu
