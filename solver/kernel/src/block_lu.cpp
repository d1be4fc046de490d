#include "koppel/solver/block_lu.hpp"

#include <btf.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace koppel {
namespace {

// +1 for an even permutation, -1 for an odd one (by its cycles).
int PermutationSign(const std::vector<int>& p) {
  std::vector<bool> seen(p.size(), false);
  int sign = 1;
  for (size_t i = 0; i < p.size(); ++i) {
    if (seen[i]) continue;
    size_t length = 0;
    for (size_t j = i; !seen[j]; j = p[j]) {
      seen[j] = true;
      ++length;
    }
    if (length % 2 == 0) sign = -sign;
  }
  return sign;
}

// Dense LU with partial pivoting of one s x s block in place (column-major: a[c * s + r] is
// row r, column c): P A = L U with L's unit diagonal implied; piv[c] the row swapped with c at
// step c. Returns the number of swaps. S > 0 fixes the size at compile time (unrolled loops for
// the small blocks mechanisms are made of); S = 0 takes it from s.
template <int S>
int FactorizeBlock(double* a, int* piv, int s) {
  if constexpr (S > 0) s = S;
  int swaps = 0;
#pragma GCC unroll 8
  for (int c = 0; c < s; ++c) {
    int p = c;
    double largest = std::abs(a[c * s + c]);
#pragma GCC unroll 8
    for (int r = c + 1; r < s; ++r) {
      if (std::abs(a[c * s + r]) > largest) {
        largest = std::abs(a[c * s + r]);
        p = r;
      }
    }
    piv[c] = p;
    if (p != c) {
#pragma GCC unroll 8
      for (int cc = 0; cc < s; ++cc) std::swap(a[cc * s + c], a[cc * s + p]);
      ++swaps;
    }
    const double pivot = a[c * s + c];
    if (pivot == 0.0) continue;  // kept as a zero pivot: the caller sees a singular matrix
    const double inverse = 1.0 / pivot;
#pragma GCC unroll 8
    for (int r = c + 1; r < s; ++r) a[c * s + r] *= inverse;
#pragma GCC unroll 8
    for (int cc = c + 1; cc < s; ++cc) {
      const double u = a[cc * s + c];
#pragma GCC unroll 8
      for (int r = c + 1; r < s; ++r) a[cc * s + r] -= a[c * s + r] * u;
    }
  }
  return swaps;
}

// v = A^-1 v with the factorisation of FactorizeBlock.
template <int S>
void SolveBlock(const double* a, const int* piv, int s, double* v) {
  if constexpr (S > 0) s = S;
#pragma GCC unroll 8
  for (int c = 0; c < s; ++c) {
    if (piv[c] != c) std::swap(v[c], v[piv[c]]);
  }
#pragma GCC unroll 8
  for (int c = 0; c < s; ++c) {
#pragma GCC unroll 8
    for (int r = c + 1; r < s; ++r) v[r] -= a[c * s + r] * v[c];
  }
#pragma GCC unroll 8
  for (int c = s - 1; c >= 0; --c) {
    v[c] /= a[c * s + c];
#pragma GCC unroll 8
    for (int r = 0; r < c; ++r) v[r] -= a[c * s + r] * v[c];
  }
}

// v = A^-T v: A^T = U^T L^T P.
void SolveBlockTransposed(const double* a, const int* piv, int s, double* v) {
  for (int c = 0; c < s; ++c) {
    for (int r = 0; r < c; ++r) v[c] -= a[c * s + r] * v[r];
    v[c] /= a[c * s + c];
  }
  for (int c = s - 1; c >= 0; --c) {
    for (int r = c + 1; r < s; ++r) v[c] -= a[c * s + r] * v[r];
  }
  for (int c = s - 1; c >= 0; --c) {
    if (piv[c] != c) std::swap(v[c], v[piv[c]]);
  }
}

// The pattern (rows[e], cols[e]) of an n x n matrix as compressed columns: column j's rows are
// ai[ap[j] .. ap[j + 1]), sorted. False when an entry lies outside the matrix or is repeated (a
// repeated entry shows up as a neighbour).
bool CompressedColumns(int n, const std::vector<int>& rows, const std::vector<int>& cols, std::vector<int>* ap,
                       std::vector<int>* ai) {
  ap->assign(n + 1, 0);
  ai->assign(rows.size(), 0);
  for (size_t e = 0; e < rows.size(); ++e) {
    if (rows[e] < 0 || rows[e] >= n || cols[e] < 0 || cols[e] >= n) return false;
    ++(*ap)[cols[e] + 1];
  }
  for (int j = 0; j < n; ++j) (*ap)[j + 1] += (*ap)[j];
  std::vector<int> next(ap->begin(), ap->end() - 1);
  for (size_t e = 0; e < rows.size(); ++e) (*ai)[next[cols[e]]++] = rows[e];
  for (int j = 0; j < n; ++j) {
    const auto begin = ai->begin() + (*ap)[j], end = ai->begin() + (*ap)[j + 1];
    std::sort(begin, end);
    if (std::adjacent_find(begin, end) != end) return false;
  }
  return true;
}

}  // namespace

