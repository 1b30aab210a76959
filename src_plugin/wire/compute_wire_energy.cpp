#include "compute_wire_energy.h"

#include <mpi.h>

#include <cstring>
#include <string>

#include "atom.h"
#include "error.h"
#include "fix_wire_elastic.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeWireEnergy::ComputeWireEnergy(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), fix_id_(NULL), fix_(NULL), bead_values_(NULL), nmax_(0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "wire/energy", id, narg, arg, iarg);
  iarg = narg;
  while (!args.done()) {
    const std::string key = args.next_keyword();
    if (key == "fix") {
      const std::string name = args.value_word(key);
      fix_id_ = new char[name.size() + 1];
      strcpy(fix_id_, name.c_str());
    } else {
      args.unknown_keyword(key);
    }
  }
  vector_flag = 1;
  size_vector = 5;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 3;
  vector = new double[size_vector];
}

ComputeWireEnergy::~ComputeWireEnergy() {
  delete[] fix_id_;
  delete[] vector;
  memory->destroy(bead_values_);
}

void ComputeWireEnergy::init() {
  fix_ = NULL;
  int found = 0;
  for (int k = 0; k < modify->nfix; k++) {
    FixWireElastic *f = dynamic_cast<FixWireElastic *>(modify->fix[k]);
    if (!f) continue;
    if (fix_id_ && strcmp(fix_id_, f->id) != 0) continue;
    fix_ = f;
    found++;
  }
  if (fix_id_ && !fix_)
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id,
                               "fix ID '" + std::string(fix_id_) + "' is not a fix wire/elastic");
  if (!fix_)
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id, "needs a fix wire/elastic");
  if (found > 1)
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id,
                               "several fix wire/elastic are defined: name one with 'fix ID'");
}

double **ComputeWireEnergy::current_fix_values() {
  if (update->ntimestep != fix_->forces_step())
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id,
                               "fix wire/elastic has not computed this step (use the compute "
                               "only on steps of a run, e.g. in thermo output)");
  return fix_->array_atom;
}

void ComputeWireEnergy::compute_vector() {
  invoked_vector = update->ntimestep;
  double **values = current_fix_values();
  double local[3] = {0.0, 0.0, 0.0}, sums[3];
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      for (int k = 0; k < 3; k++) local[k] += values[i][k];
  MPI_Allreduce(local, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  vector[0] = sums[0];
  vector[1] = sums[1];
  vector[2] = sums[0] + sums[1];
  vector[3] = sums[2];
  vector[4] = sums[2] > 0.0 ? vector[2] / sums[2] : 0.0;
}

void ComputeWireEnergy::compute_peratom() {
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(bead_values_);
    memory->create(bead_values_, nmax_, 3, "wire/energy:bead_values");
    array_atom = bead_values_;
  }
  double **values = current_fix_values();
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < 3; k++) bead_values_[i][k] = (atom->mask[i] & groupbit) ? values[i][k] : 0.0;
}

double ComputeWireEnergy::memory_usage() { return double(nmax_) * 3 * sizeof(double); }
