// One Moreau–Jean contact solve (nscd_step.h): the law's ranges, the solve on the body
// operator, the contact frames and Jacobians.
#include "core/nscd/nscd_step.h"

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/nscd/body_operator.h"

namespace wiregrain {

void MoreauJeanLaw::validate() const {
  if (!(theta >= 0.5 && theta <= 1.0)) {
    throw InvalidArgument("theta", "theta must be in [0.5, 1], got " + format_number(theta));
  }
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    throw InvalidArgument("restitution", "restitution must be in [0, 1], got " +
                                             format_number(restitution));
  }
  if (!(overlap_speed >= 0.0)) {
    throw InvalidArgument("overlap_speed", "overlap_speed must be >= 0, got " + format_number(overlap_speed));
  }
  if (!(overlap_recovery >= 0.0 && overlap_recovery <= 1.0)) {
    throw InvalidArgument("overlap_recovery", "overlap_recovery must be in [0, 1], got " +
                                                  format_number(overlap_recovery));
  }
}

std::unique_ptr<ContactOperator> body_contact_operator(const NscdStep& step) {
  return std::make_unique<BodyContactOperator>(step);
}

NscdStepResult solve_nscd_step(const NscdStep& step, const SolverSettings& settings,
                               const std::vector<Eigen::Vector3d>& warm_start,
                               StickSolveBackoff* backoff,
                               const std::vector<Eigen::Vector2d>& couple_warm_start,
                               WorkerExchange* exchange) {
  settings.validate();
  BodyContactOperator op(step);
  if (exchange != nullptr && !op.distributed())
    throw InvalidArgument("exchange", "a distributed solve needs a distributed step (NscdStep::distributed)");
  NscdStepResult result;
  result.contacts = solve_frictional_contact(op, settings, warm_start, backoff, couple_warm_start, exchange);
  const int body_count = static_cast<int>(step.bodies.size());
  result.velocities.resize(body_count);
  result.angular_velocities.resize(body_count);
  for (int b = 0; b < body_count; ++b) {
    result.velocities[b] = op.body_velocity(b).head<3>();
    result.angular_velocities[b] = op.body_velocity(b).tail<3>();
  }
  const double h = step.time_step, theta = step.law.theta;
  for (int c = 0; c < op.contact_count(); ++c) {
    const double g = step.contacts[c].gap;
    result.max_overlap = std::max(result.max_overlap, -g);
    const double predicted =
        g + h * ((1.0 - theta) * op.start_normal_velocity(c) + theta * op.unshifted_normal_velocity(c, step));
    result.max_predicted_penetration = std::max(result.max_predicted_penetration, -predicted);
  }
  return result;
}

Eigen::Matrix3d contact_frame(const Eigen::Vector3d& normal) {
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InvalidArgument("normal", "contact normal must be finite and non-zero");
  }
  const Eigen::Vector3d n = normal / length;
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::Unit(axis)).normalized();
  const Eigen::Vector3d t2 = n.cross(t1);
  Eigen::Matrix3d frame;
  frame << n, t1, t2;
  return frame;
}

ContactJacobian contact_jacobian(const Eigen::Matrix3d& frame, const Eigen::Vector3d& arm,
                                 double sign) {
  // v + ω × arm = v − [arm]× ω.
  Eigen::Matrix3d arm_cross;
  arm_cross << 0.0, -arm[2], arm[1], arm[2], 0.0, -arm[0], -arm[1], arm[0], 0.0;
  ContactJacobian H;
  H.leftCols<3>() = sign * frame.transpose();
  H.rightCols<3>() = -sign * frame.transpose() * arm_cross;
  return H;
}

}  // namespace wiregrain
