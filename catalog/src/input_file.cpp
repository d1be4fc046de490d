#include "input_file.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/limits.hpp"

#include <yaml-cpp/eventhandler.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace koppel {
namespace {

[[noreturn]] void Fail(const std::string& file, const std::string& message, int line = 0, int column = 0) {
  throw InputError({Diagnostic{file, line, column, "", message}});
}

// Counts the nesting of maps and lists as the parser meets them and stops the parse at the
// limit, before the node tree of a deep file is built.
class DepthCheck : public YAML::EventHandler {
 public:
  struct TooDeep {
    YAML::Mark mark;
  };
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override { Enter(mark); }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override { Enter(mark); }
  void OnMapEnd() override { --depth_; }

 private:
  void Enter(const YAML::Mark& mark) {
    if (++depth_ > kMaxYamlDepth) throw TooDeep{mark};
  }
  int depth_ = 0;
};

}  // namespace

std::string ReadInputText(const std::string& path) {
  // O_NONBLOCK: opening a FIFO that has no writer must not wait for one
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) Fail(path, std::string("cannot open file: ") + std::strerror(errno));
  struct stat info {};
  if (::fstat(fd, &info) != 0 || S_ISDIR(info.st_mode)) {
    ::close(fd);
    Fail(path, "cannot read: it is a directory, not a mechanism file");
  }
  // reads block again (a pipe's writer may be slow); a FIFO without a writer reads as empty
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  char buffer[65536];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      Fail(path, std::string("cannot read file: ") + std::strerror(error));
    }
    if (n == 0) break;
    if (text.size() + static_cast<size_t>(n) > kMaxInputBytes) {
      ::close(fd);
      Fail(path, "the file is larger than the input limit of " + std::to_string(kMaxInputBytes) +
                     " bytes (kMaxInputBytes, see README 'Limits'); is it a mechanism file?");
    }
    text.append(buffer, static_cast<size_t>(n));
  }
  ::close(fd);
  return text;
}

YAML::Node ParseYamlText(const std::string& text, const std::string& file_name) {
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    DepthCheck depth;
    parser.HandleNextDocument(depth);
    return YAML::Load(text);
  } catch (const DepthCheck::TooDeep& deep) {
    Fail(file_name, "the YAML nests deeper than the limit of " + std::to_string(kMaxYamlDepth) + " levels (kMaxYamlDepth)",
         deep.mark.line + 1, deep.mark.column + 1);
  } catch (const YAML::Exception& e) {
    Fail(file_name, "YAML syntax error: " + e.msg, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1);
  }
}

}  // namespace koppel
