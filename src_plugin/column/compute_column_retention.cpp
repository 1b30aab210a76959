#include "compute_column_retention.h"

#include <mpi.h>

#include <string>
#include <vector>

#include <Eigen/Core>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "update.h"

#include "core/column/observables.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeColumnRetention::ComputeColumnRetention(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), grains_(atom), wire_groupbit_(0), axis_given_(false), fixed_radius_(0.0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "column/retention", id, narg, arg, iarg, {"axis"});
  std::string why;
  if (!grains_.available(why)) args.fail(why);
  if (args.done()) args.fail("expected the wire group or 'radius r' after 'column/retention'");
  const std::string first = args.next_word();
  if (first == "radius") {
    fixed_radius_ = args.value_positive(first);
  } else {
    wire_group_ = first;
    if (group->find(wire_group_.c_str()) < 0) args.fail("wire group '" + wire_group_ + "' does not exist");
  }
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "axis") {
      axis_[0] = args.value_double(key);
      axis_[1] = args.value_double(key);
      axis_given_ = true;
    } else {
      args.unknown_keyword(key);
    }
  }
  iarg = narg;
  vector_flag = 1;
  size_vector = 4;
  extvector = 0;
  vector = new double[size_vector];
}

ComputeColumnRetention::~ComputeColumnRetention() { delete[] vector; }

void ComputeColumnRetention::init() {
  if (fixed_radius_ > 0.0) {
    wire_groupbit_ = 0;
  } else {
    const int igroup_wire = group->find(wire_group_.c_str());
    if (igroup_wire < 0)
      wiregrain_lmp::style_error(error, "compute", "column/retention", id,
                                 "wire group '" + wire_group_ + "' no longer exists");
    wire_groupbit_ = group->bitmask[igroup_wire];
  }
  long local[2] = {0, 0}, total[2];  // grains, beads
  for (int i = 0; i < atom->nlocal; i++) {
    if ((atom->mask[i] & groupbit) && grains_.is_grain(i)) local[0]++;
    if ((atom->mask[i] & wire_groupbit_) && !grains_.is_grain(i)) local[1]++;
  }
  MPI_Allreduce(local, total, 2, MPI_LONG, MPI_SUM, world);
  if (total[0] == 0)
    wiregrain_lmp::style_error(error, "compute", "column/retention", id,
                               "group '" + std::string(group->names[igroup]) + "' has no grains");
  if (fixed_radius_ <= 0.0 && total[1] == 0)
    wiregrain_lmp::style_error(error, "compute", "column/retention", id,
                               "wire group '" + wire_group_ + "' has no wire beads");
}

// The cylinder radius from all ranks' beads (sums of distances), then the grains inside.
void ComputeColumnRetention::compute_vector() {
  invoked_vector = update->ntimestep;
  const Eigen::Vector2d axis = axis_given_ ? Eigen::Vector2d(axis_[0], axis_[1])
                                           : Eigen::Vector2d(0.5 * (domain->boxlo[0] + domain->boxhi[0]),
                                                             0.5 * (domain->boxlo[1] + domain->boxhi[1]));
  std::vector<Eigen::Vector3d> beads, grains;
  for (int i = 0; i < atom->nlocal; i++) {
    const Eigen::Vector3d x(atom->x[i][0], atom->x[i][1], atom->x[i][2]);
    if ((atom->mask[i] & wire_groupbit_) && !grains_.is_grain(i)) beads.push_back(x);
    if ((atom->mask[i] & groupbit) && grains_.is_grain(i)) grains.push_back(x);
  }
  double local[2] = {beads.empty() ? 0.0 : wiregrain::mean_axis_distance(beads, axis) * double(beads.size()),
                     double(beads.size())},
         total[2];
  MPI_Allreduce(local, total, 2, MPI_DOUBLE, MPI_SUM, world);
  const double radius = fixed_radius_ > 0.0 ? fixed_radius_ : total[1] > 0.0 ? total[0] / total[1] : 0.0;
  const wiregrain::Retention mine = wiregrain::retention(grains, axis, radius);
  double counts[2] = {double(mine.inside), double(mine.total)}, all[2];
  MPI_Allreduce(counts, all, 2, MPI_DOUBLE, MPI_SUM, world);
  vector[0] = all[1] > 0.0 ? all[0] / all[1] : 0.0;
  vector[1] = radius;
  vector[2] = all[0];
  vector[3] = all[1];
}
