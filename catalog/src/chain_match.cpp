// Isomorphism of kinematic chains (catalog.hpp, SameKinematicChain): the link–joint graph with
// links as vertices (the frame marked) and joints as edges labelled R or P. Chains in a catalog
// have a dozen links at most, so a backtracking search that assigns links in breadth-first order
// from the frame, each checked against every link assigned before it, is instant.
#include "koppel/catalog/catalog.hpp"

#include <algorithm>
#include <vector>

namespace koppel {
namespace {

struct Chain {
  int n = 0;
  int frame = -1;
  std::vector<int> degree;
  std::vector<std::vector<int>> revolute, prismatic;  // joint counts between two links
};

Chain ChainOf(const Mechanism& m) {
  Chain c;
  c.n = static_cast<int>(m.links.size());
  c.frame = m.FrameLink();
  c.degree.assign(c.n, 0);
  c.revolute.assign(c.n, std::vector<int>(c.n, 0));
  c.prismatic = c.revolute;
  for (const Joint& j : m.joints) {
    auto& table = j.type == JointType::kRevolute ? c.revolute : c.prismatic;
    ++table[j.link_a][j.link_b];
    ++table[j.link_b][j.link_a];
    ++c.degree[j.link_a];
    ++c.degree[j.link_b];
  }
  return c;
}

// Links of `c` in breadth-first order from the frame (then any unconnected rest), so that every
// link after the first has an assigned neighbour to be checked against.
std::vector<int> SearchOrder(const Chain& c) {
  std::vector<int> order;
  std::vector<bool> seen(c.n, false);
  auto visit = [&](int start) {
    order.push_back(start);
    seen[start] = true;
    for (size_t k = order.size() - 1; k < order.size(); ++k) {
      for (int other = 0; other < c.n; ++other) {
        if (!seen[other] && (c.revolute[order[k]][other] || c.prismatic[order[k]][other])) {
          seen[other] = true;
          order.push_back(other);
        }
      }
    }
  };
  if (c.frame >= 0) visit(c.frame);
  for (int l = 0; l < c.n; ++l) {
    if (!seen[l]) visit(l);
  }
  return order;
}

class Matcher {
 public:
  Matcher(const Chain& a, const Chain& b) : a_(a), b_(b), order_(SearchOrder(a)), map_(a.n, -1), used_(b.n, false) {}

  bool Run() { return Assign(0); }

 private:
  bool Fits(int la, int lb) const {
    if (used_[lb] || a_.degree[la] != b_.degree[lb] || (la == a_.frame) != (lb == b_.frame)) return false;
    for (int k = 0; k < a_.n; ++k) {
      const int mk = map_[k];
      if (mk < 0) continue;
      if (a_.revolute[la][k] != b_.revolute[lb][mk] || a_.prismatic[la][k] != b_.prismatic[lb][mk]) return false;
    }
    return true;
  }

  bool Assign(size_t depth) {
    if (depth == order_.size()) return true;
    const int la = order_[depth];
    for (int lb = 0; lb < b_.n; ++lb) {
      if (!Fits(la, lb)) continue;
      map_[la] = lb;
      used_[lb] = true;
      if (Assign(depth + 1)) return true;
      map_[la] = -1;
      used_[lb] = false;
    }
    return false;
  }

  const Chain& a_;
  const Chain& b_;
  std::vector<int> order_;
  std::vector<int> map_;
  std::vector<bool> used_;
};

}  // namespace

bool SameKinematicChain(const Mechanism& a, const Mechanism& b) {
  if (a.links.size() != b.links.size() || a.joints.size() != b.joints.size()) return false;
  const Chain ca = ChainOf(a), cb = ChainOf(b);
  std::vector<int> da = ca.degree, db = cb.degree;
  std::sort(da.begin(), da.end());
  std::sort(db.begin(), db.end());
  if (da != db) return false;
  return Matcher(ca, cb).Run();
}

}  // namespace koppel
