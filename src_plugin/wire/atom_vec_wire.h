/* atom_style wire: beads of an elastic wire (docs/design.md, "The wire: bead chain with
   soft contacts").

   Per bead: position, velocity, force, radius (the wire radius r_w), mass, and the chain
   links: the tags of the previous and next bead of the same wire (0 at a free end) and
   the rest length of the segment to the next bead. Links travel with the bead between
   MPI ranks, to ghosts, to restart files and to data files, so any number of wires can
   coexist and be cut or joined by editing a data file.

   Data file Atoms line:  atom-ID atom-type wire-prev wire-next rest-length radius mass x y z
   Velocities line:       atom-ID vx vy vz

   Other styles reach the link arrays through AtomVecWire::of(atom), which also finds the
   wire sub-style of atom_style hybrid. */

#ifdef ATOM_CLASS

AtomStyle(wire,AtomVecWire)

#else

#ifndef LMP_ATOM_VEC_WIRE_H
#define LMP_ATOM_VEC_WIRE_H

#include "common/bead_chain_links.h"
#include "common/plugin_atom_vec.h"

namespace LAMMPS_NS {

class AtomVecWire : public PluginAtomVec, public wiregrain_lmp::BeadChainLinks {
 public:
  AtomVecWire(class LAMMPS *);
  ~AtomVecWire();
  void settings(int, char **);
  void init();
  int data_atom_hybrid(int, char **);

  // chain links, indexed like atom->x (owned and ghost beads)
  int *wire_prev;       // tag of the previous bead, 0 at a free end
  int *wire_next;       // tag of the next bead, 0 at a free end
  double *wire_rest;    // rest length of the segment to the next bead
  // BeadChainLinks: the links above
  int previous_bead_tag(int i) const { return wire_prev[i]; }
  int next_bead_tag(int i) const { return wire_next[i]; }

  // The springs and dashpots the contacts of this step put on each bead, owned and ghost
  // (common/bead_contact_load.h: kBeadContactLoadSize doubles per bead); not migrated, not in
  // restarts: fix nve/gear clears them before the forces, sums the ghosts' to their owners
  // after them and checks each bead's time step. The contact styles add to them where
  // they add their forces, in the steps where contact_load_wanted is set (a fix nve/gear
  // sets it in pre_force of a step it checks, and clears it after the check).
  double **contact_load;
  bool contact_load_wanted;

  // The wire style of this system (plain or inside atom_style hybrid), or NULL.
  static AtomVecWire *of(class Atom *);

  // Local index (owned or ghost) of the bead a link names, -1 when this rank has no atom
  // with that tag: every style follows links through here, since LIGGGHTS' array map is
  // not bounds-checked (a link beyond the largest atom ID would read past its end).
  int linked_bead(int link_tag) const;

 private:
  double *radius, *rmass;

  void create_atom_defaults(int i);
  int data_link(const char *word, const char *name) const;
  double data_value(const char *word, const char *name, bool positive) const;
};

}  // namespace LAMMPS_NS

#endif
#endif
