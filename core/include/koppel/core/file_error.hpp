// The one exception of koppel's file rules (input_file.hpp, output_file.hpp): a file that may not
// be read or written, or a write that failed. what() is the whole message a user reads, with the
// path; kind says which exit code it earns (bad input 2, a failed write 1).
#pragma once

#include <stdexcept>
#include <string>

namespace koppel::io {

class FileError : public std::runtime_error {
 public:
  enum class Kind {
    kRefused,      // bad input: an unreadable or oversized input, an output target koppel will not replace
    kWriteFailed,  // the write itself failed (full disk, file too large): the old file is left as it was
  };
  FileError(Kind kind, std::string path, std::string reason, const std::string& message)
      : std::runtime_error(message), kind_(kind), path_(std::move(path)), reason_(std::move(reason)) {}
  Kind kind() const { return kind_; }
  const std::string& path() const { return path_; }
  // The message without the path ("cannot open file: No such file or directory").
  const std::string& reason() const { return reason_; }

 private:
  Kind kind_;
  std::string path_, reason_;
};

}  // namespace koppel::io
