#include "atom_style_part.h"

#include "atom.h"
#include "atom_vec_hybrid.h"

namespace wiregrain_lmp {

std::vector<LAMMPS_NS::AtomVec *> atom_style_parts(LAMMPS_NS::Atom *atom) {
  if (LAMMPS_NS::AtomVecHybrid *hybrid = dynamic_cast<LAMMPS_NS::AtomVecHybrid *>(atom->avec))
    return std::vector<LAMMPS_NS::AtomVec *>(hybrid->styles, hybrid->styles + hybrid->nstyles);
  return {atom->avec};
}

}  // namespace wiregrain_lmp
