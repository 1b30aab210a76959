// Shared steps of the plugin's atom-creating commands (create_wire, create_grains): the
// new atoms get consecutive IDs after the largest one, identically on every rank.
#ifndef WIREGRAIN_PLUGIN_CREATE_H
#define WIREGRAIN_PLUGIN_CREATE_H

#include "lmptype.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wiregrain_lmp {

// the largest atom ID on any rank (0 without atoms)
int max_atom_tag(LAMMPS_NS::LAMMPS *lmp);

// After this rank created atoms nlocal_before .. nlocal−1: let fixes initialise them
// (set_arrays), add them to natoms and rebuild the atom map. Returns how many atoms all
// ranks created together.
LAMMPS_NS::bigint finish_created_atoms(LAMMPS_NS::LAMMPS *lmp, int nlocal_before);

}  // namespace wiregrain_lmp

#endif
