#include "compute_column_height.h"

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
#include "plugin_comm.h"

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

double ComputeColumnHeight::compute_scalar() {
  invoked_scalar = update->ntimestep;
  std::vector<double> tops;
  for (int i = 0; i < atom->nlocal; i++) {
    if ((atom->mask[i] & groupbit) && grains_.is_grain(i)) tops.push_back(grains_.top(i));
  }
  const std::vector<double> all = wiregrain_lmp::all_gather_records(world, tops);
  scalar = all.empty() ? 0.0 : wiregrain::quantile(all, quantile_);
  return scalar;
}
