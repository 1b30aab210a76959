#include "compute_column_height.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "error.h"
#include "group.h"
#include "update.h"
#include <mpi.h>

#include "core/column/observables.h"
#include "core/geometry/shape_library.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeColumnHeight::ComputeColumnHeight(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), quantile_(0.98), grains_(atom) {
  wiregrain_lmp::StyleArgs args(error, "compute", "column/height", id, narg, arg, iarg, {"quantile"});
  std::string why;
  if (!grains_.available(why)) args.fail(why);
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "quantile") quantile_ = args.value_in_range(key, 0.0, 1.0, "[0, 1]");
    else args.unknown_keyword(key);
  }
  iarg = narg;
  scalar_flag = 1;
  extscalar = 0;
}

void ComputeColumnHeight::init() {
  long local = 0, total = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && grains_.is_grain(i)) local++;
  MPI_Allreduce(&local, &total, 1, MPI_LONG, MPI_SUM, world);
  if (total == 0)
    wiregrain_lmp::style_error(error, "compute", "column/height", id,
                               "group '" + std::string(group->names[igroup]) + "' has no grains");
}

// The quantile of the tops over all ranks without gathering them: two reductions (the
// count, the extremes) and one per bisection round of the order statistics (core
// quantile_of_parts: at most 128).
double ComputeColumnHeight::compute_scalar() {
  invoked_scalar = update->ntimestep;
  std::vector<double> tops;
  for (int i = 0; i < atom->nlocal; i++) {
    if ((atom->mask[i] & groupbit) && grains_.is_grain(i)) tops.push_back(grains_.top(i));
  }
  long counts[2] = {static_cast<long>(tops.size()), 0}, totals[2];  // tops, tops not finite
  for (double top : tops) counts[1] += std::isfinite(top) ? 0 : 1;
  MPI_Allreduce(counts, totals, 2, MPI_LONG, MPI_SUM, world);
  if (totals[1] > 0)
    wiregrain_lmp::style_error(error, "compute", "column/height", id,
                               std::to_string(totals[1]) + " grain top height(s) are not finite");
  const long n = totals[0];
  if (n == 0) return scalar = 0.0;
  std::sort(tops.begin(), tops.end());
  double extremes[2] = {tops.empty() ? -HUGE_VAL : -tops.front(), tops.empty() ? -HUGE_VAL : tops.back()}, global[2];
  MPI_Allreduce(extremes, global, 2, MPI_DOUBLE, MPI_MAX, world);
  const auto count_at_most = [&](double x) {
    const long here = static_cast<long>(std::upper_bound(tops.begin(), tops.end(), x) - tops.begin());
    long all = 0;
    MPI_Allreduce(&here, &all, 1, MPI_LONG, MPI_SUM, world);
    return all;
  };
  scalar = wiregrain::quantile_of_parts(n, -global[0], global[1], quantile_, count_at_most);
  return scalar;
}
