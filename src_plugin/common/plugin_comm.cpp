#include "plugin_comm.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "lammps.h"
#include "memory.h"

namespace wiregrain_lmp {

void ensure_ghost_reach(LAMMPS_NS::LAMMPS *lmp, double reach, double radius) {
  const bool halved = lmp->domain->triclinic == 0 && lmp->atom->radius != nullptr;
  const double cutoff = halved ? 2.0 * reach : reach + radius;
  if (lmp->comm->cutghostuser < cutoff) lmp->comm->cutghostuser = cutoff;
}

void periodic_image_shift(const LAMMPS_NS::Domain *domain, int pbc_flag, const int *pbc, bool border,
                          double s[3]) {
  s[0] = s[1] = s[2] = 0.0;
  if (pbc_flag == 0) return;
  if (domain->triclinic == 0) {
    s[0] = pbc[0] * domain->xprd;
    s[1] = pbc[1] * domain->yprd;
    s[2] = pbc[2] * domain->zprd;
  } else if (border) {
    s[0] = pbc[0];
    s[1] = pbc[1];
    s[2] = pbc[2];
  } else {
    s[0] = pbc[0] * domain->xprd + pbc[5] * domain->xy + pbc[4] * domain->xz;
    s[1] = pbc[1] * domain->yprd + pbc[3] * domain->yz;
    s[2] = pbc[2] * domain->zprd;
  }
}

void deforming_image_velocity(int pbc_flag, const int *pbc, int deform_vremap, const double *h_rate,
                              double dv[3]) {
  dv[0] = dv[1] = dv[2] = 0.0;
  if (!pbc_flag || !deform_vremap) return;
  dv[0] = pbc[0] * h_rate[0] + pbc[5] * h_rate[5] + pbc[4] * h_rate[4];
  dv[1] = pbc[1] * h_rate[1] + pbc[3] * h_rate[3];
  dv[2] = pbc[2] * h_rate[2];
}

const double *fix_restart_record(const LAMMPS_NS::Atom *atom, int nlocal, int nth, int length) {
  if (!atom->extra || atom->nextra_store <= 0) return nullptr;
  const double *row = atom->extra[nlocal];
  int offset = 0;
  // each record starts with its own length (length word included): walk the nth before ours
  for (int i = 0; i <= nth; i++) {
    const double words = row[offset];
    if (!(words >= 1.0) || offset + words > atom->nextra_store) return nullptr;
    if (i == nth) return length < 0 || static_cast<int>(words) == length + 1 ? row + offset + 1 : nullptr;
    offset += static_cast<int>(words);
  }
  return nullptr;
}

void clear_restart_record(LAMMPS_NS::LAMMPS *lmp, int i) {
  LAMMPS_NS::Atom *atom = lmp->atom;
  if (!atom->extra || atom->nextra_store <= 0) return;
  lmp->memory->grow(atom->extra, atom->nmax, atom->nextra_store, "atom:extra");
  for (int k = 0; k < atom->nextra_store; k++) atom->extra[i][k] = 0.0;
}

std::vector<double> all_gather_records(MPI_Comm comm, const std::vector<double> &mine) {
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  const int my_count = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int p = 1; p < nprocs; p++) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), my_count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, comm);
  return all;
}

}  // namespace wiregrain_lmp
