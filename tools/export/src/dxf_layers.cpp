#include "koppel/export/dxf.hpp"

#include <cctype>
#include <set>
#include <string_view>

namespace koppel::plot {
namespace {

// AutoCAD's limit on a layer name (DXF Reference, LAYER: "names can be up to 255 characters").
constexpr size_t kMaxLayerName = 255;

// The characters AutoCAD refuses in a layer name.
constexpr std::string_view kForbidden = "<>/\\\":;?*|=`";

// Printable ASCII that a layer name may hold. A control character would end the group value
// (a line break starts a forged group), a space or a byte above 127 reads differently in other
// programs (AC1015 files are read in the drawing's ANSI code page, not UTF-8).
bool Allowed(unsigned char c) { return c > ' ' && c < 127 && kForbidden.find(static_cast<char>(c)) == std::string_view::npos; }

// Layer names are compared without case (AutoCAD, ezdxf): "Crank" and "crank" are one layer.
std::string Folded(std::string name) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

}  // namespace

std::vector<std::string> DxfLayerNames(const std::vector<std::string>& names) {
  // "0" is every drawing's default layer (the frame's); Defpoints is AutoCAD's, never plotted
  std::set<std::string> taken = {"0", "defpoints"};
  std::vector<std::string> layers;
  for (const std::string& name : names) {
    std::string legal;
    for (const char c : name.substr(0, kMaxLayerName)) legal += Allowed(static_cast<unsigned char>(c)) ? c : '_';
    if (legal.empty()) legal = "_";
    // a name already given (two names made alike above, or alike but for case): the first
    // free "~2", "~3", ... appended, within the length limit, so the mapping stays one to one
    std::string layer = legal;
    for (int n = 2; taken.count(Folded(layer)) > 0; ++n) {
      const std::string suffix = "~" + std::to_string(n);
      layer = legal.substr(0, kMaxLayerName - suffix.size()) + suffix;
    }
    taken.insert(Folded(layer));
    layers.push_back(layer);
  }
  return layers;
}

}  // namespace koppel::plot
