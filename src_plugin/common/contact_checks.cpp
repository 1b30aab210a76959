#include "contact_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "comm.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "lmptype.h"
#include "modify.h"
#include "update.h"

#include "point_mass_integrator.h"

#include "core/contact/contact_laws.h"
#include "core/contact/contact_time_step.h"

namespace wiregrain_lmp {

namespace {
std::string prefix(const std::string &kind, const std::string &style, const std::string &id) {
  return kind + " " + style + " (id " + id + "): ";
}
}  // namespace

bool gear5_integrates(LAMMPS_NS::LAMMPS *lmp) {
  bool gear = false;
  for (int k = 0; k < lmp->modify->nfix; k++)
    if (const PointMassIntegrator *g = dynamic_cast<const PointMassIntegrator *>(lmp->modify->fix[k]))
      gear = gear || g->uses_gear();
  return gear;
}

double ContactTimeStepCheck::check(LAMMPS_NS::LAMMPS *lmp, const std::string &kind, const std::string &style,
                                   const std::string &id, const std::vector<ContactSpring> &springs) {
  const bool gear = gear5_integrates(lmp);
  double limit = INFINITY;
  const ContactSpring *stiffest = nullptr;
  wiregrain::SoftContactLaw law;
  wiregrain::ContactTimeStep steps;
  for (const ContactSpring &s : springs) {
    const wiregrain::SoftContactLaw l =
        wiregrain::segment_contact_law(s.effective_modulus, s.segment_length, s.radius, s.friction);
    const wiregrain::ContactTimeStep t = wiregrain::contact_time_step(l, s.mass);
    if (t.limit(gear) < limit) {
      limit = t.limit(gear);
      stiffest = &s;
      law = l;
      steps = t;
    }
  }
  const double dt = lmp->update->dt;
  if (!stiffest || !(dt > limit)) return limit;
  if (dt == warned_dt_ && limit == warned_limit_) return limit;  // said at an earlier run
  warned_dt_ = dt;
  warned_limit_ = limit;
  if (lmp->comm->me != 0) return limit;
  char line[768];
  snprintf(line, sizeof(line),
           "%stimestep %.6g exceeds the stable limit %.6g of the %s integrator for its contact springs "
           "(k %.6g on mass %.6g, %s, damping ratio %.3g: contact critical time step %.6g); use a smaller timestep",
           prefix(kind, style, id).c_str(), dt, limit, gear ? "gear5" : "verlet",
           std::max(law.normal_stiffness, law.tangential_stiffness), stiffest->mass, stiffest->mass_name.c_str(),
           law.damping_ratio + 0.0, steps.critical);  // + 0: ζ of restitution 1 is −0
  lmp->error->warning(FLERR, line);
  return limit;
}

bool OverlapWarnings::due(double ratio) {
  if (!(ratio > kLargeOverlapFraction) || count_ >= kMaxOverlapWarnings || !(ratio > 2.0 * named_)) return false;
  named_ = ratio;
  return true;
}

void OverlapWarnings::warn(LAMMPS_NS::LAMMPS *lmp, const std::string &kind, const std::string &style,
                           const std::string &id, double overlap, double radius, const std::string &which,
                           const std::string &remedy) {
  count_++;
  // overlap / r_w with 4 digits, more when those would round it down to the threshold
  char ratio[32];
  for (int digits = 4; digits <= 12; digits++) {
    snprintf(ratio, sizeof(ratio), "%.*g", digits, overlap / radius);
    if (std::atof(ratio) > kLargeOverlapFraction) break;
  }
  char line[768];
  snprintf(line, sizeof(line),
           "%sat step " BIGINT_FORMAT " %s overlap by %.3g (%s r_w, beyond %.2g r_w: the soft contact assumes "
           "small overlaps); use a smaller timestep or %s%s",
           prefix(kind, style, id).c_str(), lmp->update->ntimestep, which.c_str(), overlap, ratio,
           kLargeOverlapFraction, remedy.c_str(),
           count_ == kMaxOverlapWarnings ? "; further large overlaps on this rank are not reported" : "");
  lmp->error->warning(FLERR, line);
}

}  // namespace wiregrain_lmp
