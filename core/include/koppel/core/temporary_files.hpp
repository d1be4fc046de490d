// Temporary files that must not outlive the process: those of atomic writes (output_file.hpp).
// They are kept in a fixed table that a signal handler can read without allocating or locking,
// so that SIGINT, SIGTERM or SIGHUP removes them before the process dies by that signal.
#pragma once

namespace koppel::io {

// At most this many at once: a command writes its files one after the other.
inline constexpr int kMaxTemporaryFiles = 32;
// The longest path the table holds (Linux PATH_MAX).
inline constexpr int kMaxTemporaryPath = 4096;

// Registers an existing temporary file; the slot to forget it by, or -1 when the table is full or
// the path too long (the file is then not removed on a signal).
int RegisterTemporaryFile(const char* path);
// Forgets the slot (the file was renamed into place or removed). -1 is ignored.
void ForgetTemporaryFile(int slot);

// Installs, once, handlers for SIGINT, SIGTERM and SIGHUP that unlink every registered
// temporary file, restore the default action and raise the signal again, so the process still
// dies by it (a shell sees 128 + the signal). A signal the process inherited as ignored (nohup,
// a background job) stays ignored. For programs (the CLI); the library never installs handlers
// by itself.
void RemoveTemporaryFilesOnSignals();

}  // namespace koppel::io
