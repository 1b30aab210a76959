// Which atoms are grains, for the column observables: the polyhedra of atom_style
// polyhedron, or, in a system without it, the stock granular spheres (atom_style sphere or
// granular) or superquadrics (atom_style superquadric) that are not wire beads (no chain
// links). Reads the atom styles through common/grain_shape_source.h and
// common/bead_chain_links.h. Not a style of its own.
#ifndef WIREGRAIN_GRAIN_ATOMS_H
#define WIREGRAIN_GRAIN_ATOMS_H

#include <string>

namespace LAMMPS_NS {
class Atom;
}  // namespace LAMMPS_NS

namespace wiregrain_lmp {

class BeadChainLinks;
class GrainShapeSource;

class GrainAtoms {
 public:
  explicit GrainAtoms(LAMMPS_NS::Atom *atom);
  // false when the atom style has neither polyhedra nor spheres; `why` then says so
  bool available(std::string &why) const;
  bool is_grain(int i) const;
  bool is_polyhedron(int i) const;  // a grain of atom_style polyhedron (else a stock sphere)
  // the grain's highest point (core vertex + sweep radius; a sphere's centre + radius; a
  // superquadric's support point along +z)
  double top(int i) const;

 private:
  LAMMPS_NS::Atom *atom_;
  const GrainShapeSource *polyhedra_;  // atom_style polyhedron, or nullptr
  const BeadChainLinks *chains_;       // atom_style wire, or nullptr
};

}  // namespace wiregrain_lmp

#endif
