// Writing output files (README "Output files"). A command names its outputs first: each target
// is claimed before any input is read or any work begins, so a refusal costs nothing and no file
// is ever half written. A claimed target is refused (FileError kRefused) when it
//   - is a symbolic link (never written through), a directory, a FIFO, a device or a socket;
//   - is a file this run reads (input_file.hpp: by device and inode, so also through a symbolic
//     or a hard link), or a target claimed twice;
//   - is a file the user could not write with `>` (access(2): mode 0444, another user's file);
//   - lies in a folder where no file can be made (missing, no permission, /proc): tried by
//     making and removing a temporary file there.
// A write replaces the target only by rename(2) of a complete temporary file (mkstemp: O_EXCL, an
// unpredictable name, in the target's folder), registered for removal should a signal end the
// process (temporary_files.hpp); any failure removes it and leaves the old file as it was.
#pragma once

#include "koppel/core/file_error.hpp"

#include <string>
#include <string_view>

namespace koppel::io {

// Claims `path` as the output file named by `flag` ("-o", "--error-curve"). "" and "-" stand for
// standard output and always pass.
void ClaimOutputFile(const std::string& path, const std::string& flag);

// Claims `path` as a directory files are written into (-o DIR): refused when it exists and is
// not a directory (a file, /dev/null), or when it cannot be made or no file can be made in it.
void ClaimOutputDirectory(const std::string& path, const std::string& flag);

// Makes the directory and its missing parents. Throws FileError.
void MakeOutputDirectory(const std::string& path);

// Writes `text` to `path` atomically, with the checks of ClaimOutputFile (a target may have
// changed since it was claimed, and files inside an output directory are checked only here).
// The permissions of a replaced file are kept; a new file gets 0666 less the umask.
// FileError kRefused for a target that may not be written, kWriteFailed when writing failed.
void WriteFileAtomically(const std::string& path, const std::string& text);

// The same write in pieces, for a text too long to hold whole (analyze's millions of rows): the
// checks and the temporary file at construction, Write() appends to the temporary, Commit()
// replaces the target. Destroyed before Commit (an exception, an early exit) it removes the
// temporary and leaves the target as it was. Throws FileError as WriteFileAtomically does.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(const std::string& path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void Write(std::string_view bytes);
  void Commit();

 private:
  std::string path_, temporary_;
  int fd_ = -1, slot_ = -1;
  unsigned mode_ = 0;  // the permissions the target gets (mode_t)
  bool open_ = false;  // the temporary exists and is not yet renamed
};

}  // namespace koppel::io
