// `catalog find --like`: kinematic chains compared as link–joint graphs (frame marked, joint
// types respected). For every entry, copies with renamed links and joints, shuffled link and
// joint order and swapped joint ends (seeded) are isomorphic and find the entry; a copy with one
// joint's type changed is not and does not.
#include "koppel/catalog/catalog.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

namespace koppel::chain_match_test {
namespace {

// The mechanism with its links and joints renamed and re-ordered by `random` (geometry and
// outputs dropped: the chain is what is compared).
Mechanism Relabelled(const Mechanism& m, std::mt19937& random) {
  std::vector<int> link_order(m.links.size());
  std::iota(link_order.begin(), link_order.end(), 0);
  std::shuffle(link_order.begin(), link_order.end(), random);
  std::vector<int> new_index(m.links.size());
  Mechanism out;
  out.name = "sketch";
  for (size_t k = 0; k < link_order.size(); ++k) {
    new_index[link_order[k]] = static_cast<int>(k);
    Link link = m.links[link_order[k]];
    link.name = "L" + std::to_string(k);
    out.links.push_back(link);
  }
  std::vector<Joint> joints = m.joints;
  std::shuffle(joints.begin(), joints.end(), random);
  for (size_t k = 0; k < joints.size(); ++k) {
    Joint j = joints[k];
    j.name = "J" + std::to_string(k);
    j.link_a = new_index[j.link_a];
    j.link_b = new_index[j.link_b];
    if (j.type == JointType::kRevolute && random() % 2) {  // an R joint has no guide and block: either order
      std::swap(j.link_a, j.link_b);
      std::swap(j.point_a, j.point_b);
    }
    out.joints.push_back(j);
  }
  return out;
}

bool Found(const Catalog& catalog, const Mechanism& like, const std::string& id) {
  FeatureQuery q;
  q.like = like;
  for (const CatalogEntry* e : FindEntries(catalog, q)) {
    if (e->file.id == id) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("relabelled and re-ordered copies of every entry are isomorphic and find it", "[catalog][like]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  std::mt19937 random(20240515);
  for (const CatalogEntry& e : catalog.entries()) {
    INFO(e.file.id);
    for (int copy = 0; copy < 3; ++copy) {
      const Mechanism sketch = Relabelled(e.file.mechanism, random);
      CHECK(SameKinematicChain(e.file.mechanism, sketch));
      CHECK(SameKinematicChain(sketch, e.file.mechanism));
      CHECK(Found(catalog, sketch, e.file.id));
    }
  }
}

TEST_CASE("a copy with one joint type changed is not isomorphic and does not find the entry", "[catalog][like]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  std::mt19937 random(7);
  for (const CatalogEntry& e : catalog.entries()) {
    for (size_t j = 0; j < e.file.mechanism.joints.size(); ++j) {
      INFO(e.file.id << ", joint " << j << " of a relabelled copy");
      Mechanism changed = Relabelled(e.file.mechanism, random);
      Joint& joint = changed.joints[j];
      joint.type = joint.type == JointType::kRevolute ? JointType::kPrismatic : JointType::kRevolute;
      CHECK_FALSE(SameKinematicChain(e.file.mechanism, changed));
      CHECK_FALSE(Found(catalog, changed, e.file.id));
    }
  }
}

TEST_CASE("the frame is marked: the same chain with another link as frame is another mechanism", "[catalog][like]") {
  // the slider-crank (seed 000) and its inversion with the crank as frame (Kurbelschleife) share
  // the chain but not the frame
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  const Mechanism& slider_crank = catalog.Find("slider-crank-offset")->file.mechanism;
  Mechanism inverted = slider_crank;
  for (Link& l : inverted.links) l.is_frame = l.name == "crank";
  CHECK_FALSE(SameKinematicChain(slider_crank, inverted));
  // frame back where it was: the same
  for (Link& l : inverted.links) l.is_frame = l.name == "frame";
  CHECK(SameKinematicChain(slider_crank, inverted));
}

TEST_CASE("different counts or degrees are never isomorphic", "[catalog][like]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  const Mechanism& four_bar = catalog.Find("mzc-crank-rocker")->file.mechanism;
  const Mechanism& six_bar = catalog.Find("proportional-linkage")->file.mechanism;
  CHECK_FALSE(SameKinematicChain(four_bar, six_bar));
  Mechanism fewer = four_bar;
  fewer.joints.pop_back();
  CHECK_FALSE(SameKinematicChain(four_bar, fewer));
}

}  // namespace koppel::chain_match_test
