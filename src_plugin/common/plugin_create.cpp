#include "plugin_create.h"

#include <mpi.h>

#include <algorithm>

#include "atom.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

namespace wiregrain_lmp {

int max_atom_tag(LAMMPS_NS::LAMMPS *lmp) {
  LAMMPS_NS::Atom *atom = lmp->atom;
  int local = 0, global = 0;
  for (int i = 0; i < atom->nlocal; i++) local = std::max(local, atom->tag[i]);
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, lmp->world);
  return global;
}

LAMMPS_NS::bigint finish_created_atoms(LAMMPS_NS::LAMMPS *lmp, int nlocal_before) {
  LAMMPS_NS::Atom *atom = lmp->atom;
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (int m = 0; m < modify->nfix; m++) {
    LAMMPS_NS::Fix *fix = modify->fix[m];
    if (!fix->create_attribute) continue;
    fix->pre_set_arrays();
    for (int i = nlocal_before; i < atom->nlocal; i++) fix->set_arrays(i);
  }
  LAMMPS_NS::bigint created_local = atom->nlocal - nlocal_before, created = 0;
  MPI_Allreduce(&created_local, &created, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  atom->natoms += created;
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
  return created;
}

}  // namespace wiregrain_lmp
