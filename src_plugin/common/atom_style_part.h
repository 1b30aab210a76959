/* How common/ reads the plugin's atom styles without knowing their classes: a style
   implements an interface common/ declares (grain_shape_source.h, bead_chain_links.h) and
   atom_style_part<Interface>(atom) finds it, whether it is the atom style or one of the
   sub-styles of atom_style hybrid. */

#ifndef WIREGRAIN_ATOM_STYLE_PART_H
#define WIREGRAIN_ATOM_STYLE_PART_H

#include <vector>

#include "atom_vec.h"

namespace LAMMPS_NS {
class Atom;
}

namespace wiregrain_lmp {

// The atom style of this system, or the sub-styles of atom_style hybrid in their order.
std::vector<LAMMPS_NS::AtomVec *> atom_style_parts(LAMMPS_NS::Atom *atom);

// The first of atom_style_parts(atom) that implements Interface, or nullptr.
template <class Interface>
Interface *atom_style_part(LAMMPS_NS::Atom *atom) {
  for (LAMMPS_NS::AtomVec *style : atom_style_parts(atom))
    if (Interface *part = dynamic_cast<Interface *>(style)) return part;
  return nullptr;
}

}  // namespace wiregrain_lmp

#endif
