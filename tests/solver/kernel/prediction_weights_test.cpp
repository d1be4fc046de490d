// The compiled step's prediction weights (prediction_weights.hpp), against polynomials they must
// reproduce exactly: the quintic weights any polynomial of degree 5 through the two states' value,
// 1st and 2nd derivative, the 2nd-order ones any quadratic; and the rule that picks between them.
#include "koppel/solver/prediction_weights.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace koppel::prediction_weights_test {
namespace {

// p(t) = sum c_k t^k and its 1st and 2nd derivatives at t
struct Poly {
  double c[6] = {0, 0, 0, 0, 0, 0};
  double At(int derivative, double t) const {
    double sum = 0.0;
    for (int k = derivative; k < 6; ++k) {
      double factor = 1.0;
      for (int i = 0; i < derivative; ++i) factor *= k - i;
      sum += factor * c[k] * std::pow(t, k - derivative);
    }
    return sum;
  }
};

// the weights' prediction of p(h) from the state at 0 and the one at -h_before, and the size of
// what it sums (its roundoff: the earlier state's values times their weights)
double Predict(const PredictionWeights& w, const Poly& p, double h_before, double* magnitude = nullptr) {
  double sum = p.At(0, 0.0) + w.j1 * p.At(1, 0.0) + w.j2 * p.At(2, 0.0);
  double size = std::abs(p.At(0, 0.0)) + std::abs(w.j1 * p.At(1, 0.0)) + std::abs(w.j2 * p.At(2, 0.0));
  if (w.quintic) {
    const double m[3] = {w.m0, w.m1, w.m2};
    for (int k = 0; k < 3; ++k) {
      sum += m[k] * (p.At(k, -h_before) - p.At(k, 0.0));
      size += std::abs(m[k]) * (std::abs(p.At(k, -h_before)) + std::abs(p.At(k, 0.0)));
    }
  }
  if (magnitude) *magnitude += size;
  return sum;
}

}  // namespace

TEST_CASE("prediction weights reproduce a quintic through both states for steps up to 4 times the one before", "[prediction]") {
  std::mt19937 random(25);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0), step(0.005, 0.05), ratio(-4.0, 4.0);
  PredictionWeights w;
  for (int trial = 0; trial < 500; ++trial) {
    Poly p;
    for (double& c : p.c) c = coefficient(random);
    const double h_before = step(random), h = ratio(random) * h_before;
    w.For(h, h_before);
    REQUIRE(w.quintic);
    // reference: the polynomial itself, to the roundoff of the weighted sum (its weights grow
    // like (h / h_before)^5: 1e4 at 4)
    double magnitude = std::abs(p.At(0, h));
    const double predicted = Predict(w, p, h_before, &magnitude);
    CHECK(std::abs(predicted - p.At(0, h)) <= 8.0 * std::numeric_limits<double>::epsilon() * magnitude);
  }
}

TEST_CASE("prediction weights take the 2nd order without a state before or for a step far longer than it", "[prediction]") {
  Poly quadratic;
  quadratic.c[0] = 0.4;
  quadratic.c[1] = -1.3;
  quadratic.c[2] = 0.8;
  Poly quintic = quadratic;
  quintic.c[5] = 2.0;
  PredictionWeights w;
  for (const auto& [h, h_before] : {std::pair{0.01, 0.0}, std::pair{0.05, 0.01}, std::pair{-0.041, 0.01}, std::pair{0.2, -0.01}}) {
    w.For(h, h_before);
    CHECK_FALSE(w.quintic);
    // exact on a quadratic (Taylor's 2nd order); on a quintic with the same value, 1st and 2nd
    // derivative at 0 the same prediction (the earlier state, where they differ, is not used)
    CHECK(std::abs(Predict(w, quadratic, h_before) - quadratic.At(0, h)) <= 1e-15);
    CHECK(std::abs(Predict(w, quintic, h_before) - quadratic.At(0, h)) <= 1e-15);
  }
}

TEST_CASE("prediction weights are kept for a step within 1e-12 of theirs and computed anew for another", "[prediction]") {
  Poly p;
  const double c[6] = {0.3, -0.9, 0.4, 0.7, -0.2, 0.5};
  std::copy(c, c + 6, p.c);
  const double h = 0.0175, drift = 1.0 + 1e-13;  // a walk's steps of 1 degree, to roundoff
  PredictionWeights kept;
  kept.For(h, h);
  kept.For(h * drift, h / drift);
  PredictionWeights fresh;
  fresh.For(h, h);
  CHECK(kept.j1 == fresh.j1);  // kept, not computed anew
  CHECK(kept.m0 == fresh.m0);
  // reference: the polynomial at the new steps; the kept weights miss it by the states' shift
  // (1e-13 h) times |p'| (below 2 here) times the weights (1 - m0 = 32 at equal steps), and
  // their roundoff
  CHECK(std::abs(Predict(kept, p, h / drift) - p.At(0, h * drift)) <= 32 * 1e-13 * h * 2 + 1e-15);
  kept.For(h * drift * drift, h);  // the change measured from the step they were computed for
  CHECK(kept.j1 == fresh.j1);
  // a step that differs (the walk's last, shortened step; a turn back) gets its own weights
  for (const auto& [next, before] : {std::pair{0.6 * h, h}, std::pair{-h, h}, std::pair{h, 0.0}, std::pair{h, 0.5 * h}}) {
    kept.For(next, before);
    PredictionWeights again;
    again.For(next, before);
    CHECK(kept.quintic == again.quintic);
    CHECK(kept.j1 == again.j1);
    CHECK(kept.j2 == again.j2);
    CHECK(kept.m0 == again.m0);
    CHECK(kept.m1 == again.m1);
    CHECK(kept.m2 == again.m2);
  }
}

}  // namespace koppel::prediction_weights_test
