/* A fix that integrates point masses (the wire beads: fix nve/gear) says which scheme it
   uses: the stability limit of a contact spring depends on it (common/contact_checks.h,
   core/contact/contact_time_step.h). common/contact_checks finds such fixes through this
   interface, not through their classes. */

#ifndef WIREGRAIN_POINT_MASS_INTEGRATOR_H
#define WIREGRAIN_POINT_MASS_INTEGRATOR_H

namespace wiregrain_lmp {

class PointMassIntegrator {
 public:
  virtual ~PointMassIntegrator() = default;
  // true for the 6-value fifth-order Gear predictor–corrector (gear5), false for velocity Verlet
  virtual bool uses_gear() const = 0;
};

}  // namespace wiregrain_lmp

#endif
