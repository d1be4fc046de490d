#include "koppel/core/input_file.hpp"

#include "file_registry.hpp"

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace koppel::io {
namespace {

constexpr std::size_t kChunk = 65536;  // bytes per read(2)

}  // namespace

InputFile::InputFile(std::string path) : path_(std::move(path)) {
  // O_NONBLOCK: opening a FIFO that has no writer must not wait for one
  fd_ = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) Fail(std::string("cannot open file: ") + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd_, &info) != 0) Fail(std::string("cannot read file: ") + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) Fail("cannot read: it is a directory, not a file");
  if (S_ISREG(info.st_mode)) regular_size_ = static_cast<std::uint64_t>(info.st_size);
  // the identity of what was opened, not of the name: no race with a rename in between
  if (const std::string flag = detail::NoteInput({info.st_dev, info.st_ino}, path_); !flag.empty()) {
    Fail("this input file is also named as the output of " + flag + ": koppel never writes over a file it reads");
  }
  // reads block again (a pipe's writer may be slow); a FIFO without a writer reads as empty
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

void InputFile::Fail(const std::string& reason) const { throw FileError(FileError::Kind::kRefused, path_, reason, path_ + ": " + reason); }

std::string InputFile::Read(std::size_t count) {
  std::string bytes;
  char buffer[kChunk];
  while (bytes.size() < count) {
    const ssize_t n = ::read(fd_, buffer, std::min(sizeof buffer, count - bytes.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) Fail(std::string("cannot read file: ") + std::strerror(errno));
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  consumed_ += bytes.size();
  return bytes;
}

std::string InputFile::ReadRest(std::size_t limit, const std::string& what) {
  const std::string too_large = "the file is larger than the input limit of " + std::to_string(limit) + " bytes (" + what +
                                ", see README 'Limits'): is it the file you meant?";
  if (regular_size_ && *regular_size_ > consumed_ + limit) Fail(too_large);
  // one byte past the limit tells a file at the limit from a larger one (a pipe, a device)
  std::string text = Read(limit + 1);
  if (text.size() > limit) Fail(too_large);
  return text;
}

std::string ReadInputFile(const std::string& path) { return InputFile(path).ReadRest(); }

}  // namespace koppel::io
