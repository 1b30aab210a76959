/* What each atom is, for the styles that act on wire beads only or on grains only: a
   group that mixes the two is refused by the styles that act on one kind (a grain taken
   for a bead, or a bead for a grain, gets wrong forces or is integrated wrongly) and
   filtered by kind by the outputs (docs/commands/<style>.md, "Restrictions"). Reads the atom
   styles through common/grain_shape_source.h and common/bead_chain_links.h, as
   common/grain_atoms.h does. Not a style of its own. */
#ifndef WIREGRAIN_ATOM_KINDS_H
#define WIREGRAIN_ATOM_KINDS_H

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}  // namespace LAMMPS_NS

namespace wiregrain_lmp {

class BeadChainLinks;
class GrainShapeSource;

enum class AtomKind {
  bead,         // a wire bead: an atom with chain links; where the atom style has wire and no
                // grains (atom_style wire), any atom (a lone bead too)
  polyhedron,   // a grain of atom_style polyhedron with a shape (shape index >= 0)
  stock_grain,  // without atom_style polyhedron: a sphere (atom_style sphere, granular) or a
                // superquadric without chain links
  shapeless,    // of atom_style polyhedron, without a shape and without links: made by
                // create_atoms, or a lone bead of a hybrid with wire
  other         // none of these (atom_style atomic, ...)
};

// The atoms of each kind in a group, summed over the ranks.
struct AtomKindCounts {
  long beads = 0, polyhedra = 0, stock_grains = 0, shapeless = 0, others = 0;
  long grains() const { return polyhedra + stock_grains; }
};

class AtomKinds {
 public:
  explicit AtomKinds(LAMMPS_NS::LAMMPS *lmp);
  AtomKind of(int i) const;
  // the grains (polyhedra with a shape, stock grains) are no beads; a shapeless atom and
  // an atom of kind other may be a lone bead
  bool is_grain(int i) const;
  AtomKindCounts count(int groupbit) const;  // collective

 private:
  LAMMPS_NS::LAMMPS *lmp_;
  const GrainShapeSource *polyhedra_;  // atom_style polyhedron, or nullptr
  const BeadChainLinks *chains_;       // atom_style wire, or nullptr
  bool stock_grains_;                  // atom_style sphere, granular or superquadric
};

// At a style's init (collective): stops with "<kind> <style> (id ID): group 'G' holds N
// grains (give the wire beads only)" when group igroup holds grains (a style that acts on
// wire beads only).
void require_no_grains(LAMMPS_NS::LAMMPS *lmp, int igroup, const std::string &kind, const std::string &style,
                       const std::string &id);
// ... and "group 'G' holds N wire beads (give the grains only)" when it holds linked beads
// (a style that acts on grains only).
void require_no_beads(LAMMPS_NS::LAMMPS *lmp, int igroup, const std::string &kind, const std::string &style,
                      const std::string &id);

}  // namespace wiregrain_lmp

#endif
