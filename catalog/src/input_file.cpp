#include "input_file.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/core/input_file.hpp"
#include "koppel/core/limits.hpp"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <limits>
#include <sstream>

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
  try {
    return io::ReadInputFile(path);
  } catch (const io::FileError& e) {
    Fail(path, e.reason());
  }
}

int YamlNestingBound(const std::string& text) {
  long long flow_opens = 0;
  size_t max_p = 0;
  bool at_line_start = true;  // still in the leading run of the line (p not yet found)
  size_t column = 0;
  for (const char c : text) {
    if (c == '[' || c == '{') ++flow_opens;
    if (c == '\n') {
      at_line_start = true;
      column = 0;
      continue;
    }
    if (at_line_start) {
      if (c == ' ' || c == '\t' || c == '-' || c == '?' || c == ':' || c == '\r') {
        ++column;
        max_p = std::max(max_p, column);  // a line of these alone: p is its length
      } else {
        at_line_start = false;
      }
    }
  }
  // + 2: a map whose first key follows an anchor or a tag on its line ("- &x a: 1") starts after
  // p; it can hold no further block collection on that line, nor start one there
  const long long bound = 2 * (static_cast<long long>(max_p) + 1) + 2 + flow_opens;
  return static_cast<int>(std::min<long long>(bound, std::numeric_limits<int>::max()));
}

YAML::Node ParseYamlText(const std::string& text, const std::string& file_name) {
  try {
    if (YamlNestingBound(text) > kMaxYamlDepth) {
      // perhaps too deep: count the depth on the parser's events before building the tree
      std::istringstream in(text);
      YAML::Parser parser(in);
      DepthCheck depth;
      parser.HandleNextDocument(depth);
    }
    return YAML::Load(text);
  } catch (const DepthCheck::TooDeep& deep) {
    Fail(file_name, "the YAML nests deeper than the limit of " + std::to_string(kMaxYamlDepth) + " levels (kMaxYamlDepth)",
         deep.mark.line + 1, deep.mark.column + 1);
  } catch (const YAML::Exception& e) {
    Fail(file_name, "YAML syntax error: " + e.msg, e.mark.is_null() ? 0 : e.mark.line + 1, e.mark.is_null() ? 0 : e.mark.column + 1);
  }
}

}  // namespace koppel
