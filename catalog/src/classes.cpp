#include "koppel/catalog/classes.hpp"

#include "koppel/analysis/classification.hpp"
#include "lower_case.hpp"

#include <algorithm>
#include <cctype>

namespace koppel {
namespace {

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

bool Contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

struct Graph {
  int links = 0, revolute = 0, prismatic = 0;
  std::vector<int> degree;
  bool slide_at_frame = false, slide_between_moving = false;
};

Graph Summarise(const Mechanism& m) {
  Graph g;
  g.links = static_cast<int>(m.links.size());
  g.degree.assign(m.links.size(), 0);
  for (const Joint& j : m.joints) {
    ++g.degree[j.link_a];
    ++g.degree[j.link_b];
    if (j.type == JointType::kRevolute) {
      ++g.revolute;
      continue;
    }
    ++g.prismatic;
    const bool at_frame = m.links[j.link_a].is_frame || m.links[j.link_b].is_frame;
    (at_frame ? g.slide_at_frame : g.slide_between_moving) = true;
  }
  return g;
}

// The six-bar chains: two ternary and four binary links with seven joints. The ternary links
// are jointed to each other in Watt's chain and not in Stephenson's.
std::string SixBarChain(const Mechanism& m, const Graph& g) {
  if (g.links != 6 || static_cast<int>(m.joints.size()) != 7) return "";
  std::vector<int> ternary;
  for (int l = 0; l < g.links; ++l) {
    if (g.degree[l] == 3) ternary.push_back(l);
    else if (g.degree[l] != 2) return "";
  }
  if (ternary.size() != 2) return "";
  for (const Joint& j : m.joints) {
    if ((j.link_a == ternary[0] && j.link_b == ternary[1]) || (j.link_a == ternary[1] && j.link_b == ternary[0])) return "watt-six-bar";
  }
  return "stephenson-six-bar";
}

}  // namespace

const std::vector<CatalogClass>& CatalogClasses() {
  static const std::vector<CatalogClass> classes = {
      {"four-bar", "Gelenkviereck: four links, four R joints (computed)"},
      {"crank-rocker", "Kurbelschwinge: Grashof four-bar, the shortest link is the crank (computed)"},
      {"double-crank", "Doppelkurbel: Grashof four-bar, the frame is the shortest link (computed)"},
      {"double-rocker", "Doppelschwinge: Grashof four-bar, the coupler is the shortest link (computed)"},
      {"triple-rocker", "non-Grashof four-bar: no link turns fully against another (computed)"},
      {"change-point", "Grashof-neutral (s + l = p + q): the chain passes a change point where it can fold (computed)"},
      {"slider-crank-chain", "four links, three R joints and one P joint, any inversion (computed)"},
      {"slider-crank", "Schubkurbel: the slider slides on the frame (computed; a P pair is the same whichever of its links holds the block, so the hand pump's fixed-block inversion is one too)"},
      {"slotted-link-oscillating", "schwingende Kurbelschleife: the slotted link oscillates"},
      {"slotted-link-rotating", "umlaufende Kurbelschleife: the slotted link turns fully"},
      {"swinging-block", "Schubschwinge: the rod slides in a block that pivots on the frame"},
      {"fixed-block", "the slider-crank chain read with the slider block as frame: the plunger slides in the fixed cylinder and the handle is the coupler (hand pump); a slider-crank as well"},
      {"double-slider", "four links, two R and two P joints: trammel, Scotch yoke, Oldham coupling (computed)"},
      {"watt-six-bar", "six links, the two ternary links jointed to each other (computed)"},
      {"stephenson-six-bar", "six links, the two ternary links not jointed to each other (computed)"},
      {"straight-line-approximate", "a point moves approximately on a straight line over part of the cycle"},
      {"straight-line-exact", "a point moves exactly on a straight line"},
      {"quick-return", "the strokes of the output take different crank angles: time ratio != 1 (computed: declared exactly where the first Abtrieb output's time ratio over a turn is not 1)"},
      {"toggle", "Kniehebel: large force amplification near an extended position"},
      {"walking", "a foot point with a flat ground stretch and a lifted return"},
      {"moving-slider", "a P joint between two moving links (computed)"},
      {"dwell", "the output stands nearly still over part of the cycle"},
      {"parallel-guidance", "a link keeps its orientation (translates)"},
      {"inversor", "a point pair related by inversion in a circle"},
  };
  return classes;
}

bool IsCatalogClass(const std::string& name) {
  const auto& all = CatalogClasses();
  return std::any_of(all.begin(), all.end(), [&](const CatalogClass& c) { return name == c.name; });
}

std::vector<std::string> StructuralClasses(const Mechanism& m) {
  const Graph g = Summarise(m);
  std::vector<std::string> classes;
  const bool four_links = g.links == 4 && static_cast<int>(m.joints.size()) == 4;
  if (four_links && g.prismatic == 0) classes.push_back("four-bar");
  if (four_links && g.prismatic == 1) {
    classes.push_back("slider-crank-chain");
    if (g.slide_at_frame) classes.push_back("slider-crank");
  }
  if (four_links && g.prismatic == 2) classes.push_back("double-slider");
  if (const std::string six = SixBarChain(m, g); !six.empty()) classes.push_back(six);
  if (g.slide_between_moving) classes.push_back("moving-slider");
  return classes;
}

std::vector<std::string> ComputedClasses(const Mechanism& m) {
  std::vector<std::string> classes = StructuralClasses(m);
  const Classification chain = ClassifyChain(m);
  if (chain.grashof != GrashofType::kNotApplicable && IsCatalogClass(ToString(chain.grashof))) classes.push_back(ToString(chain.grashof));
  return classes;
}

// A structural class the card leaves out is added to the entry's classes (catalog.cpp), not an
// error; one it declares and the graph is not is. A declared Grashof type must be the one the
// four-bar's lengths give (s + l against p + q, classification.hpp).
std::vector<std::string> ClassProblems(const Mechanism& m, const std::vector<std::string>& declared) {
  static const std::vector<std::string> kStructural = {"four-bar",     "slider-crank-chain", "slider-crank",
                                                       "double-slider", "watt-six-bar",       "stephenson-six-bar",
                                                       "moving-slider"};
  // the Grashof types of a four-bar, decided by its link lengths (classification.hpp)
  static const std::vector<std::string> kGrashof = {"crank-rocker", "double-crank", "double-rocker", "triple-rocker", "change-point"};
  const std::vector<std::string> computed = StructuralClasses(m);
  std::vector<std::string> problems;
  for (const std::string& c : declared) {
    if (Contains(kStructural, c) && !Contains(computed, c)) problems.push_back("class " + c + ": declared, but the joint graph is not one");
    if (!Contains(kGrashof, c)) continue;
    const Classification chain = ClassifyChain(m);
    if (chain.grashof == GrashofType::kNotApplicable) {
      problems.push_back("class " + c + ": declared, but the chain is no four-bar");
    } else if (ToString(chain.grashof) != c) {
      problems.push_back("class " + c + ": declared, but the chain is a " + ToString(chain.grashof) + " (" + chain.rule + ")");
    }
  }
  return problems;
}

const std::vector<std::string>& InputMotions() {
  static const std::vector<std::string> words = {"full rotation", "oscillating rotation", "translation"};
  return words;
}

const std::vector<std::string>& OutputMotions() {
  static const std::vector<std::string> words = {
      "uniform rotation",         "non-uniform rotation", "full rotation",       "oscillating rotation",
      "oscillating translation",  "translation",          "straight-line guidance", "path guidance",
      "rigid-body guidance",
  };
  return words;
}

std::string MotionProblem(const std::string& motion) {
  const auto arrow = motion.find("->");
  if (arrow == std::string::npos) return "expected '<input motion> -> <output motion>'";
  const std::string input = Trim(motion.substr(0, arrow)), output = Trim(motion.substr(arrow + 2));
  auto list = [](const std::vector<std::string>& words) {
    std::string s;
    for (const std::string& w : words) s += (s.empty() ? "" : ", ") + w;
    return s;
  };
  if (!Contains(InputMotions(), input)) return "the input motion '" + input + "' is not one of: " + list(InputMotions());
  const auto& outputs = OutputMotions();
  const bool known = std::any_of(outputs.begin(), outputs.end(), [&](const std::string& w) {
    return output.compare(0, w.size(), w) == 0 && (output.size() == w.size() || output[w.size()] == ' ');
  });
  if (!known) return "the output motion '" + output + "' does not start with one of: " + list(outputs);
  return "";
}

bool MotionMatches(const std::string& motion, const std::string& query) {
  const std::string m = Lower(motion), q = Lower(query);
  const auto arrow = m.find("->"), q_arrow = q.find("->");
  const std::string input = arrow == std::string::npos ? m : m.substr(0, arrow);
  const std::string output = arrow == std::string::npos ? m : m.substr(arrow + 2);
  if (q_arrow == std::string::npos) {
    const std::string word = Trim(q);
    return input.find(word) != std::string::npos || output.find(word) != std::string::npos;
  }
  const std::string q_in = Trim(q.substr(0, q_arrow)), q_out = Trim(q.substr(q_arrow + 2));
  return input.find(q_in) != std::string::npos && output.find(q_out) != std::string::npos;
}

}  // namespace koppel
