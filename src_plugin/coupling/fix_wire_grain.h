/* fix wire/grain: soft frictional contact between the wire and the grains, with the
   grains held during the wire's sub-steps (paper Sec. 2.3–2.4, Fig. 5; docs/design.md,
   "Wire–grain contacts").

   fix ID wire-group wire/grain grain-group keyword value ...
   Every keyword, its values and its default: docs/commands/fix_wire_grain.md.

   Every LIGGGHTS step (the wire sub-step dt), each segment of the wire group (a bead and
   its next bead, a spherocylinder of the bead's radius r_w) is tested against the grains
   of grain-group (atom_style polyhedron, integrated by fix nscd/polyhedra): exact
   segment–core distance, overlap ξ = r_w + r_p − d, linear spring–dashpot
   k_n = E_wp l_w π/4, tangential spring k_t = E_wp r_w with static/dynamic Coulomb
   friction, 1/E_wp = (1−ν_w²)/E_w + (1−ν_p²)/E_p, l_w the segment's rest length
   (core/contact/wire_grain_contact.h). The force goes to the two beads with the
   closest-point weights, its opposite and torque to the grain.
   E and ν: the keywords, else fix property/global youngsModulus / poissonsRatio of the
   bead's / grain's atom type, else Table 1 (common/plugin_material.h).
   max_stretch s: the contact search finds every grain near segments stretched up to
   (1 + s) times their rest length; a longer segment stops the run (default 0.5: under
   Table 1's soft wire, E_w = 100, a grain landing on a loop can stretch a segment by 25 %).

   Sub-cycling: the grains are seen where fix nscd/polyhedra last put them, with its last
   velocities, for the N steps of one NSCD step (its `every N` / `timestep h`). Each rank
   sums the forces and torques on each grain over these steps; at the last one the sums
   are combined over the ranks and added to the grains' force and torque, so the NSCD
   step, which averages over its N steps, applies (Σ F)/N over h = N dt: the grain gets
   exactly the impulse dt·ΣF the wire received.

   Ranks: each rank tests its own segments against its own and its ghost grains (the fix
   asks LIGGGHTS for the grains whose surface is within (1 + max_stretch) ℓ + 2 r_w + the
   skins of the subdomain); no grain record leaves its rank. The loads on the
   grains its segments touch go to the grains' owners at the NSCD step's last sub-step:
   with the grains distributed (stock grains, or fix nscd/polyhedra's `solve
   distributed`) by LIGGGHTS' reverse communication from the ghost copies (a load on a
   grain that is no longer a ghost of the rank by then, after a reneighbouring within the
   NSCD step, goes by an all-gather of those loads alone); with `solve replicated` every
   rank takes all ranks' loads (an all-gather), so the sums are added in rank order.

   Stock LIGGGHTS spheres: a grain group without polyhedra is taken as granular spheres
   (atom_style sphere/granular in the hybrid, integrated by fix nve/sphere every step):
   the same law, the geometry in closed form (wire_sphere_contact), the spheres held and
   their forces and torques applied every step (no sub-cycling).

   Tangential springs per (segment, grain), kept by the segment's first bead in fix
   WIRE_GRAIN_HISTORY_<ID> (migrate, restart; dropped when the pair separates).

   Checks (common/contact_checks.h): at each run start the timestep against the stability
   limit of the stiffest contact spring (longest segment, thickest bead, stiffest pair of
   materials present) on the lightest bead alone: the grain is held during the wire's
   sub-steps (fix nscd/polyhedra moves it, implicitly, once per NSCD step) and is much
   heavier (Table 1: ~150 beads); every step, an overlap beyond 0.5 r_w is named in a
   warning, the first 10 times per rank.

   Outputs: vector [contacts, largest overlap, largest overlap / r_w, force of the wire on
   the grains averaged over the last NSCD step (x, y, z), exact segment–grain evaluations
   of the step, contacts sliding (on the Coulomb limit)]; per-atom array (6): beads: force
   from the grains this step (3), the grains touching the bead's segment (its sum over the
   beads over the segments is z_wpc), 0, 0;
   grains: force and torque from the wire averaged over the last NSCD step. Publishes its
   contacts (kind wire_grain, a = the segment's first bead, b = the grain). */

#ifdef FIX_CLASS

FixStyle(wire/grain,FixWireGrain)

#else