bool BlockLU::Analyse(int n, const std::vector<int>& rows, const std::vector<int>& cols) {
  analysed_ = false;
  if (n <= 0 || rows.size() != cols.size()) return false;
  std::vector<int> ap, ai;
  if (!CompressedColumns(n, rows, cols, &ap, &ai)) return false;
  std::vector<int> p(n), q(n), r(n + 1), work(5 * n);
  double transversal_work = 0.0;
  int matched = 0;
  const int count = btf_order(n, ap.data(), ai.data(), 0.0, &transversal_work, p.data(), q.data(), r.data(), &matched, work.data());
  if (matched < n) return false;  // structurally singular: no LU by blocks

  n_ = n;
  row_perm_ = p;
  col_perm_ = q;
  permutation_sign_ = PermutationSign(row_perm_) * PermutationSign(col_perm_);
  blocks_.assign(count, Block{});
  std::vector<int> block_of(n, 0);
  int total = 0;
  for (int b = 0; b < count; ++b) {
    Block& block = blocks_[b];
    block.start = r[b];
    block.size = r[b + 1] - r[b];
    block.lu = total;
    total += block.size * block.size;
    for (int k = r[b]; k < r[b + 1]; ++k) block_of[k] = b;
  }
  std::vector<int> row_position(n), col_position(n);
  for (int k = 0; k < n; ++k) {
    row_position[row_perm_[k]] = k;
    col_position[col_perm_[k]] = k;
  }
  if (!PlaceEntries(rows, cols, row_position, col_position, block_of)) return false;
  lu_.assign(total, 0.0);
  off_values_.assign(off_.size(), 0.0);
  pivot_row_.assign(n, 0);
  pivot_slot_.assign(n, 0);
  for (const Block& block : blocks_) {
    for (int c = 0; c < block.size; ++c) pivot_slot_[col_perm_[block.start + c]] = block.lu + c * block.size + c;
  }
  work_.assign(n, 0.0);
  analysed_ = true;
  return true;
}

