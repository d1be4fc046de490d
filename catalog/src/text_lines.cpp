#include "text_lines.hpp"

namespace koppel {

std::vector<TextLine> SplitLines(const std::string& text) {
  std::vector<TextLine> lines;
  std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  for (int number = 1; start <= text.size(); ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (end < text.size() || !line.empty()) lines.push_back({number, std::move(line)});
    start = end + 1;
  }
  return lines;
}

std::vector<TextField> SplitFields(const std::string& line, char separator) {
  std::vector<TextField> fields;
  std::size_t start = 0;
  while (true) {
    std::size_t end = line.find(separator, start);
    if (end == std::string::npos) end = line.size();
    std::size_t first = start, last = end;
    while (first < last && (line[first] == ' ' || line[first] == '\t')) ++first;
    while (last > first && (line[last - 1] == ' ' || line[last - 1] == '\t')) --last;
    fields.push_back({line.substr(first, last - first), static_cast<int>(first) + 1});
    if (end == line.size()) break;
    start = end + 1;
  }
  return fields;
}

}  // namespace koppel
