/* LIGGGHTS' per-atom double[3] rows (x, v, f, omega, torque) as Eigen vectors, for the
   adapters that hand them to the core. */

#ifndef WIREGRAIN_PLUGIN_VECTOR_H
#define WIREGRAIN_PLUGIN_VECTOR_H

#include <Eigen/Core>

namespace wiregrain_lmp {

inline Eigen::Vector3d vec3(const double *p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

}  // namespace wiregrain_lmp

#endif
