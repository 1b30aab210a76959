/* create_grains: insert spheropolyhedral grains (atom_style polyhedron), docs/design.md,
   "Grains: rigid spheropolyhedra, NSCD" and "The column procedure".

   create_grains type N layer region-ID z0 keyword value ...   the paper's particle layer
   create_grains type N random region-ID keyword value ...     random non-overlapping insertion
   seed S is required. Every keyword, its values and its default:
   docs/commands/create_grains.md.

   layer: two staggered square lattices of spacing s (keyword spacing, default 2 a_max; the
   second s/2 across and 2 a_max higher) in the region's bounding box, sites inside the
   region filled in order; a grain that would overlap is given a new random orientation, up
   to `attempts` times. random: uniform positions in the region, `attempts`
   position+orientation draws per grain. The region bounds the centres of mass (a grain's
   position); grains never overlap each other, the existing grains, other atoms (spheres) or
   wire segments (exact core distance ≤ r_A + r_B is an overlap). Every rank generates every
   grain from the seed (shapes, orientations, positions, the overlap checks against all
   existing atoms, gathered), so the library and the grains are the same on any number of
   ranks; each rank then creates the grains in its subdomain. New grains get the next free
   atom IDs in order of generation. */

#ifdef COMMAND_CLASS

CommandStyle(create_grains,CreateGrains)

#else

#ifndef LMP_CREATE_GRAINS_H
#define LMP_CREATE_GRAINS_H

#include "pointers.h"

namespace LAMMPS_NS {

class CreateGrains : protected Pointers {
 public:
  CreateGrains(class LAMMPS *);
  void command(int, char **);
};

}  // namespace LAMMPS_NS

#endif
#endif
