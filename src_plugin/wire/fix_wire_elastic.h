/* fix wire/elastic: stretching and bending forces of wires made of linked beads
   (atom_style wire), docs/design.md, "The wire: bead chain with soft contacts", and the
   paper's section 2.2.

   fix ID group wire/elastic [E 100] [m_elo 1] [m_rot 0.1]

   E: the keyword, else fix property/global youngsModulus of each bead's atom type, else
   Table 1 (common/plugin_material.h).
   Segment i–j of rest length l0 (per bead, from create_wire or the data file) is an
   axial spring k_s = m_elo E A / l0; inner node j a rotational spring κ = m_rot E I / l
   on the angle θ between consecutive segments (l the mean of its two rest lengths);
   A = π r², I = π r⁴/4 with r the bead radius (core::WireMaterial's axial_stiffness and
   bending_stiffness). With m_elo = m_rot = 1 the chain is an
   Euler–Bernoulli beam (axial stiffness EA, bending stiffness EI) in the continuum limit.

   Outputs: scalar = elastic energy (added to thermo pe with fix_modify energy yes);
   vector = [stretching energy, bending energy, elastic energy, wire length, U_s/L];
   per-atom array = [stretching energy, bending energy, length of the segment to the
   next bead] of each bead (a segment's energy is shared half-half by its two beads), for
   outputs also through the WireEnergySource interface (bead_energy). */

#ifdef FIX_CLASS

FixStyle(wire/elastic,FixWireElastic)

#else

#ifndef LMP_FIX_WIRE_ELASTIC_H
#define LMP_FIX_WIRE_ELASTIC_H

#include <vector>

#include "fix.h"
#include "common/plugin_material.h"
#include "common/wire_energy_source.h"

namespace LAMMPS_NS {

class FixWireElastic : public Fix, public wiregrain_lmp::WireEnergySource {
 public:
  FixWireElastic(class LAMMPS *, int, char **);
  ~FixWireElastic();
  int setmask();
  void init();
  void setup(int);
  void min_setup(int);
  void post_force(int);
  void min_post_force(int);
  double compute_scalar();
  double compute_vector(int);
  void grow_arrays(int);
  void copy_arrays(int, int, int);
  double memory_usage();

  // dt_crit = 2/ω_max of the elastic chain (Verlet's limit), from the stiffest segment
  // and the lightest bead of the group; all ranks return the same value.
  double critical_time_step();
  // step of the last force evaluation, when the per-atom energies are current
  bigint forces_step() const { return forces_step_; }
  // WireEnergySource: the per-bead energies of that step
  long long energies_step() const { return forces_step_; }
  wiregrain::BeadElasticEnergy bead_energy(int i) const;

 private:
  wiregrain_lmp::MaterialKeywords material_keywords_;  // E when given
  std::vector<double> youngs_modulus_of_type_;          // E_w per atom type, from init()
  double m_elo_, m_rot_;
  class AtomVecWire *wire_;
  static constexpr int kBeadColumns = 4;
  double **bead_energy_;        // per bead: stretching, bending energy, length and tension of the segment to the next bead
  double local_sums_[3];        // stretching, bending energy, wire length of owned beads
  double global_sums_[3];
  bigint sums_step_;            // step of global_sums_, -1 if none
  bigint forces_step_;
  bool reported_time_step_;

  int bead_index(int tag, int from_tag);
  void reduce_sums();
};

}  // namespace LAMMPS_NS

#endif
#endif