bool BlockLU::PlaceEntries(const std::vector<int>& rows, const std::vector<int>& cols, const std::vector<int>& row_position,
                           const std::vector<int>& col_position, const std::vector<int>& block_of) {
  fill_.clear();
  off_.clear();
  for (size_t e = 0; e < rows.size(); ++e) {
    const int pr = row_position[rows[e]], pc = col_position[cols[e]];
    const int br = block_of[pr], bc = block_of[pc];
    const Block& block = blocks_[br];
    if (br == bc) {
      fill_.push_back({block.lu + (pc - block.start) * block.size + (pr - block.start), static_cast<int>(e)});
    } else if (br < bc) {
      off_.push_back({pr, pc, static_cast<int>(e)});
    } else {
      return false;  // not block upper triangular: cannot happen with BTF's ordering
    }
  }
  std::stable_sort(off_.begin(), off_.end(), [&](const OffDiagonal& a, const OffDiagonal& b) { return block_of[a.row] < block_of[b.row]; });
  const int count = static_cast<int>(blocks_.size());
  for (int b = 0, i = 0; b < count; ++b) {
    blocks_[b].off_begin = i;
    while (i < static_cast<int>(off_.size()) && block_of[off_[i].row] == b) ++i;
    blocks_[b].off_end = i;
  }
  return true;
}

int BlockLU::LargestBlock() const {
  int largest = 0;
  for (const Block& b : blocks_) largest = std::max(largest, b.size);
  return largest;
}

void BlockLU::Factorize(const double* values) {
  std::fill(lu_.begin(), lu_.end(), 0.0);
  for (const Fill& f : fill_) lu_[f.slot] = values[f.entry];
  for (size_t i = 0; i < off_.size(); ++i) off_values_[i] = values[off_[i].entry];
  int swaps = 0;
  for (const Block& block : blocks_) {
    double* a = lu_.data() + block.lu;
    int* piv = pivot_row_.data() + block.start;
    switch (block.size) {
      case 1: piv[0] = 0; break;  // the most common block of a mechanism: one coordinate from one equation
      case 2: swaps += FactorizeBlock<2>(a, piv, 2); break;
      case 3: swaps += FactorizeBlock<3>(a, piv, 3); break;
      case 4: swaps += FactorizeBlock<4>(a, piv, 4); break;
      case 5: swaps += FactorizeBlock<5>(a, piv, 5); break;
      case 6: swaps += FactorizeBlock<6>(a, piv, 6); break;
      default: swaps += FactorizeBlock<0>(a, piv, block.size); break;
    }
  }
  sign_ = swaps % 2 == 0 ? permutation_sign_ : -permutation_sign_;
}

void BlockLU::Solve(double* x) const {
  double* y = work_.data();
  for (int k = 0; k < n_; ++k) y[k] = x[row_perm_[k]];
  // block upper triangular: the last block first, each with the later ones already known
  for (auto block = blocks_.rbegin(); block != blocks_.rend(); ++block) {
    for (int i = block->off_begin; i < block->off_end; ++i) y[off_[i].row] -= off_values_[i] * y[off_[i].col];
    const double* a = lu_.data() + block->lu;
    const int* piv = pivot_row_.data() + block->start;
    double* v = y + block->start;
    switch (block->size) {
      case 1: v[0] /= a[0]; break;
      case 2: SolveBlock<2>(a, piv, 2, v); break;
      case 3: SolveBlock<3>(a, piv, 3, v); break;
      case 4: SolveBlock<4>(a, piv, 4, v); break;
      case 5: SolveBlock<5>(a, piv, 5, v); break;
      case 6: SolveBlock<6>(a, piv, 6, v); break;
      default: SolveBlock<0>(a, piv, block->size, v); break;
    }
  }
  for (int k = 0; k < n_; ++k) x[col_perm_[k]] = y[k];
}

void BlockLU::SolveTransposed(double* x) const {
  double* y = work_.data();
  for (int k = 0; k < n_; ++k) y[k] = x[col_perm_[k]];
  // the transpose is block lower triangular: the first block first, then its part taken from
  // the equations of the later ones
  for (const Block& block : blocks_) {
    SolveBlockTransposed(lu_.data() + block.lu, pivot_row_.data() + block.start, block.size, y + block.start);
    for (int i = block.off_begin; i < block.off_end; ++i) y[off_[i].col] -= off_values_[i] * y[off_[i].row];
  }
  for (int k = 0; k < n_; ++k) x[row_perm_[k]] = y[k];
}

}  // namespace koppel
