// FCLib local problems <-> wiregrain reduced problems (see fclib_io.h).
#include "fclib_io.h"

#include <cstdio>
#include <stdexcept>
#include <vector>

extern "C" {
#include <fclib.h>
}

namespace wiregrain::bench {

void write_fclib_local(const std::string& path, const ReducedProblem& problem,
                       const FclibInfo& info, FclibMatrixFormat format) {
  problem.validate();
  const int n = problem.contact_count();
  const int size = 3 * n;

  // Entries in row order (block rows are sorted by column).
  std::vector<int> rows, columns;
  std::vector<double> values;
  for (int block_row = 0; block_row < n; ++block_row) {
    for (int a = 0; a < 3; ++a) {
      for (const BlockSparseMatrix3::Entry& entry : problem.W.row(block_row)) {
        for (int b = 0; b < 3; ++b) {
          rows.push_back(3 * block_row + a);
          columns.push_back(3 * entry.column + b);
          values.push_back(entry.block(a, b));
        }
      }
    }
  }
  const int count = static_cast<int>(values.size());
  std::vector<int> pointers, indices;
  std::vector<double> x;
  fclib_matrix W{};
  W.nzmax = count;
  W.m = size;
  W.n = size;
  W.info = nullptr;
  if (format == FclibMatrixFormat::compressed_rows) {
    pointers.assign(size + 1, 0);
    for (int k = 0; k < count; ++k) ++pointers[rows[k] + 1];
    for (int r = 0; r < size; ++r) pointers[r + 1] += pointers[r];
    indices = columns;
    x = values;
    W.nz = -2;
  } else if (format == FclibMatrixFormat::compressed_columns) {
    pointers.assign(size + 1, 0);
    for (int k = 0; k < count; ++k) ++pointers[columns[k] + 1];
    for (int c = 0; c < size; ++c) pointers[c + 1] += pointers[c];
    std::vector<int> next(pointers.begin(), pointers.end() - 1);
    indices.resize(count);
    x.resize(count);
    for (int k = 0; k < count; ++k) {
      const int slot = next[columns[k]]++;
      indices[slot] = rows[k];
      x[slot] = values[k];
    }
    W.nz = -1;
  } else {
    pointers = columns;  // CSparse triplets: p = column, i = row
    indices = rows;
    x = values;
    W.nz = count;
  }
  W.p = pointers.data();
  W.i = indices.data();
  W.x = x.data();

  std::vector<double> q(problem.q.data(), problem.q.data() + size);
  std::vector<double> mu(problem.mu);
  std::string title = info.title, description = info.description, math_info = info.math_info;
  fclib_info problem_info{};
  problem_info.title = title.data();
  problem_info.description = description.data();
  problem_info.math_info = math_info.data();

  fclib_local local{};
  local.W = &W;
  local.V = nullptr;
  local.R = nullptr;
  local.mu = mu.data();
  local.q = q.data();
  local.s = nullptr;
  local.spacedim = 3;
  local.info = &problem_info;

  std::remove(path.c_str());  // fclib_write_local opens an existing file for update
  if (fclib_write_local(&local, path.c_str()) != 1) {
    throw std::runtime_error("fclib_write_local failed for " + path);
  }
}

ReducedProblem read_fclib_local(const std::string& path, FclibInfo* info) {
  fclib_local* local = fclib_read_local(path.c_str());
  if (local == nullptr) throw std::runtime_error("fclib_read_local failed for " + path);
  struct Release {
    fclib_local* p;
    ~Release() { fclib_delete_local(p); }
  } release{local};

  if (local->spacedim != 3) {
    throw std::runtime_error(path + ": spacedim " + std::to_string(local->spacedim) +
                             ", only 3-D problems are supported");
  }
  if (local->V != nullptr || local->R != nullptr) {
    throw std::runtime_error(path + ": mixed problems (V, R) are not supported");
  }
  const fclib_matrix& W = *local->W;
  if (W.m != W.n || W.m % 3 != 0) {
    throw std::runtime_error(path + ": W is " + std::to_string(W.m) + " x " +
                             std::to_string(W.n) + ", expected square with 3 rows per contact");
  }
  const int n = W.m / 3;
  ReducedProblem problem;
  problem.W = BlockSparseMatrix3(n);
  auto add_entry = [&](int row, int col, double x) {
    if (row < 0 || row >= W.m || col < 0 || col >= W.n) {
      throw std::runtime_error(path + ": W entry index out of range");
    }
    if (x == 0.0) return;
    Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
    block(row % 3, col % 3) = x;
    problem.W.add(row / 3, col / 3, block);
  };
  if (W.nz == -2) {  // compressed rows
    for (int row = 0; row < W.m; ++row) {
      for (int k = W.p[row]; k < W.p[row + 1]; ++k) add_entry(row, W.i[k], W.x[k]);
    }
  } else if (W.nz == -1) {  // compressed columns
    for (int col = 0; col < W.n; ++col) {
      for (int k = W.p[col]; k < W.p[col + 1]; ++k) add_entry(W.i[k], col, W.x[k]);
    }
  } else {  // triplets, CSparse convention
    for (int k = 0; k < W.nz; ++k) add_entry(W.i[k], W.p[k], W.x[k]);
  }
  problem.q = Eigen::Map<const Eigen::VectorXd>(local->q, W.m);
  problem.mu.assign(local->mu, local->mu + n);
  if (info != nullptr && local->info != nullptr) {
    info->title = local->info->title ? local->info->title : "";
    info->description = local->info->description ? local->info->description : "";
    info->math_info = local->info->math_info ? local->info->math_info : "";
  }
  problem.validate();
  return problem;
}

}  // namespace wiregrain::bench
