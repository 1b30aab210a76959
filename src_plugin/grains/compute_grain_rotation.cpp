#include "compute_grain_rotation.h"

#include <mpi.h>

#include <string>

#include <Eigen/Geometry>

#include "atom.h"
#include "atom_vec_polyhedron.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeGrainRotation::ComputeGrainRotation(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), values_(NULL), nmax_(0), kinds_(lmp) {
  wiregrain_lmp::StyleArgs args(error, "compute", "grain/rotation", id, narg, arg, iarg);
  if (!AtomVecPolyhedron::of(atom))
    args.fail("needs atom_style polyhedron (or hybrid with polyhedron), not '" + std::string(atom->atom_style) + "'");
  if (!args.done()) args.unknown_keyword(args.next_keyword());
  iarg = narg;
  vector_flag = 1;
  size_vector = 4;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 8;
  vector = new double[size_vector];
}

ComputeGrainRotation::~ComputeGrainRotation() {
  delete[] vector;
  memory->destroy(values_);
}

bool ComputeGrainRotation::counts(int i) const {
  return (atom->mask[i] & groupbit) && kinds_.of(i) == wiregrain_lmp::AtomKind::polyhedron;
}

void ComputeGrainRotation::compute_vector() {
  invoked_vector = update->ntimestep;
  double local[4] = {0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < atom->nlocal; i++) {
    if (!counts(i)) continue;
    for (int d = 0; d < 3; d++) {
      local[0] += 0.5 * atom->omega[i][d] * atom->angmom[i][d];
      local[1 + d] += atom->angmom[i][d];
    }
  }
  MPI_Allreduce(local, vector, 4, MPI_DOUBLE, MPI_SUM, world);
}

void ComputeGrainRotation::compute_peratom() {
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(values_);
    memory->create(values_, nmax_, size_peratom_cols, "grain/rotation:values");
    array_atom = values_;
  }
  for (int i = 0; i < atom->nlocal; i++) {
    double *out = values_[i];
    for (int k = 0; k < size_peratom_cols; k++) out[k] = 0.0;
    if (!counts(i)) continue;
    const double *q = atom->quaternion[i];
    const Eigen::Quaterniond r = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    const Eigen::Vector3d w_body = r.conjugate() * Eigen::Vector3d(atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]);
    for (int k = 0; k < 4; k++) out[k] = q[k];
    for (int d = 0; d < 3; d++) {
      out[4 + d] = w_body[d];
      out[7] += 0.5 * atom->omega[i][d] * atom->angmom[i][d];
    }
  }
}

double ComputeGrainRotation::memory_usage() { return double(nmax_) * size_peratom_cols * sizeof(double); }
