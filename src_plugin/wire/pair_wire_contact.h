/* pair_style wire/contact: soft frictional contact between wire segments (DESIGN.md
   section 4, the paper's section 2.2).

   pair_style wire/contact [E 100] [nu 0] [mu_s 0.5] [mu_d 0.5]
                           [restitution 0.5 | damping_ratio z] [limit_force no|yes]
   pair_coeff I J [same keywords]      (per type pair, overriding pair_style's values)

   Each segment (bead i to its next bead) is a spherocylinder of the bead radius; the
   closest points of two segments (Sunday's algorithm) give the overlap ξ, the normal and
   the weights that share the force among the four beads. Segments sharing a bead do not
   interact. k_n = E_ww l_w π/4, k_t = E_ww r_w with E_ww = E/(2(1−ν²)), l_w and r_w the
   means of the two segments; damping γ = 2ζ√(k m) with m = m_A m_B/(m_A + m_B) and m_A the
   mass of segment A's two beads. The tangential springs live in the fix
   WIRE_CONTACT_HISTORY, so they survive neighbour rebuilds, migration and restarts;
   restart files also keep the pair_style and pair_coeff settings. */

#ifdef PAIR_CLASS

PairStyle(wire/contact,PairWireContact)

#else

#ifndef LMP_PAIR_WIRE_CONTACT_H
#define LMP_PAIR_WIRE_CONTACT_H

#include "pair.h"

namespace LAMMPS_NS {

class PairWireContact : public Pair {
 public:
  PairWireContact(class LAMMPS *);
  ~PairWireContact();
  void compute(int, int);
  void settings(int, char **);
  void coeff(int, char **);
  void init_style();
  double init_one(int, int);
  int pack_reverse_comm(int, int, double *);
  void unpack_reverse_comm(int, int *, double *);
  void write_restart(FILE *);
  void read_restart(FILE *, const int, const int);
  double memory_usage();

  // this step's wire–wire contacts and the largest overlap (all ranks)
  double contact_count();
  double max_overlap();
  // exact segment–segment distance evaluations of this step (pairs past the
  // bounding-sphere test)
  double pair_evaluations();

  struct Coefficients {
    double youngs_modulus, poisson_ratio, static_friction, dynamic_friction, damping_ratio;
    bool limit_force;
  };

 private:
  Coefficients defaults_;
  Coefficients **coefficients_;
  class AtomVecWire *wire_;
  class FixWireContactHistory *history_;
  double reach_;                     // largest segment extent + 2 radii: the pair cutoff
  double local_stats_[3];            // contacts, largest overlap, evaluations on this rank
  double global_stats_[3];
  bigint stats_step_;
  // per bead (owned and ghost), rebuilt every step: index of the next bead (−1: none,
  // −2: not in the ghost shell) and the position of its image nearest to the bead
  int *segment_next_;
  double **segment_end_;
  int segment_capacity_;

  void allocate();
  // reads the keywords from arg[first..narg) into c; `kind` names the command in errors
  void parse(int narg, char **arg, int first, Coefficients &c, const char *kind);
};

}  // namespace LAMMPS_NS

#endif
#endif
