// Output files and standard output: the rules of WriteOutput (common.hpp) and README "Output
// files". A target is replaced only by rename(2) of a complete temporary file, so a reader never
// sees half a file and a failure leaves the old file (or nothing) behind.
#include "common.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace koppel::cli {
namespace {

std::vector<std::pair<dev_t, ino_t>>& InputFiles() {
  static std::vector<std::pair<dev_t, ino_t>> files;
  return files;
}

bool stdout_failure_reported = false;

[[noreturn]] void Refuse(const std::string& path, const std::string& why) {
  Complain("will not write '" + path + "': " + why);
  throw Exit{kExitBadInput};
}

[[noreturn]] void WriteFailed(const std::string& path, int error) {
  Complain("cannot write '" + path + "': " + std::strerror(error));
  throw Exit{kExitFailed};
}

// What an existing target is, when it may not be replaced.
std::string RefusalFor(const struct stat& info) {
  if (S_ISLNK(info.st_mode)) return "it is a symbolic link (koppel never writes through one: name the file itself)";
  if (S_ISDIR(info.st_mode)) return "it is a directory";
  if (S_ISFIFO(info.st_mode)) return "it is a FIFO (leave out -o to write to standard output)";
  if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode)) return "it is a device (leave out -o to write to standard output)";
  if (S_ISSOCK(info.st_mode)) return "it is a socket";
  for (const auto& [device, inode] : InputFiles()) {
    if (info.st_dev == device && info.st_ino == inode) return "it is an input file of this command";
  }
  return "";
}

void WriteStandardOutput(const std::string& text) {
  std::cout << text;
  std::cout.flush();
  // std::cout shares stdout's buffer: a full disk or closed pipe shows in the stream or in fflush
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int error = errno;
    stdout_failure_reported = true;
    Complain(std::string("cannot write to standard output: ") + std::strerror(error ? error : EIO));
    throw Exit{kExitFailed};
  }
}

// Writes all of `text` to fd; errno of the first failure, 0 on success.
int WriteAll(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    done += static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

void NoteInputFile(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) InputFiles().emplace_back(info.st_dev, info.st_ino);
}

void WriteOutput(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") return WriteStandardOutput(text);
  struct stat existing {};
  const bool exists = ::lstat(path.c_str(), &existing) == 0;
  if (exists) {
    if (const std::string why = RefusalFor(existing); !why.empty()) Refuse(path, why);
  }
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  if (!target.has_filename()) Refuse(path, "it names a folder, not a file");
  // an unpredictable name created with O_EXCL: a link planted in the folder is never followed
  std::string hidden_name = ".";
  hidden_name += target.filename().string();
  hidden_name += ".koppel-XXXXXX";
  std::string temporary = (folder / hidden_name).string();
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) Refuse(path, "cannot create a file in '" + folder.string() + "': " + std::strerror(errno));
  // an existing file keeps its permissions; a new one gets the usual 0666 less the umask
  mode_t mode = existing.st_mode & 0777;
  if (!exists) {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  int error = WriteAll(fd, text);
  if (error == 0 && ::fchmod(fd, mode) != 0) error = errno;
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    WriteFailed(path, error);
  }
}

int FinishStandardOutput(int code) {
  errno = 0;
  const bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  const int error = errno;
  if (std::fclose(stdout) != 0 && !failed && !stdout_failure_reported) {
    Complain(std::string("cannot write to standard output: ") + std::strerror(errno ? errno : EIO));
    return code == kExitOk ? kExitFailed : code;
  }
  if (failed && !stdout_failure_reported) {
    Complain(std::string("cannot write to standard output: ") + std::strerror(error ? error : EIO));
    return code == kExitOk ? kExitFailed : code;
  }
  return code;
}

}  // namespace koppel::cli
