// FCLib (https://frictionalcontactlibrary.github.io) "local" frictional contact problems
// in HDF5, read and written with Debian's libfclib, for wiregrain's reduced problems
// (core/nscd_solver.h: u = W r + q, W in 3×3 blocks, one μ per contact; FCLib's local
// problem with spacedim 3 and no V, R, s).
//
// W is written by default in compressed rows (fclib_matrix nz = −2: p = row pointers,
// i = column indices), the layout Siconos writes; compressed columns (nz = −1: p = column
// pointers, i = row indices) and triplets (nz ≥ 0) on request. Reading accepts all three.
// Triplets use CSparse's convention p = column, i = row index, as Siconos' reader does
// (fclib.h's comment says the opposite, which only matters for a non-symmetric W).
#pragma once

#include <string>

#include "core/nscd/nscd_solver.h"

namespace wiregrain::bench {

// Layout of W in the file (fclib_matrix::nz = −2, −1, or the entry count).
enum class FclibMatrixFormat { compressed_rows, compressed_columns, triplets };

struct FclibInfo {
  std::string title;
  std::string description;
  std::string math_info;
};

// Writes `problem` to `path` (replacing an existing file), every entry of every stored
// 3×3 block. Throws std::runtime_error when libfclib reports a failure.
void write_fclib_local(const std::string& path, const ReducedProblem& problem,
                       const FclibInfo& info = {},
                       FclibMatrixFormat format = FclibMatrixFormat::compressed_rows);

// Reads an FCLib local problem. Throws std::runtime_error if the file cannot be read, is
// not a 3-D local problem, or has V/R (mixed problems are not supported).
ReducedProblem read_fclib_local(const std::string& path, FclibInfo* info = nullptr);

}  // namespace wiregrain::bench
