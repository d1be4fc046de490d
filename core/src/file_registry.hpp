// The files of this process's run (private to the file rules, input_file.cpp and
// output_file.cpp): the inputs it opened and the outputs it claimed, each by device and inode so
// that a symbolic or hard link names the same file. An entry whose path no longer leads to its
// inode (the file was removed and the inode reused: tests, a long-lived Python process) is
// dropped when met. Guarded by a mutex: readers may run on several threads.
#pragma once

#include <string>
#include <sys/types.h>

namespace koppel::io::detail {

struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  bool operator==(const FileIdentity&) const = default;
};

// Records an input opened by `path`; the flag of an output claimed earlier that is the same
// file, or "".
std::string NoteInput(FileIdentity file, const std::string& path);
bool IsInput(FileIdentity file);
// Records an output target claimed by `flag`: an existing file by identity, and in any case by
// its absolute lexical path. The flag of an earlier claim of the same target, or "".
std::string NoteOutput(const FileIdentity* existing, const std::string& absolute_path, const std::string& flag);

}  // namespace koppel::io::detail
