// The axes left to a pair's rolling couples (rolling_axes.h).
#include "core/nscd/rolling_axes.h"

#include <algorithm>

namespace wiregrain {

RollingAxes rolling_axes(const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& normal, double arm) {
  RollingAxes axes;
  if (positions.size() < 2) return axes;
  const Eigen::Matrix3d frame = contact_frame(normal);
  const Eigen::Matrix<double, 3, 2> tangents = frame.rightCols<2>();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : positions) centroid += p;
  centroid /= static_cast<double>(positions.size());
  std::vector<Eigen::Vector2d> spread;  // in the tangent plane (t1, t2)
  Eigen::Matrix2d second_moment = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector3d& p : positions) {
    spread.push_back(tangents.transpose() * (p - centroid));
    second_moment += spread.back() * spread.back().transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(second_moment);
  const Eigen::Vector2d along = principal.eigenvectors().col(1);  // the larger spread
  const Eigen::Vector2d across = principal.eigenvectors().col(0);
  // half the points' extent along `direction`
  const auto half_width = [&](const Eigen::Vector2d& direction) {
    double low = 0.0, high = 0.0;
    for (const Eigen::Vector2d& d : spread) {
      low = std::min(low, d.dot(direction));
      high = std::max(high, d.dot(direction));
    }
    return 0.5 * (high - low);
  };
  // rolling about `along` is resisted by the spread across it, and conversely
  const bool free_along = half_width(across) <= arm, free_across = half_width(along) <= arm;
  axes.count = int(free_along) + int(free_across);
  if (axes.count == 1) axes.axis = tangents * (free_along ? along : across);
  return axes;
}

}  // namespace wiregrain
