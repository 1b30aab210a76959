#include "compute_wire_energy.h"

#include <mpi.h>

#include <cstring>
#include <string>

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "core/wire/wire_elasticity.h"
#include "plugin_args.h"

using namespace LAMMPS_NS;

ComputeWireEnergy::ComputeWireEnergy(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), fix_id_(NULL), source_(NULL), bead_values_(NULL), nmax_(0) {
  wiregrain_lmp::StyleArgs args(error, "compute", "wire/energy", id, narg, arg, iarg, {"fix"});
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
  source_ = NULL;
  int found = 0;
  for (int k = 0; k < modify->nfix; k++) {
    Fix *f = modify->fix[k];
    if (strcmp(f->style, "wire/elastic") != 0) continue;
    if (fix_id_ && strcmp(fix_id_, f->id) != 0) continue;
    source_ = dynamic_cast<const wiregrain_lmp::WireEnergySource *>(f);
    found++;
  }
  if (fix_id_ && !source_)
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id,
                               "fix ID '" + std::string(fix_id_) + "' is not a fix wire/elastic");
  if (!source_)
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id, "needs a fix wire/elastic");
  if (found > 1)
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id,
                               "several fix wire/elastic are defined: name one with 'fix ID'");
}

void ComputeWireEnergy::check_current() {
  if (!source_) init();  // defined since the last run and invoked before the next (write_dump)
  if (update->ntimestep != source_->energies_step())
    wiregrain_lmp::style_error(error, "compute", "wire/energy", id,
                               "fix wire/elastic has not computed this step (use the compute "
                               "only on steps of a run, e.g. in thermo output)");
}

void ComputeWireEnergy::compute_vector() {
  invoked_vector = update->ntimestep;
  check_current();
  wiregrain::WireEnergyTotals local;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local.add(source_->bead_energy(i));
  const double local_sums[3] = {local.stretching_energy, local.bending_energy, local.length};
  double sums[3];
  MPI_Allreduce(local_sums, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  wiregrain::WireEnergyTotals totals;
  totals.stretching_energy = sums[0];
  totals.bending_energy = sums[1];
  totals.length = sums[2];
  vector[0] = totals.stretching_energy;
  vector[1] = totals.bending_energy;
  vector[2] = totals.total_energy();
  vector[3] = totals.length;
  vector[4] = totals.energy_per_length();
}

void ComputeWireEnergy::compute_peratom() {
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(bead_values_);
    memory->create(bead_values_, nmax_, 3, "wire/energy:bead_values");
    array_atom = bead_values_;
  }
  check_current();
  for (int i = 0; i < atom->nlocal; i++) {
    const wiregrain::BeadElasticEnergy e =
        (atom->mask[i] & groupbit) ? source_->bead_energy(i) : wiregrain::BeadElasticEnergy();
    bead_values_[i][0] = e.stretching;
    bead_values_[i][1] = e.bending;
    bead_values_[i][2] = e.segment_length;
  }
}

double ComputeWireEnergy::memory_usage() { return double(nmax_) * 3 * sizeof(double); }
