// A square matrix of 3×3 blocks stored by block row: the Delassus operator W of a contact
// problem (one block row and column per contact; a block between two contacts that share
// a body), as the reduced problem holds it (core/nscd/reduced_problem.h) and the stick
// solves of method subspace read it (core/nscd/subspace_correction.h).
#pragma once

#include <Eigen/Dense>

#include <vector>

namespace wiregrain {

// n × n blocks of 3×3, stored by block row (each row sorted by column).
class BlockSparseMatrix3 {
 public:
  struct Entry {
    int column;
    Eigen::Matrix3d block;
  };

  BlockSparseMatrix3() = default;
  explicit BlockSparseMatrix3(int block_count);

  int block_count() const { return static_cast<int>(rows_.size()); }
  long stored_blocks() const;
  // Adds `block` to block (row, column), creating it if absent.
  void add(int row, int column, const Eigen::Matrix3d& block);
  // nullptr when the block is not stored.
  const Eigen::Matrix3d* find(int row, int column) const;
  const std::vector<Entry>& row(int row) const { return rows_[row]; }

  // Keeps the blocks with at least one non-zero entry. dense: 3n × 3n.
  static BlockSparseMatrix3 from_dense(const Eigen::MatrixXd& dense);
  Eigen::MatrixXd to_dense() const;
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;

 private:
  std::vector<std::vector<Entry>> rows_;
};

}  // namespace wiregrain
