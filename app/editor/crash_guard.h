// The crash guard: on SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL, SIGTERM, SIGINT or SIGHUP it writes
// the latest published recovery document to the recovery file, then lets the signal do what it
// would have done. The handler only calls async-signal-safe functions (open, write, fsync,
// close, rename, signal, raise) on text serialised beforehand; it never serialises or allocates.
// SIGKILL cannot be caught: periodic autosave covers it.
#pragma once

#include <string>

namespace glint {

// Installs the handlers; `recoveryPath` is copied into a fixed buffer now. Its directory must
// exist already (the handler only opens, writes and renames).
void installCrashGuard(const std::string& recoveryPath);
// Publishes the text the handler would write; empty text means "nothing to save".
void publishCrashCopy(const std::string& text);
// Removes the handlers (restores the defaults) and forgets the published text.
void uninstallCrashGuard();

}  // namespace glint
