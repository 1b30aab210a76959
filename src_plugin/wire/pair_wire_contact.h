/* pair_style wire/contact: soft frictional contact between wire segments (docs/design.md,
   "The wire: bead chain with soft contacts"; the paper's section 2.2).

   pair_style wire/contact [E 100] [nu 0] [mu_s 0.5] [mu_d 0.5]
                           [restitution 0.5 | damping_ratio z] [limit_force no|yes] [cache yes|no]
   pair_coeff I J [same keywords but cache]  (per type pair, overriding pair_style's values)

   Each segment (bead i to its next bead) is a spherocylinder of the bead radius; the
   closest points of two segments (Sunday's algorithm) give the overlap ξ, the normal and
   the weights that share the force among the four beads (the contact's kinematics and
   force: core/contact/wire_wire_contact.h). Segments sharing a bead do not interact.
   k_n = E_ww l_w π/4, k_t = E_ww r_w with E_ww = E/(2(1−ν²)) (the mixing rule
   1/E* = (1−ν_a²)/E_a + (1−ν_b²)/E_b for two atom types of different materials), l_w and
   r_w the means of the two segments (core/contact/contact_laws.h); E and ν: the keywords,
   else fix property/global youngsModulus / poissonsRatio per atom type, else Table 1
   (common/plugin_material.h); damping γ = 2ζ√(k m) with m = m_A m_B/(m_A + m_B) and m_A the
   mass of segment A's two beads. The tangential springs live in the fix
   WIRE_CONTACT_HISTORY, so they survive neighbour rebuilds, migration and restarts;
   restart files also keep the pair_style and pair_coeff settings. cache yes (the
   default): when the neighbour list is built, only its segment pairs that can touch before
   the next build (core/geometry/segment_distance.h, segments_may_touch with the neighbour
   skin) are kept and looked at each step; no: every pair of the list each step. Publishes its contacts
   (kind wire_wire, a and b the tags of the segments' first beads) as a ContactPublisher.

   Checks (common/contact_checks.h): at each run start the timestep against the stability
   limit of the stiffest contact spring of the wire types present (the longest segment,
   the thickest bead) on the reduced mass of two of the lightest beads (a contact point at
   a segment end moves with one bead); every step, an overlap beyond 0.5 r_w (r_w the mean
   radius of the two segments) is named in a warning, the first 10 times per rank. */

#ifdef PAIR_CLASS

PairStyle(wire/contact,PairWireContact)

#else

#ifndef LMP_PAIR_WIRE_CONTACT_H
#define LMP_PAIR_WIRE_CONTACT_H

#include "pair.h"

#include <utility>
#include <vector>

#include "common/contact_checks.h"
#include "common/contact_publisher.h"
#include "common/plugin_material.h"
#include "core/contact/contact_materials.h"

namespace wiregrain {
struct WireSegmentState;
struct WireWireContact;
struct SoftContactLaw;
}  // namespace wiregrain

namespace LAMMPS_NS {

class PairWireContact : public Pair, public wiregrain_lmp::ContactPublisher {
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

  // this rank's wire–wire contacts of the last force call; its evaluations are the exact
  // segment–segment distances computed (pairs past the bounding-sphere test)
  const wiregrain::ContactList &published_contacts() const;

  // the settings of pair_style / pair_coeff; E and ν only where given (has_*)
  // one pair_style / pair_coeff setting (written as is to restart files)
  struct Coefficients {
    wiregrain_lmp::MaterialKeywords material;
    wiregrain::ContactFriction friction;
  };

 private:
  Coefficients defaults_;
  Coefficients **coefficients_;
  // per type pair, from init_one: the effective modulus E* and the friction settings
  double **effective_modulus_;
  wiregrain::ContactFriction **friction_;
  wiregrain::ContactList *contacts_;
  class AtomVecWire *wire_;
  class FixWireContactHistory *history_;
  // The beads of segments (a lone bead is none), from init_style: per atom type the
  // thickest one's radius (0: the type has none), the longest rest length and the
  // lightest mass of all. A type pair's cutoff (init_one) reaches the far ends of two of
  // its segments, 0 for a type without beads (the grains of a hybrid: their pairs are not
  // listed); reach_ is the largest.
  struct WireExtent {
    std::vector<double> radius;  // index 1..ntypes
    double rest = 0.0, lightest_mass = 0.0;
  };
  WireExtent extent_;
  double reach_;
  WireExtent gather_wire_extent() const;
  // per bead (owned and ghost), rebuilt every step: index of the next bead (−1: none,
  // −2: not in the ghost shell) and the position of its image nearest to the bead
  int *segment_next_;
  double **segment_end_;
  int segment_capacity_;
  // keyword cache (pair_style): the segment pairs to look at until the neighbour list is
  // built again (compute()), and the neighbour build they were chosen at
  bool cache_ = true;
  std::vector<std::pair<int, int>> candidates_;
  bigint candidates_built_at_ = -1;

  wiregrain_lmp::ContactTimeStepCheck time_step_check_;
  wiregrain_lmp::OverlapWarnings overlap_warnings_;

  void allocate();
  void check_time_step();
  void check_rest_geometry();
  // the steps of compute()
  void find_segments();
  void select_candidates();
  wiregrain::WireSegmentState segment_state(int i) const;
  void add_motion(int i, wiregrain::WireSegmentState &s) const;
  void scatter(int a, int b, const wiregrain::SoftContactLaw &law, const wiregrain::WireWireContact &c);
  // reads the keywords from arg[first..narg) into c; `kind` names the command in errors
  void parse(int narg, char **arg, int first, Coefficients &c, const char *kind);
};

}  // namespace LAMMPS_NS

#endif
#endif
