/* The checks the soft contact styles of the wire (pair wire/contact, fix wire/wall,
   fix wire/grain) share: a run either stays within the contact model or says so.

   Time step. At each run start a style names the contact laws it can meet (its stiffest
   per material pairing, on the lightest mass it can act on) and ContactTimeStepCheck
   compares the timestep with their stability limit (core/contact/contact_time_step.h:
   velocity Verlet dt_crit = (2/ω)(√(1+ζ²) − ζ); gear5 0.313/2 of it and ζ ω dt < 0.075, the
   fractions fix wire/elastic uses for its springs). Beyond it, rank 0 warns
     "<kind> <style> (id <ID>): timestep T exceeds the stable limit L of the gear5 integrator
      for its contact springs (k K on mass M, <which>, damping ratio Z: critical time step C);
      use a smaller timestep"
   once per (timestep, limit): a later run warns again only when either changed.

   Overlap. The soft contact is a linear spring on the overlap ξ of two spherocylinders
   (k_n = E* l π/4, the stiffness of a shallow line contact): it assumes ξ small against the
   wire radius r_w. At ξ = r_w a bead's axis reaches the partner's surface, and in a
   wire–wire contact the two axes cross at ξ = 2 r_w, where the normal is undefined. An
   overlap beyond kLargeOverlapFraction = 0.5 r_w (Table 1 runs of a few loops stay at
   0.2–0.25 r_w; the bottom beads of a 2000-segment pile sink 0.56 r_w into the floor) is
   named in a warning on the rank that computed it (these styles reduce nothing per step):
     "<kind> <style> (id <ID>): at step S <which> overlap by X (Y r_w, beyond 0.5 r_w: the
      soft contact assumes small overlaps); use a smaller timestep or <remedy>"
   the first time, and again only when an overlap doubles the largest one named (about
   0.5, 1, 2, 4 r_w ...), so that its size shows without repeating a run that stays near
   the threshold (the reduced column presses beads 0.5 r_w into the floor and grains
   again and again); kMaxOverlapWarnings per style and rank in all.

   Per bead, per step: common/bead_contact_load.h. */

#ifndef WIREGRAIN_CONTACT_CHECKS_H
#define WIREGRAIN_CONTACT_CHECKS_H

#include <string>
#include <vector>

#include "core/contact/contact_materials.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wiregrain_lmp {

constexpr double kLargeOverlapFraction = 0.5;  // of r_w
constexpr int kMaxOverlapWarnings = 10;

// true when a fix that integrates point masses with the gear5 scheme is defined (fix
// nve/gear, common/point_mass_integrator.h: the wire is then integrated by it, its limits
// are gear5's)
bool gear5_integrates(LAMMPS_NS::LAMMPS *lmp);

// One contact a style can meet: the segment law's inputs (k_n = E* l π/4, k_t = E* r,
// core/contact/contact_laws.h) and the mass its spring acts on. Plain data: LIGGGHTS'
// own sources include the style headers, without Eigen.
struct ContactSpring {
  double effective_modulus = 0.0;  // E*
  double segment_length = 0.0;     // l
  double radius = 0.0;             // r
  wiregrain::ContactFriction friction;
  double mass = 0.0;
  std::string mass_name;  // e.g. "the lightest bead"
};

class ContactTimeStepCheck {
 public:
  // kind/style/id as in the style's messages ("pair", "wire/contact", "-"). Call on every
  // rank with the same springs (from reduced extremes); rank 0 warns for the spring with
  // the smallest limit when update->dt exceeds it. Returns that limit (∞ without springs).
  double check(LAMMPS_NS::LAMMPS *lmp, const std::string &kind, const std::string &style, const std::string &id,
               const std::vector<ContactSpring> &springs);

 private:
  double warned_dt_ = 0.0, warned_limit_ = 0.0;
};

class OverlapWarnings {
 public:
  // Call every step with this rank's largest overlap / r_w of the step (0 without
  // contacts): true when this step is to be named (then call warn()).
  bool due(double ratio);
  void warn(LAMMPS_NS::LAMMPS *lmp, const std::string &kind, const std::string &style, const std::string &id,
            double overlap, double radius, const std::string &which, const std::string &remedy);

 private:
  int count_ = 0;
  double named_ = 0.0;  // the largest ratio named so far (0: none)
};

}  // namespace wiregrain_lmp

#endif
