// The features (vertex, edge or face) of a posed core that carry a contact along a
// normal, and the points of a feature the contact queries read: the first step of a
// contact manifold (contact_manifold.h) and of a wire segment's contact interval
// (segment_contact.h). docs/design.md, "Contact geometry".
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "core/geometry/contact_frame.h"
#include "core/geometry/polygon_clipping.h"
#include "core/geometry/posed_shape.h"

namespace wiregrain {

// Clipped polygon vertices closer than this times the size are merged; a vertex this
// close to the line through its neighbours is dropped; clipping treats points this far
// outside a polygon edge as on it; vertices this close to a supporting plane belong to
// the support set.
constexpr double kMergeTolerance = 1e-10;

enum class FeatureKind { vertex, edge, face };

// The feature of a core that carries the contact: index into the shape's vertices(),
// edges() or faces().
struct ContactFeature {
  FeatureKind kind = FeatureKind::vertex;
  int index = -1;
};

// The feature of P that faces direction n (unit). The support set S (vertices within
// `tight` of the supporting plane ⟂ n: one vertex, an edge or a face) contains the
// deepest points; only features containing all of S are candidates, so the feature
// always contains them: a face whose normal is within the angle tolerance of n
// (cos ≥ cos_tol), else an edge perpendicular to n within the tolerance (|sin| ≤ sin_tol
// of its angle with the plane), else the support vertex.
ContactFeature select_feature(const PosedShape& P, const Eigen::Vector3d& n, double cos_tol, double sin_tol,
                              double tight);

// The parameter s ∈ [0, 1] of the point of segment [b0, b1] nearest to the line through x
// with direction n (unit): minimises |P(b(s) − x)|, P the projector ⟂ n.
double segment_param_nearest_line(const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& x,
                                  const Eigen::Vector3d& n);

// The point of a feature of P on (or nearest to) the line through x along n.
Eigen::Vector3d feature_point_on_line(const PosedShape& P, const ContactFeature& f, const Eigen::Vector3d& x,
                                      const Eigen::Vector3d& n);

// 2D polygon of a face, counter-clockwise about n (the face's loop is counter-clockwise
// about its outward normal; reversed when that points against n).
PlanePolygon face_polygon(const PosedShape& P, int face, const ContactFrame& frame);

}  // namespace wiregrain
