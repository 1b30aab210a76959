#include "compute_grain_shape.h"

#include <string>

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include "plugin_args.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kColumns = 7;
// the shape index of grains without a library shape
constexpr double kSphere = -1.0, kSuperquadric = -3.0;
}

ComputeGrainShape::ComputeGrainShape(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), grains_(atom), values_(NULL), nmax_(0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "grain/shape", id, narg, arg, iarg);
  std::string why;
  if (!grains_.available(why)) args.fail(why);
  if (!args.done()) args.unknown_keyword(args.next_keyword());
  iarg = narg;
  peratom_flag = 1;
  size_peratom_cols = kColumns;
}

ComputeGrainShape::~ComputeGrainShape() { memory->destroy(values_); }

void ComputeGrainShape::compute_peratom() {
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(values_);
    memory->create(values_, nmax_, kColumns, "grain/shape:values");
    array_atom = values_;
  }
  for (int i = 0; i < atom->nlocal; i++) {
    double *out = values_[i];
    for (int k = 0; k < kColumns; k++) out[k] = 0.0;
    if (!(atom->mask[i] & groupbit) || !grains_.is_grain(i)) {
      out[0] = -2.0;  // no grain
      continue;
    }
    const bool polyhedron = grains_.is_polyhedron(i);
    const bool superquadric = !polyhedron && atom->superquadric_flag;
    out[0] = polyhedron ? atom->shapetype[i] : superquadric ? kSuperquadric : kSphere;
    out[1] = 1.0;
    if (polyhedron || superquadric)
      for (int k = 0; k < 4; k++) out[1 + k] = atom->quaternion[i][k];
    out[5] = atom->radius[i];
    out[6] = grains_.top(i);
  }
}

double ComputeGrainShape::memory_usage() { return double(nmax_) * kColumns * sizeof(double); }
