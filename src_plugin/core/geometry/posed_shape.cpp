// A ConvexShape placed in the world. See posed_shape.h.
#include "core/geometry/posed_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/errors.h"

namespace wiregrain {

using Eigen::Vector3d;

PosedShape::PosedShape(const ConvexShape& shape, const Vector3d& position,
                       const Eigen::Quaterniond& orientation)
    : shape_(&shape), position_(position) {
  if (!position.allFinite()) throw InvalidArgument("position", "position must have finite coordinates");
  const double norm = orientation.norm();
  if (!std::isfinite(norm) || !(norm > 0.0))
    throw InvalidArgument("orientation", "orientation must be a finite non-zero quaternion");
  orientation_ = orientation.normalized();
  rotation_ = orientation_.toRotationMatrix();
  vertices_.reserve(shape.vertices().size());
  for (const auto& v : shape.vertices()) {
    core_radius_ = std::max(core_radius_, v.norm());
    vertices_.push_back(rotation_ * v + position_);
  }
}

int PosedShape::support_vertex(const Vector3d& direction) const {
  int best = 0;
  double h = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(vertices_.size()); ++i) {
    const double x = direction.dot(vertices_[i]);
    if (x > h) {
      h = x;
      best = i;
    }
  }
  return best;
}

double support_value(const PosedShape& p, const Vector3d& n) {
  double h = -std::numeric_limits<double>::infinity();
  for (const auto& v : p.vertices()) h = std::max(h, n.dot(v));
  return h;
}

double configuration_size(const PosedShape& a, const Vector3d& other_center, double other_radius) {
  return std::max({a.core_radius(), other_radius, (a.position() - other_center).norm(),
                   std::numeric_limits<double>::min()});
}

}  // namespace wiregrain
