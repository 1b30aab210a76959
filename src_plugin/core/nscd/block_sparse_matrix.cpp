// BlockSparseMatrix3 (block_sparse_matrix.h).
#include "core/nscd/block_sparse_matrix.h"

#include <algorithm>
#include <string>

#include "core/common/errors.h"

namespace wiregrain {

BlockSparseMatrix3::BlockSparseMatrix3(int block_count) {
  if (block_count < 0) throw InvalidArgument("W", "negative block count");
  rows_.resize(block_count);
}

long BlockSparseMatrix3::stored_blocks() const {
  long count = 0;
  for (const auto& row : rows_) count += static_cast<long>(row.size());
  return count;
}

void BlockSparseMatrix3::add(int row, int column, const Eigen::Matrix3d& block) {
  if (row < 0 || row >= block_count() || column < 0 || column >= block_count()) {
    throw InvalidArgument("W", "block (" + std::to_string(row) + ", " + std::to_string(column) +
                                   ") outside a " + std::to_string(block_count()) +
                                   "-block matrix");
  }
  std::vector<Entry>& entries = rows_[row];
  auto it = std::lower_bound(entries.begin(), entries.end(), column,
                             [](const Entry& e, int col) { return e.column < col; });
  if (it != entries.end() && it->column == column) {
    it->block += block;
  } else {
    entries.insert(it, Entry{column, block});
  }
}

const Eigen::Matrix3d* BlockSparseMatrix3::find(int row, int column) const {
  const std::vector<Entry>& entries = rows_[row];
  auto it = std::lower_bound(entries.begin(), entries.end(), column,
                             [](const Entry& e, int col) { return e.column < col; });
  return (it != entries.end() && it->column == column) ? &it->block : nullptr;
}

BlockSparseMatrix3 BlockSparseMatrix3::from_dense(const Eigen::MatrixXd& dense) {
  if (dense.rows() != dense.cols() || dense.rows() % 3 != 0) {
    throw InvalidArgument("W", "dense W must be square with a size divisible by 3");
  }
  const int n = static_cast<int>(dense.rows() / 3);
  BlockSparseMatrix3 matrix(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Matrix3d block = dense.block<3, 3>(3 * i, 3 * j);
      if (!block.isZero(0.0)) matrix.rows_[i].push_back(Entry{j, block});
    }
  }
  return matrix;
}

Eigen::MatrixXd BlockSparseMatrix3::to_dense() const {
  const int n = block_count();
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) {
    for (const Entry& e : rows_[i]) dense.block<3, 3>(3 * i, 3 * e.column) = e.block;
  }
  return dense;
}

Eigen::VectorXd BlockSparseMatrix3::multiply(const Eigen::VectorXd& x) const {
  const int n = block_count();
  if (x.size() != 3 * n) throw InvalidArgument("x", "vector size does not match W");
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    for (const Entry& e : rows_[i]) y.segment<3>(3 * i) += e.block * x.segment<3>(3 * e.column);
  }
  return y;
}

}  // namespace wiregrain
