// Reading input files, the one way every koppel reader takes (mechanisms, specs, poses, points,
// motor curves, charts, atlases): at most a stated number of bytes is read, whatever the file is
// (a regular file, a pipe, /dev/zero, a sparse file of 20 GB), and every file read is registered
// as an input of this process, so that no output of the same run replaces it (output_file.hpp).
// Problems are FileError (file_error.hpp) of kind kRefused.
#pragma once

#include "koppel/core/file_error.hpp"
#include "koppel/core/limits.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace koppel::io {

// An open input file. Opening registers it as an input (by device and inode, so a symbolic or a
// hard link to it is the same file); a file already claimed as an output of this run is refused.
class InputFile {
 public:
  // Throws FileError: cannot open, a directory, an output of this run. A FIFO without a writer
  // is not waited for: it reads as empty.
  explicit InputFile(std::string path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }
  // The size of a regular file; empty for a pipe or a device, whose size is known only by reading.
  std::optional<std::uint64_t> RegularFileSize() const { return regular_size_; }
  // Up to `count` more bytes: fewer only at the end of the file.
  std::string Read(std::size_t count);
  // The rest of the file; FileError when it holds more than `limit` bytes (a regular file is
  // refused by its size, before anything is read). `what` names the limit in the message.
  std::string ReadRest(std::size_t limit = kMaxInputBytes, const std::string& what = "kMaxInputBytes");

 private:
  [[noreturn]] void Fail(const std::string& reason) const;
  std::string path_;
  int fd_ = -1;
  std::uint64_t consumed_ = 0;  // bytes read so far
  std::optional<std::uint64_t> regular_size_;
};

// The whole of a text input: InputFile(path).ReadRest(kMaxInputBytes).
std::string ReadInputFile(const std::string& path);

}  // namespace koppel::io
