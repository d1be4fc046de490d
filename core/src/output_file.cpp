#include "koppel/core/output_file.hpp"

#include "koppel/core/temporary_files.hpp"
#include "file_registry.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace koppel::io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void Refuse(const std::string& path, const std::string& why) {
  throw FileError(FileError::Kind::kRefused, path, why, "will not write '" + path + "': " + why);
}

[[noreturn]] void WriteFailed(const std::string& path, int error) {
  const std::string why = std::strerror(error);
  throw FileError(FileError::Kind::kWriteFailed, path, why, "cannot write '" + path + "': " + why);
}

// Why an existing target may not be replaced; "" when it may.
std::string RefusalFor(const std::string& path, const struct stat& info) {
  if (S_ISLNK(info.st_mode)) return "it is a symbolic link (koppel never writes through one: name the file itself)";
  if (S_ISDIR(info.st_mode)) return "it is a directory";
  if (S_ISFIFO(info.st_mode)) return "it is a FIFO (leave out the file name to write to standard output)";
  if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode)) return "it is a device (leave out the file name to write to standard output)";
  if (S_ISSOCK(info.st_mode)) return "it is a socket";
  if (detail::IsInput({info.st_dev, info.st_ino})) return "it is an input file of this command";
  // what `>` would refuse: the rename would replace it all the same, so ask as the shell would
  if (::access(path.c_str(), W_OK) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(info.st_mode & 07777));
    return std::string("you may not write to it (mode ") + mode + ", owner uid " + std::to_string(info.st_uid) +
           "): koppel replaces only a file that `>` could write";
  }
  return "";
}

std::string Quoted(const std::string& text) {
  std::string quoted(1, '\'');
  quoted += text;
  quoted += '\'';
  return quoted;
}

fs::path FolderOf(const std::string& path) {
  const fs::path target(path);
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// A new file made by mkstemp (O_EXCL, an unpredictable name: a link planted in the folder is
// never followed) in `folder`, registered for removal on a signal. The signals wait while the
// file is made and registered, so neither can happen without the other.
struct Temporary {
  int fd = -1, slot = -1;
  std::string path;
};
Temporary MakeTemporary(const fs::path& folder, const std::string& name, const std::string& target) {
  Temporary t;
  t.path = (folder / ("." + name + ".koppel-XXXXXX")).string();
  sigset_t signals, old;
  sigemptyset(&signals);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, s);
  pthread_sigmask(SIG_BLOCK, &signals, &old);
  t.fd = ::mkstemp(t.path.data());
  const int error = errno;
  if (t.fd >= 0) t.slot = RegisterTemporaryFile(t.path.c_str());
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (t.fd < 0) Refuse(target, "cannot create a file in '" + folder.string() + "': " + std::strerror(error));
  return t;
}

void Discard(Temporary& t) {
  if (t.fd >= 0) ::close(t.fd);
  ::unlink(t.path.c_str());
  ForgetTemporaryFile(t.slot);
}

// Whether a file can be made in `folder`: made and removed at once.
void ProbeFolder(const fs::path& folder, const std::string& target) {
  Temporary probe = MakeTemporary(folder, "probe", target);
  Discard(probe);
}

// Writes all of `text` to fd; errno of the first failure, 0 on success.
int WriteAll(int fd, std::string_view text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    done += static_cast<size_t>(n);
  }
  return 0;
}

mode_t NewFileMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

void ClaimOutputFile(const std::string& path, const std::string& flag) {
  if (path.empty() || path == "-") return;
  if (!fs::path(path).has_filename()) Refuse(path, "it names a folder, not a file");
  struct stat existing {};
  const bool exists = ::lstat(path.c_str(), &existing) == 0;
  if (exists) {
    if (const std::string why = RefusalFor(path, existing); !why.empty()) Refuse(path, why);
  }
  ProbeFolder(FolderOf(path), path);
  const detail::FileIdentity file{existing.st_dev, existing.st_ino};
  std::error_code ec;
  const std::string absolute = fs::absolute(path, ec).lexically_normal().string();
  if (const std::string earlier = detail::NoteOutput(exists ? &file : nullptr, absolute, flag); !earlier.empty()) {
    Refuse(path, "it is also the output of " + earlier + " (one file cannot hold both)");
  }
}

void ClaimOutputDirectory(const std::string& path, const std::string& flag) {
  if (path.empty()) return;
  // the directory itself, or the nearest of its parents that exists: files will be made there
  fs::path existing = fs::path(path);
  struct stat info {};
  while (::stat(existing.c_str(), &info) != 0) {
    const int error = errno;
    const fs::path parent = existing.has_parent_path() ? existing.parent_path() : fs::path(".");
    if (error != ENOENT || parent == existing) Refuse(path, "cannot use it as the directory of " + flag + ": " + std::strerror(error));
    existing = parent;
  }
  if (!S_ISDIR(info.st_mode)) {
    const std::string what = S_ISREG(info.st_mode) ? "a file" : S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) ? "a device" : "not a directory";
    Refuse(path, (existing == fs::path(path) ? std::string("it") : Quoted(existing.string())) + " is " + what + ", and " + flag + " names a directory to write files into");
  }
  ProbeFolder(existing, path);
}

void MakeOutputDirectory(const std::string& path) {
  std::error_code ec;
  fs::create_directories(path, ec);
  if (ec) Refuse(path, "cannot make the directory: " + ec.message());
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  AtomicFileWriter file(path);
  file.Write(text);
  file.Commit();
}

AtomicFileWriter::AtomicFileWriter(const std::string& path) : path_(path) {
  const fs::path target(path);
  if (!target.has_filename()) Refuse(path, "it names a folder, not a file");
  struct stat existing {};
  const bool exists = ::lstat(path.c_str(), &existing) == 0;
  if (exists) {
    if (const std::string why = RefusalFor(path, existing); !why.empty()) Refuse(path, why);
  }
  Temporary t = MakeTemporary(FolderOf(path), target.filename().string(), path);
  fd_ = t.fd;
  slot_ = t.slot;
  temporary_ = std::move(t.path);
  open_ = true;
  // an existing file keeps its permissions; a new one gets the usual 0666 less the umask
  mode_ = exists ? existing.st_mode & 0777 : NewFileMode();
}

AtomicFileWriter::~AtomicFileWriter() {
  if (!open_) return;
  Temporary t{fd_, slot_, temporary_};
  Discard(t);
}

void AtomicFileWriter::Write(std::string_view bytes) {
  if (!open_) throw std::logic_error("koppel: AtomicFileWriter::Write after Commit or a failure");
  if (const int error = WriteAll(fd_, bytes); error != 0) {
    Temporary t{fd_, slot_, temporary_};
    open_ = false;
    Discard(t);
    WriteFailed(path_, error);
  }
}

void AtomicFileWriter::Commit() {
  if (!open_) throw std::logic_error("koppel: AtomicFileWriter::Commit after Commit or a failure");
  int error = 0;
  if (::fchmod(fd_, static_cast<mode_t>(mode_)) != 0) error = errno;
  if (error == 0 && ::fsync(fd_) != 0) error = errno;
  if (::close(fd_) != 0 && error == 0) error = errno;
  fd_ = -1;
  if (error == 0 && ::rename(temporary_.c_str(), path_.c_str()) != 0) error = errno;
  open_ = false;
  Temporary t{-1, slot_, temporary_};
  if (error != 0) {
    Discard(t);
    WriteFailed(path_, error);
  }
  ForgetTemporaryFile(slot_);
}

}  // namespace koppel::io
