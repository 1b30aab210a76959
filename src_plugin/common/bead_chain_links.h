/* An atom style whose atoms may be beads of chains (atom_style wire): the atom IDs of the
   previous and the next bead of owned or ghost atom i, 0 at a free end and for an atom
   that is no bead. A bead and its next bead bound a segment, the spherocylinder of the
   bead's radius between them. common/grain_atoms (a bead is no grain) and create_grains
   (grains keep off the segments) read the links through this interface, found with
   atom_style_part.h, not through the style's class. */

#ifndef WIREGRAIN_BEAD_CHAIN_LINKS_H
#define WIREGRAIN_BEAD_CHAIN_LINKS_H

namespace wiregrain_lmp {

class BeadChainLinks {
 public:
  virtual ~BeadChainLinks() = default;
  virtual int previous_bead_tag(int i) const = 0;
  virtual int next_bead_tag(int i) const = 0;
};

}  // namespace wiregrain_lmp

#endif
