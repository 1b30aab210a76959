// Convex shapes: the adjacency the contact queries read, the regular and random solids,
// shapes from vertex files, rigid motions and drawing polygons. The hull construction is
// in convex_hull.cpp, the mass properties in mass_properties.cpp. See convex_shape.h for
// the conventions.
#include "core/geometry/convex_shape.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <utility>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/random_stream.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

}  // namespace

void ConvexShape::index_adjacency() {
  faces_at_vertex_.assign(vertices_.size(), {});
  edges_at_vertex_.assign(vertices_.size(), {});
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
    for (int v : faces_[f].vertices) faces_at_vertex_[v].push_back(f);
  for (int e = 0; e < static_cast<int>(edges_.size()); ++e)
    for (int v : edges_[e]) edges_at_vertex_[v].push_back(e);
  face_vertex_masks_.clear();
  if (vertices_.size() <= 64)
    for (const Face& f : faces_) {
      std::uint64_t mask = 0;
      for (int v : f.vertices) mask |= std::uint64_t(1) << v;
      face_vertex_masks_.push_back(mask);
    }
  index_incident_faces();
}

void ConvexShape::index_incident_faces() {
  incident_faces_.clear();
  incident_offsets_.assign(1, 0);
  for (const std::vector<int>& at : faces_at_vertex_) {
    for (int f : at) {
      IncidentFace i;
      i.normal = faces_[f].normal;
      i.mask = face_vertex_masks_.empty() ? 0 : face_vertex_masks_[f];
      i.face = f;
      incident_faces_.push_back(i);
    }
    incident_offsets_.push_back(static_cast<int>(incident_faces_.size()));
  }
}

ConvexShape ConvexShape::random_ellipsoid(std::mt19937_64& rng, int n_vertices, double a,
                                          double b_over_a, double c_over_a,
                                          double sweep_radius) {
  if (n_vertices < 4)
    throw InvalidArgument("n_vertices", "n_vertices (N_v) must be >= 4, got " +
                                            std::to_string(n_vertices));
  if (!(a > 0.0) || !std::isfinite(a))
    throw InvalidArgument("a", "a (the longest semi-axis) must be > 0 and finite, got " +
                                   format_number(a));
  if (!(b_over_a > 0.0 && b_over_a <= 1.0))
    throw InvalidArgument("b_over_a", "b_over_a (b/a) must be in (0, 1], got " + format_number(b_over_a));
  if (!(c_over_a > 0.0 && c_over_a <= b_over_a))
    throw InvalidArgument("c_over_a", "c_over_a (c/a) must be in (0, b/a] = (0, " +
                                          format_number(b_over_a) + "], got " + format_number(c_over_a));
  require_nonnegative("sweep_radius", sweep_radius);

  const Vector3d semi_axes(a, a * b_over_a, a * c_over_a);
  std::vector<Vector3d> points;
  points.reserve(n_vertices);
  for (int i = 0; i < n_vertices; ++i) {
    // Archimedes: z uniform in [-1, 1] and azimuth uniform give a uniform direction
    const double z = 2.0 * uniform01(rng) - 1.0;
    const double phi = 2.0 * kPi * uniform01(rng);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    points.push_back(semi_axes.cwiseProduct(Vector3d(s * std::cos(phi), s * std::sin(phi), z)));
  }
  return from_points(points, sweep_radius);
}

ConvexShape ConvexShape::random_ellipsoid(std::uint64_t seed, int n_vertices, double a,
                                          double b_over_a, double c_over_a,
                                          double sweep_radius) {
  std::mt19937_64 rng(seed);
  return random_ellipsoid(rng, n_vertices, a, b_over_a, c_over_a, sweep_radius);
}

ConvexShape ConvexShape::sphere(double radius) {
  require_positive("radius", radius);
  return from_points({Vector3d::Zero()}, radius);
}

ConvexShape ConvexShape::box(double lx, double ly, double lz, double sweep_radius) {
  require_positive("lx", lx);
  require_positive("ly", ly);
  require_positive("lz", lz);
  std::vector<Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back((i & 1 ? 0.5 : -0.5) * lx, (i & 2 ? 0.5 : -0.5) * ly,
                         (i & 4 ? 0.5 : -0.5) * lz);
  return from_points(corners, sweep_radius);
}

ConvexShape ConvexShape::cube(double edge, double sweep_radius) {
  require_positive("edge", edge);
  return box(edge, edge, edge, sweep_radius);
}

ConvexShape ConvexShape::regular_tetrahedron(double edge, double sweep_radius) {
  require_positive("edge", edge);
  // alternate corners of a cube of side edge/√2 (their distance is 2√2 · h, h = half side)
  const double h = edge / (2.0 * std::sqrt(2.0));
  return from_points({Vector3d(h, h, h), Vector3d(h, -h, -h), Vector3d(-h, h, -h),
                      Vector3d(-h, -h, h)},
                     sweep_radius);
}

