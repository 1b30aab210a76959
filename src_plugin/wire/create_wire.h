/* create_wire: lay one wire as a chain of linked beads (atom_style wire).

   create_wire type line x0 y0 z0 x1 y1 z1            [keywords]
   create_wire type loop cx cy z R turns pitch         [keywords]   (helix: an alias)
   create_wire type circle cx cy z R                   [keywords]
   create_wire type spiral cx cy z r0 r1 turns         [keywords]
   create_wire type polyline file                      [keywords]
     keywords: segment l_w (0.2)  radius r_w (0.1)  density rho_w (0.5)
               append ID|last  join straight|helix (straight)  join_max L (10 l_w)
               join_min f (0.5)

   Nodes are resampled so consecutive beads are exactly l_w apart (a partial last
   segment is dropped); each bead has mass rho_w pi r_w^2 l_w, the rest length of each
   segment is l_w, the ends are free. New beads get the next free atom IDs. With append the
   new beads continue the chain whose end bead (no next bead) is ID, or the chain end of
   the largest ID (last): a join of beads at chord l_w leads from it to the layout's first
   node, its last segment's rest length its own length (core/wire/wire_layout.h, wire_join);
   the rank that owns the end bead links it to the first new bead. */

#ifdef COMMAND_CLASS

CommandStyle(create_wire,CreateWire)

#else

#ifndef LMP_CREATE_WIRE_H
#define LMP_CREATE_WIRE_H

#include "pointers.h"

namespace LAMMPS_NS {

class CreateWire : protected Pointers {
 public:
  CreateWire(class LAMMPS *);
  void command(int, char **);
};

}  // namespace LAMMPS_NS

#endif
#endif
