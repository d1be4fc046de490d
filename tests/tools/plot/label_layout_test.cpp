// The label layout on hand-made scenes: where the nearest places are free a label sits up and
// right of its point (the usual 7 px); labels of one point, or of points a few px apart, never
// overlap; blocked places push a label outwards with a leader; a box test against segments.
#include "koppel/plot/label_layout.hpp"

#include <catch2/catch.hpp>

namespace koppel::plot::label_layout_test {
namespace {

bool AnyOverlap(const std::vector<PlacedLabel>& placed) {
  for (size_t i = 0; i < placed.size(); ++i)
    for (size_t j = i + 1; j < placed.size(); ++j)
      if (placed[i].box.Overlaps(placed[j].box)) return true;
  return false;
}

LabelScene Open() {
  LabelScene scene;
  scene.area = {0, 0, 400, 300};
  return scene;
}

}  // namespace

TEST_CASE("a lone label sits 7 px up and right of its point", "[plot][labels]") {
  const auto placed = PlaceLabels({{"A", {100, 100}, 13}}, Open());
  REQUIRE(placed.size() == 1);
  CHECK(placed[0].baseline.x() == Approx(107));
  CHECK(placed[0].baseline.y() == Approx(93));
  CHECK_FALSE(placed[0].leader);
}

TEST_CASE("labels of coinciding and nearby points do not overlap", "[plot][labels]") {
  // "B" and "B_a" a pixel apart (the dead centre next to the pose drawn), and a crowd of eight
  std::vector<LabelRequest> requests = {{"B", {200, 150}, 13}, {"B_a", {201, 150}, 12}};
  for (int i = 0; i < 8; ++i) requests.push_back({"P" + std::to_string(i), {200.0 + 3 * i, 152}, 12});
  const auto placed = PlaceLabels(requests, Open());
  CHECK_FALSE(AnyOverlap(placed));
  CHECK_FALSE(placed[0].leader);  // the first keeps the nearest place
  int leaders = 0;
  for (const PlacedLabel& p : placed) leaders += p.leader;
  CHECK(leaders > 0);  // ten labels do not fit on the nearest ring of one spot
}

TEST_CASE("symbols are not covered; a label leaves the picture only when nothing else fits", "[plot][labels]") {
  LabelScene scene = Open();
  // the nearest ring around (100, 100) is blocked all round
  scene.symbols.push_back({70, 70, 130, 130});
  const auto placed = PlaceLabels({{"K", {100, 100}, 13}}, scene);
  CHECK_FALSE(placed[0].box.Overlaps(scene.symbols[0]));
  CHECK(placed[0].leader);
  CHECK(scene.area.Contains(placed[0].box));
  // at the picture's corner the label turns inwards
  const auto corner = PlaceLabels({{"K", {395, 5}, 13}}, Open());
  CHECK(Open().area.Contains(corner[0].box));
}

TEST_CASE("a label avoids crossing a link where a free place does not cross one", "[plot][labels]") {
  LabelScene scene = Open();
  scene.lines.push_back({{100, 100}, {200, 0}});  // a link leaving the point up and right
  const auto placed = PlaceLabels({{"A", {100, 100}, 13}}, scene);
  CHECK_FALSE(placed[0].box.Crosses({100, 100}, {200, 0}));
  CHECK_FALSE(placed[0].leader);
}

TEST_CASE("box geometry", "[plot][labels]") {
  const LabelBox box{10, 10, 20, 20};
  CHECK(box.Crosses({0, 15}, {30, 15}));
  CHECK(box.Crosses({15, 15}, {15, 16}));  // inside
  CHECK_FALSE(box.Crosses({0, 0}, {30, 5}));
  CHECK_FALSE(box.Crosses({0, 30}, {5, 0}));
  CHECK(box.OverlapArea({15, 15, 30, 30}) == Approx(25));
  CHECK(box.Nearest({0, 15}) == Eigen::Vector2d(10, 15));
  // the extent grows with the characters, code points not bytes
  CHECK(TextBox("φ_a", 12, {0, 0}).right == Approx(TextBox("B_a", 12, {0, 0}).right));
  CHECK(TextBox("B_a", 12, {0, 0}).right > TextBox("B", 12, {0, 0}).right);
}

}  // namespace koppel::plot::label_layout_test