ConvexShape ConvexShape::regular_octahedron(double edge, double sweep_radius) {
  require_positive("edge", edge);
  const double s = edge / std::sqrt(2.0);  // |(s,0,0) - (0,s,0)| = s√2 = edge
  return from_points({Vector3d(s, 0, 0), Vector3d(-s, 0, 0), Vector3d(0, s, 0),
                      Vector3d(0, -s, 0), Vector3d(0, 0, s), Vector3d(0, 0, -s)},
                     sweep_radius);
}

ConvexShape ConvexShape::from_vertex_file(const std::string& path, double sweep_radius) {
  std::ifstream in(path);
  if (!in)
    throw InvalidArgument("path", "cannot open vertex file '" + path + "'");
  std::vector<Vector3d> points;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank or comment
    std::istringstream fields(line);
    Vector3d p;
    std::string extra;
    if (!(fields >> p.x() >> p.y() >> p.z()) || (fields >> extra))
      throw InvalidArgument("path", "vertex file '" + path + "' line " +
                                        std::to_string(line_number) +
                                        ": expected three numbers \"x y z\", got \"" + line +
                                        "\"");
    points.push_back(p);
  }
  if (in.bad()) throw InvalidArgument("path", "cannot read vertex file '" + path + "'");
  try {
    return from_points(points, sweep_radius);
  } catch (const InvalidArgument& e) {
    if (e.argument() != "points") throw;
    throw InvalidArgument("path", "vertex file '" + path + "': " + e.what());
  }
}

// ---------------------------------------------------------------------------------------
// Queries and transformations

double ConvexShape::bounding_radius() const {
  double r = 0.0;
  for (const auto& v : vertices_) r = std::max(r, v.norm());
  return r + sweep_radius_;
}

ConvexShape ConvexShape::transformed(const Matrix3d& rotation, const Vector3d& translation) const {
  ConvexShape out = *this;
  for (auto& v : out.vertices_) v = rotation * v + translation;
  for (auto& f : out.faces_) {
    f.normal = (rotation * f.normal).normalized();
    f.offset = -std::numeric_limits<double>::infinity();
    for (int v : f.vertices) f.offset = std::max(f.offset, f.normal.dot(out.vertices_[v]));
  }
  out.index_incident_faces();
  return out;
}

// ---------------------------------------------------------------------------------------
// Drawing

std::vector<std::vector<Vector3d>> surface_polygons(const ConvexShape& shape, bool swept) {
  std::vector<std::vector<Vector3d>> out;
  const double r = shape.sweep_radius();
  if (!shape.is_sphere()) {
    out.reserve(shape.faces().size());
    for (const auto& face : shape.faces()) {
      const Vector3d shift = (swept ? r : 0.0) * face.normal;
      std::vector<Vector3d> polygon;
      polygon.reserve(face.vertices.size());
      for (int v : face.vertices) polygon.push_back(shape.vertices()[v] + shift);
      out.push_back(std::move(polygon));
    }
    return out;
  }
  // Ring i (polar angle θ_i = π i / B, i = 0..B; rings 0 and B are the poles), sector j
  // (azimuth φ_j = 2π j / S, S = 2B): c + r (sin θ cos φ, sin θ sin φ, cos θ). Each
  // vertex is computed once, so neighbouring polygons share it bit for bit. The loop
  // (i, j), (i+1, j), (i+1, j+1), (i, j+1) runs down, east, up: counter-clockwise seen
  // from outside (at φ = 0 the edges −z then +y give the outward normal +x).
  const int bands = kSphereDisplayBands, sectors = 2 * kSphereDisplayBands;
  const Vector3d& c = shape.vertices()[0];
  std::vector<std::vector<Vector3d>> ring(bands + 1, std::vector<Vector3d>(sectors));
  for (int i = 0; i <= bands; ++i) {
    const double theta = kPi * i / bands;
    const double sin_t = i == bands ? 0.0 : std::sin(theta), cos_t = i == bands ? -1.0 : std::cos(theta);
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2.0 * kPi * j / sectors;
      ring[i][j] = c + r * Vector3d(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
    }
  }
  out.reserve(static_cast<std::size_t>(bands) * sectors);
  for (int i = 0; i < bands; ++i)
    for (int j = 0; j < sectors; ++j) {
      const int k = (j + 1) % sectors;
      if (i == 0)
        out.push_back({ring[0][0], ring[1][j], ring[1][k]});
      else if (i == bands - 1)
        out.push_back({ring[i][j], ring[bands][0], ring[i][k]});
      else
        out.push_back({ring[i][j], ring[i + 1][j], ring[i + 1][k], ring[i][k]});
    }
  return out;
}

}  // namespace wiregrain