#ifndef LMP_FIX_WIRE_GRAIN_H
#define LMP_FIX_WIRE_GRAIN_H

#include <memory>
#include <string>
#include <vector>

#include "common/contact_checks.h"
#include "common/grain_atoms.h"
#include "common/contact_publisher.h"
#include "common/plugin_material.h"
#include "core/contact/contact_materials.h"
#include "fix.h"

namespace wiregrain {
class GrainLoadSums;
struct WireGrainContact;
struct WireSegmentState;
}

namespace LAMMPS_NS {

class FixWireGrain : public Fix, public wiregrain_lmp::ContactPublisher {
 public:
  FixWireGrain(class LAMMPS *, int, char **);
  ~FixWireGrain();
  int setmask();
  void post_create();
  void init();
  void setup_pre_force(int);
  void pre_force(int) {}
  void post_force(int);
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);
  int pack_reverse_comm(int, int, double *);
  void unpack_reverse_comm(int, int *, double *);
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  double memory_usage();
  // this rank's wire–grain contacts of the last force call
  const wiregrain::ContactList &published_contacts() const;

 private:
  // held grains, load sums and contacts (Eigen types, defined in the .cpp)
  struct CoreState;
  std::unique_ptr<CoreState> core_;
  std::string grain_group_;
  int grain_groupbit_;
  wiregrain_lmp::MaterialKeywords wire_given_, grain_given_;  // E_w, nu_w, E_p, nu_p when given
  wiregrain::ContactFriction friction_;
  std::vector<double> modulus_;  // E_wp per (bead type, grain type), (ntypes+1)² from init()
  class AtomVecWire *wire_;
  class AtomVecPolyhedron *grains_;
  class FixNSCDPolyhedra *nscd_;
  class FixWireContactHistory *history_;
  wiregrain_lmp::GrainAtoms grain_atoms_;  // which atoms are polyhedra
  bool stock_grains_;            // the grains are stock spheres or superquadrics, integrated by LIGGGHTS
                                 // every step (no fix nscd/polyhedra, no sub-cycling)
  std::string history_id_;
  long held_version_;            // the NSCD fix's pose_version() of the held grains
  double segment_reach_;         // largest half segment stretched by max_stretch_ + r_w
  double max_stretch_;           // keyword max_stretch: the strain the contact search allows
  double skin_;                  // keyword skin: pairs kept while nothing moved more (0: search every step)
  bool warm_geometry_ = false;   // keyword warm_geometry: GJK from each kept pair's last simplex
  bool stretch_warned_;          // the warning of a segment beyond max_stretch was given
  int summed_steps_;             // sub-steps in the load sums
  double **bead_force_;          // per atom (owned and ghost): this step's force from the grains
  double **grain_load_;          // per atom (owned and ghost): the NSCD step's load summed on a grain, force and torque
  int reverse_width_;            // values per atom of the reverse communication: 3 bead forces, 6 grain loads
  bool loads_by_owner_;          // grains distributed: loads reach the owners by reverse communication
  double **output_;              // per-atom array (see above)
  std::vector<int> segment_contacts_;  // this step, per owned bead: grains touching its segment
  std::vector<int> held_copies_;       // hold_grains' scratch: the local index of each held grain's copy
  int nmax_ghost_;
  double local_stats_[5];        // contacts, overlap, overlap / r_w, evaluations, sliding contacts
  double global_stats_[8];
  double average_force_[3];      // on all grains, last NSCD step
  bigint stats_step_;
  wiregrain_lmp::ContactTimeStepCheck time_step_check_;
  wiregrain_lmp::OverlapWarnings overlap_warnings_;
  int deepest_bead_;             // this step: the bead and grain of the largest overlap / r_w
  long deepest_grain_;
  double deepest_overlap_, deepest_radius_;

  bool is_grain(int i) const;  // atom i is one of the grains the wire touches
  void hold_grains();
  void check_time_step();
  double held_reach();
  bool segments_within_reach();
  void evaluate(bool setup);
  wiregrain::WireSegmentState segment_of(int i, int j) const;
  void record_contact(const wiregrain::WireGrainContact &c, int i, long grain_tag);
  void apply_bead_forces();
  void apply_grain_loads(const wiregrain::GrainLoadSums &loads, int steps);
  [[noreturn]] void fail(const std::string &what);
  [[noreturn]] void fail_one(const std::string &what);
};

}  // namespace LAMMPS_NS

#endif
#endif
