// The LU factorisation of a square sparse matrix with a fixed pattern, block by block: the
// pattern is permuted once into block upper triangular form (SuiteSparse BTF: a maximum
// transversal, then the strongly connected components — the fine Dulmage–Mendelsohn
// decomposition of a structurally regular matrix), and each diagonal block gets its own dense
// LU with partial pivoting. For a mechanism the blocks are the smallest subsystems that can be
// solved one after the other (a crank, a dyad, a triad, a loop that cannot be split), so the
// work grows with the number of loops, not with its cube.
#pragma once

#include <vector>

namespace koppel {

class BlockLU {
 public:
  // The pattern of an n x n matrix: entry e at (rows[e], cols[e]), no two at one place. False
  // (and nothing analysed) when the pattern is structurally singular or has a repeated entry.
  bool Analyse(int n, const std::vector<int>& rows, const std::vector<int>& cols);
  bool analysed() const { return analysed_; }
  int size() const { return n_; }
  int blocks() const { return static_cast<int>(blocks_.size()); }
  int LargestBlock() const;

  // Factorises the matrix whose entries are `values`, in the pattern's order (copied: the
  // factorisation does not refer to them afterwards). A zero pivot is kept as zero.
  void Factorize(const double* values);
  // x = A^-1 x and x = A^-T x in place, with the last factorisation.
  void Solve(double* x) const;
  void SolveTransposed(double* x) const;

  // The pivots of the factorisation (U's diagonal, one per column of A): pivot(j) belongs to
  // column j of A. det A = DeterminantSign() * product of the pivots.
  double Pivot(int column) const { return lu_[pivot_slot_[column]]; }
  int DeterminantSign() const { return sign_; }

 private:
  struct OffDiagonal {
    int row, col;  // in the permuted matrix
    int entry;     // in the pattern
  };
  struct Block {
    int start = 0, size = 0;  // permuted rows/columns start .. start + size - 1
    int lu = 0;               // its dense column-major LU in lu_
    int off_begin = 0, off_end = 0;  // its entries right of the diagonal block in off_
  };
  struct Fill {
    int slot, entry;  // lu_[slot] = values[entry]
  };
  // Sorts the pattern's entries into fill_ (inside the diagonal blocks) and off_ (above them,
  // grouped by block row), given each row's and column's permuted position and each permuted
  // position's block. False when an entry lies below the diagonal blocks.
  bool PlaceEntries(const std::vector<int>& rows, const std::vector<int>& cols, const std::vector<int>& row_position,
                    const std::vector<int>& col_position, const std::vector<int>& block_of);

  bool analysed_ = false;
  int n_ = 0;
  std::vector<int> row_perm_, col_perm_;  // row/column k of the permuted matrix is row/column ...[k] of A
  std::vector<Block> blocks_;
  std::vector<Fill> fill_;                // the entries inside the diagonal blocks
  std::vector<OffDiagonal> off_;          // entries above the diagonal blocks, grouped by block row
  int permutation_sign_ = 1;              // sign of the row and column permutations together
  // the factorisation
  std::vector<double> lu_;
  std::vector<double> off_values_;
  std::vector<int> pivot_row_;            // per permuted row: the row (of its block) swapped with it at that step
  std::vector<int> pivot_slot_;           // per column of A: where its pivot (U's diagonal entry) lies in lu_
  int sign_ = 1;
  mutable std::vector<double> work_;
};

}  // namespace koppel
