// BlockLU against Eigen's dense LU of the same matrix: solutions, transposed solutions and the
// determinant, on random sparse matrices that hide a block triangular structure behind random
// row and column permutations (fixed seed); the blocks BTF finds; patterns it must refuse.
#include "koppel/solver/block_lu.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

namespace koppel::block_lu_test {
namespace {

// relative: the product of the block pivots against Eigen's dense LU of the same O(10) matrix, two
// elimination orders whose rounding differs by a few ulps per pivot, well inside 1e-10
constexpr double kDeterminant = 1e-10;

// Dense LU of well-conditioned random matrices of size <= 40: solutions agree to a few hundred ulps.
constexpr double kSolve = 1e-11;

struct Sparse {
  int n = 0;
  std::vector<int> rows, cols;
  std::vector<double> values;
  Eigen::MatrixXd Dense() const {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (size_t e = 0; e < rows.size(); ++e) a(rows[e], cols[e]) = values[e];
    return a;
  }
};

// Block lower triangular with diagonal blocks of the given sizes (dense, diagonally dominant so
// that they are regular) and a sprinkle of entries below them, then permuted at random.
Sparse RandomBlockTriangular(const std::vector<int>& sizes, std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1.0, 1.0), coin(0.0, 1.0);
  const int n = std::accumulate(sizes.begin(), sizes.end(), 0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  int start = 0;
  for (int s : sizes) {
    for (int r = 0; r < s; ++r) {
      for (int c = 0; c < s; ++c) a(start + r, start + c) = value(random) + (r == c ? 3.0 * (coin(random) < 0.5 ? 1 : -1) : 0.0);
      for (int c = 0; c < start; ++c) {
        if (coin(random) < 0.3) a(start + r, c) = value(random);
      }
    }
    start += s;
  }
  std::vector<int> p(n), q(n);
  std::iota(p.begin(), p.end(), 0);
  std::iota(q.begin(), q.end(), 0);
  std::shuffle(p.begin(), p.end(), random);
  std::shuffle(q.begin(), q.end(), random);
  Sparse m;
  m.n = n;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      if (a(r, c) == 0.0) continue;
      m.rows.push_back(p[r]);
      m.cols.push_back(q[c]);
      m.values.push_back(a(r, c));
    }
  }
  return m;
}

}  // namespace

TEST_CASE("block LU: solutions, transposed solutions and determinant as the dense LU's", "[block_lu]") {
  std::mt19937 random(1123);
  std::uniform_int_distribution<int> block_size(1, 7), block_count(1, 8);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<int> sizes(block_count(random));
    for (int& s : sizes) s = block_size(random);
    const Sparse m = RandomBlockTriangular(sizes, random);
    INFO("trial " << trial << ", n = " << m.n);
    BlockLU lu;
    REQUIRE(lu.Analyse(m.n, m.rows, m.cols));
    // BTF finds blocks no larger than the ones built (it may split a block whose random entries allow it)
    CHECK(lu.LargestBlock() <= *std::max_element(sizes.begin(), sizes.end()));
    CHECK(lu.blocks() >= static_cast<int>(sizes.size()));
    lu.Factorize(m.values.data());
    const Eigen::MatrixXd dense = m.Dense();
    const Eigen::PartialPivLU<Eigen::MatrixXd> reference(dense);
    Eigen::VectorXd b(m.n);
    for (int i = 0; i < m.n; ++i) b(i) = value(random);
    Eigen::VectorXd x = b;
    lu.Solve(x.data());
    CHECK((x - reference.solve(b)).lpNorm<Eigen::Infinity>() <= kSolve * (1.0 + x.lpNorm<Eigen::Infinity>()));
    CHECK((dense * x - b).lpNorm<Eigen::Infinity>() <= kSolve);
    Eigen::VectorXd y = b;
    lu.SolveTransposed(y.data());
    CHECK((dense.transpose() * y - b).lpNorm<Eigen::Infinity>() <= kSolve);
    double determinant = lu.DeterminantSign();
    for (int j = 0; j < m.n; ++j) determinant *= lu.Pivot(j);
    CHECK_THAT(determinant, Catch::Matchers::WithinRel(reference.determinant(), kDeterminant));
  }
}

TEST_CASE("block LU: a triangular matrix is n blocks of one; refactorising takes new values", "[block_lu]") {
  // lower triangular 4 x 4 given in scrambled order
  const std::vector<int> rows = {3, 0, 2, 1, 3, 2, 1, 3}, cols = {0, 0, 2, 1, 3, 0, 0, 2};
  BlockLU lu;
  REQUIRE(lu.Analyse(4, rows, cols));
  CHECK(lu.blocks() == 4);
  CHECK(lu.LargestBlock() == 1);
  for (double scale : {1.0, -2.5}) {
    std::vector<double> values = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0};
    for (double& v : values) v *= scale;
    lu.Factorize(values.data());
    Sparse m{4, rows, cols, values};
    Eigen::VectorXd b(4);
    b << 1, 2, 3, 4;
    Eigen::VectorXd x = b;
    lu.Solve(x.data());
    CHECK((m.Dense() * x - b).lpNorm<Eigen::Infinity>() <= kSolve);
    // the pivots are the diagonal: column 0 -> 2, 1 -> 4, 2 -> 3, 3 -> 5
    CHECK(lu.Pivot(0) == 2.0 * scale);
    CHECK(lu.Pivot(3) == 5.0 * scale);
  }
}

TEST_CASE("block LU: a singular block gives a zero pivot; structurally singular or repeated patterns are refused", "[block_lu]") {
  BlockLU lu;
  // [[1, 2], [2, 4]]: regular pattern, singular values
  REQUIRE(lu.Analyse(2, {0, 0, 1, 1}, {0, 1, 0, 1}));
  const std::vector<double> values = {1.0, 2.0, 2.0, 4.0};
  lu.Factorize(values.data());
  CHECK(std::min(std::abs(lu.Pivot(0)), std::abs(lu.Pivot(1))) == 0.0);
  // column 1 empty: no matching
  CHECK_FALSE(lu.Analyse(2, {0, 1}, {0, 0}));
  CHECK_FALSE(lu.analysed());
  // the same place twice
  CHECK_FALSE(lu.Analyse(2, {0, 1, 1}, {0, 1, 1}));
  // out of range
  CHECK_FALSE(lu.Analyse(2, {0, 2}, {0, 1}));
}

}  // namespace koppel::block_lu_test
