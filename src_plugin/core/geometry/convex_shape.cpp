// Convex hulls of grain vertices and exact mass properties of polyhedra and
// spheropolyhedra. See convex_shape.h for the conventions.
#include "core/geometry/convex_shape.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;


// Two input points closer than this times the size of the cloud are duplicates; a cloud
// whose points all lie this close (relative) to one plane is flat.
constexpr double kDegenerateTolerance = 1e-10;
// Adjacent hull triangles whose vertices lie this close (relative to the size of the
// cloud) to a face's plane belong to that face; vertices this close to the line through
// their neighbours on every face are not corners. Well above the rounding of a rigidly
// moved point set (~1e-15), well below any facet of a random hull.
constexpr double kCoplanarTolerance = 1e-11;

// Uniform double in [0, 1) from the top 53 bits of one engine output (platform-independent,
// unlike std::uniform_real_distribution).
double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Second moment ∫ x xᵀ of a triangle (area A, vertices a, b, c):
// A/12 (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a + b + c.
Matrix3d triangle_second_moment(double area, const Vector3d& a, const Vector3d& b,
                                const Vector3d& c) {
  const Vector3d s = a + b + c;
  return area / 12.0 *
         (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
}

// Moments about a reference point o: ∫ 1, ∫ (x - o), ∫ (x - o)(x - o)ᵀ.
struct Moments {
  double volume = 0.0;
  Vector3d first = Vector3d::Zero();
  Matrix3d second = Matrix3d::Zero();
};

MassProperties mass_properties_from_moments(const Moments& m, const Vector3d& reference,
                                            double density) {
  MassProperties p;
  p.volume = m.volume;
  p.mass = density * m.volume;
  const Vector3d shift = m.first / m.volume;
  p.centroid = reference + shift;
  // second moment about the centroid (parallel-axis theorem), then
  // I = ρ (tr C · 1 − C)
  Matrix3d c = m.second - m.volume * shift * shift.transpose();
  c = 0.5 * (c + c.transpose());
  p.inertia = density * (c.trace() * Matrix3d::Identity() - c);
  return p;
}

// Moments of the polyhedron: one signed tetrahedron (o, v0, vi, vi+1) per fan triangle
// of every face. Coordinates relative to o: the apex is 0, so with a, b, c the other
// three vertices, V_T = a·(b×c)/6, ∫ x = V_T s/4 and ∫ x xᵀ = V_T/20 (a aᵀ + b bᵀ + c cᵀ
// + s sᵀ), s = a + b + c (Tonon 2004, J. Math. Stat. 1, 8; the affine image of the unit
// simplex moments ∫λ_i = 1/24, ∫λ_iλ_j = (1+δ_ij)/120).
Moments polyhedron_moments(const std::vector<Vector3d>& vertices,
                           const std::vector<ConvexShape::Face>& faces,
                           const Vector3d& reference) {
  Moments m;
  for (const auto& face : faces) {
    const Vector3d a = vertices[face.vertices[0]] - reference;
    for (std::size_t i = 1; i + 1 < face.vertices.size(); ++i) {
      const Vector3d b = vertices[face.vertices[i]] - reference;
      const Vector3d c = vertices[face.vertices[i + 1]] - reference;
      const double vol = a.dot(b.cross(c)) / 6.0;
      const Vector3d s = a + b + c;
      m.volume += vol;
      m.first += vol / 4.0 * s;
      m.second += vol / 20.0 *
                  (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }
  return m;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Construction

ConvexShape ConvexShape::from_points(const std::vector<Vector3d>& points, double sweep_radius) {
  require_nonnegative("sweep_radius", sweep_radius);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      throw InvalidArgument("points", "point " + std::to_string(i) +
                                          " has a non-finite coordinate");
  // One point: its hull is the point, and the grain the sphere of radius sweep_radius
  // about it (one vertex, no edges, no faces).
  if (points.size() == 1) {
    if (!(sweep_radius > 0.0))
      throw InvalidArgument("sweep_radius",
                            "one point is a sphere and needs sweep_radius > 0 (its radius), got " +
                                format_number(sweep_radius));
    ConvexShape shape;
    shape.vertices_ = points;
    shape.sweep_radius_ = sweep_radius;
    shape.index_adjacency();
    return shape;
  }
  if (points.size() < 4)
    throw InvalidArgument("points", "a convex polyhedron needs at least 4 points, got " +
                                        std::to_string(points.size()) +
                                        " (one point with sweep_radius > 0 makes a sphere)");

  // size of the cloud: diagonal of its bounding box
  Vector3d lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double scale = (hi - lo).norm();
  const double tol = kDegenerateTolerance * scale;
  if (scale == 0.0)
    throw InvalidArgument("points", "all " + std::to_string(points.size()) +
                                        " points coincide: the hull has zero volume");

  // duplicates: sweep in x order, comparing only points within tol in x
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return points[i].x() < points[j].x(); });
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t l = k + 1;
         l < order.size() && points[order[l]].x() - points[order[k]].x() <= tol; ++l)
      if ((points[order[l]] - points[order[k]]).norm() <= tol) {
        const std::size_t i = std::min(order[k], order[l]), j = std::max(order[k], order[l]);
        throw InvalidArgument("points", "points " + std::to_string(i) + " and " +
                                            std::to_string(j) +
                                            " are duplicates (closer than " + format_number(tol) +
                                            ")");
      }

  // flatness: farthest point from p0, from the line p0-p1, from the plane p0-p1-p2
  const Vector3d& p0 = points[0];
  std::size_t i1 = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if ((points[i] - p0).squaredNorm() > (points[i1] - p0).squaredNorm()) i1 = i;
  const Vector3d axis = (points[i1] - p0).normalized();
  std::size_t i2 = 0;
  double line_distance = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (points[i] - p0).cross(axis).norm();
    if (d > line_distance) {
      line_distance = d;
      i2 = i;
    }
  }
  if (line_distance <= tol)
    throw InvalidArgument("points",
                          "all points lie on one line: the hull has zero volume");
  const Vector3d plane_normal = axis.cross(points[i2] - p0).normalized();
  double plane_distance = 0.0;
  for (const auto& p : points) plane_distance = std::max(plane_distance, std::abs(plane_normal.dot(p - p0)));
  if (plane_distance <= tol)
    throw InvalidArgument("points",
                          "all points lie in one plane (largest distance " +
                              format_number(plane_distance) + " for a cloud of size " + format_number(scale) +
                              "): the hull has zero volume");

  // CGAL quickhull with exact predicates: the combinatorics are exact for the given
  // doubles, and the hull vertices are copies of input points (no constructions).
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> input;
  input.reserve(points.size());
  for (const auto& p : points) input.emplace_back(p.x(), p.y(), p.z());
  // Output into a Surface_mesh: CGAL 5.5's overload that writes an indexed triangle set
  // (point vector + index triples) was seen to return a non-convex triangle set (a corner
  // outside one of its facets) for a rotated cube with extra points within rounding of
  // its edges and faces; the Surface_mesh output of the same input was correct.
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Mesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);

  // Number the hull vertices in the order of the input points (each is a copy of one),
  // so that a point set always gives the same numbering, whatever CGAL's internal order.
  std::map<std::array<double, 3>, std::size_t> input_index;
  for (std::size_t i = 0; i < points.size(); ++i)
    input_index[{points[i].x(), points[i].y(), points[i].z()}] = i;
  std::vector<std::pair<std::size_t, Mesh::Vertex_index>> by_input;
  for (const Mesh::Vertex_index v : hull.vertices()) {
    const Kernel::Point_3& p = hull.point(v);
    by_input.emplace_back(input_index.at({p.x(), p.y(), p.z()}), v);
  }
  std::sort(by_input.begin(), by_input.end());
  std::vector<Vector3d> vertices;
  std::map<std::size_t, int> vertex_index;
  for (const auto& [input, v] : by_input) {
    vertex_index[static_cast<std::size_t>(v)] = static_cast<int>(vertices.size());
    vertices.push_back(points[input]);
  }
  std::vector<std::array<int, 3>> triangles;
  for (const Mesh::Face_index f : hull.faces()) {
    std::array<int, 3> triangle{};
    int corner = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      if (corner == 3) throw NumericalFailure("convex hull face is not a triangle");
      triangle[corner++] = vertex_index.at(static_cast<std::size_t>(v));
    }
    if (corner != 3) throw NumericalFailure("convex hull face is not a triangle");
    triangles.push_back(triangle);
  }
  return from_hull_triangles(vertices, triangles, sweep_radius, scale);
}

ConvexShape ConvexShape::from_hull_triangles(const std::vector<Vector3d>& points,
                                             const std::vector<std::array<int, 3>>& triangles_in,
                                             double sweep_radius, double length_scale) {
  const double tol = kCoplanarTolerance * length_scale;
  std::vector<std::array<int, 3>> triangles = triangles_in;

  // Orient every triangle counter-clockwise from outside: the hull is closed, so the
  // signed volume Σ a·(b×c)/6 about any point is positive for outward orientation.
  Vector3d inner = Vector3d::Zero();
  for (const auto& p : points) inner += p;
  inner /= static_cast<double>(points.size());
  double signed_volume = 0.0;
  for (const auto& t : triangles)
    signed_volume += (points[t[0]] - inner).dot((points[t[1]] - inner).cross(points[t[2]] - inner));
  if (signed_volume < 0.0)
    for (auto& t : triangles) std::swap(t[1], t[2]);

  // triangle across each directed edge (a -> b belongs to the triangle listing a, b in order)
  std::map<std::pair<int, int>, int> triangle_of_edge;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      triangle_of_edge[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;

  // Group coplanar triangles: grow each group from a seed over shared edges while the new
  // triangle's vertices lie within tol of the seed's plane (no drift along curved
  // surfaces) and its normal points the same way. A sliver (height below tol: three
  // points that rounding put just off one edge line) has an ill-defined, even zero,
  // normal: it joins any face whose plane holds its vertices, and seeds are taken
  // largest first so that slivers are absorbed rather than start faces.
  std::vector<Vector3d> triangle_normal(triangles.size());
  std::vector<double> triangle_area(triangles.size());
  std::vector<bool> sliver(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tr = triangles[t];
    const Vector3d n = (points[tr[1]] - points[tr[0]]).cross(points[tr[2]] - points[tr[0]]);
    triangle_area[t] = 0.5 * n.norm();
    triangle_normal[t] = n.normalized();
    double longest = 0.0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (points[tr[(k + 1) % 3]] - points[tr[k]]).norm());
    sliver[t] = 2.0 * triangle_area[t] <= tol * longest;  // height <= tol
  }
  std::vector<int> seeds(triangles.size());
  std::iota(seeds.begin(), seeds.end(), 0);
  std::stable_sort(seeds.begin(), seeds.end(),
                   [&](int s, int t) { return triangle_area[s] > triangle_area[t]; });
  std::vector<int> group(triangles.size(), -1);
  std::vector<Vector3d> group_normal;
  std::vector<double> group_offset;
  const auto neighbour = [&](int t, int k) {
    const auto it = triangle_of_edge.find({triangles[t][(k + 1) % 3], triangles[t][k]});
    if (it == triangle_of_edge.end()) throw NumericalFailure("convex hull is not a closed surface");
    return it->second;
  };
  const auto in_plane = [&](int t, int g) {
    for (int v : triangles[t])
      if (std::abs(group_normal[g].dot(points[v]) - group_offset[g]) > tol) return false;
    return true;
  };
  for (int seed : seeds) {
    if (group[seed] >= 0 || sliver[seed]) continue;
    const int g = static_cast<int>(group_normal.size());
    group_normal.push_back(triangle_normal[seed]);
    group_offset.push_back(triangle_normal[seed].dot(points[triangles[seed][0]]));
    std::vector<int> stack{seed};
    group[seed] = g;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int u = neighbour(t, k);
        if (group[u] >= 0 || (!sliver[u] && triangle_normal[u].dot(group_normal[g]) <= 0.0) ||
            !in_plane(u, g))
          continue;
        group[u] = g;
        stack.push_back(u);
      }
    }
  }
  // slivers not reached from a face: join a neighbouring face whose plane holds them
  for (bool changed = true; changed;) {
    changed = false;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      if (group[t] >= 0) continue;
      for (int k = 0; k < 3 && group[t] < 0; ++k) {
        const int u = neighbour(t, k);
        if (group[u] >= 0 && in_plane(t, group[u])) {
          group[t] = group[u];
          changed = true;
        }
      }
    }
  }
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    if (group[t] < 0) throw NumericalFailure("a degenerate hull triangle fits no face plane");
  const int n_groups = static_cast<int>(group_normal.size());

  // Boundary loop of each group: its directed edges whose twin lies in another group,
  // chained head to tail (a convex planar region has one simple boundary loop).
  std::vector<std::vector<int>> loops(n_groups);
  {
    std::vector<std::map<int, int>> next_of(n_groups);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
        const auto twin = triangle_of_edge.find({b, a});
        if (twin == triangle_of_edge.end())
          throw NumericalFailure("convex hull is not a closed surface");
        if (group[twin->second] != group[t]) next_of[group[t]][a] = b;
      }
    for (int g = 0; g < n_groups; ++g) {
      const auto& next = next_of[g];
      if (next.size() < 3) throw NumericalFailure("merged hull face has fewer than 3 edges");
      const int start = next.begin()->first;
      int v = start;
      do {
        loops[g].push_back(v);
        const auto it = next.find(v);
        if (it == next.end()) throw NumericalFailure("merged hull face boundary is not a loop");
        v = it->second;
      } while (v != start && loops[g].size() <= next.size());
      if (loops[g].size() != next.size())
        throw NumericalFailure("merged hull face boundary is not a single loop");
    }
  }

  // Drop vertices that are no corner: on every face loop containing them they lie on the
  // line through their two neighbours (they sit on an edge of the hull).
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<int> uses(points.size(), 0), straight(points.size(), 0);
    for (const auto& loop : loops) {
      const std::size_t n = loop.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Vector3d& prev = points[loop[(i + n - 1) % n]];
        const Vector3d& here = points[loop[i]];
        const Vector3d& next = points[loop[(i + 1) % n]];
        const Vector3d chord = next - prev;
        const double distance = (here - prev).cross(chord).norm() / chord.norm();
        ++uses[loop[i]];
        if (distance <= tol) ++straight[loop[i]];
      }
    }
    for (std::size_t v = 0; v < points.size(); ++v)
      if (uses[v] > 0 && straight[v] == uses[v]) {
        for (auto& loop : loops) {
          const auto it = std::find(loop.begin(), loop.end(), static_cast<int>(v));
          if (it != loop.end()) loop.erase(it);
        }
        changed = true;
        break;  // recount: neighbours changed
      }
  }

  // Keep the vertices used by some face, renumbered in input order.
  std::vector<bool> used(points.size(), false);
  for (const auto& loop : loops)
    for (int v : loop) used[v] = true;
  std::vector<int> new_index(points.size(), -1);
  ConvexShape shape;
  shape.sweep_radius_ = sweep_radius;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) {
      new_index[v] = static_cast<int>(shape.vertices_.size());
      shape.vertices_.push_back(points[v]);
    }

  // Canonical order: each loop starts at its lowest vertex, faces sorted by their loops.
  for (auto& loop : loops) {
    for (int& v : loop) v = new_index[v];
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  }
  std::sort(loops.begin(), loops.end());

  std::map<std::pair<int, int>, int> edge_uses;
  for (const auto& loop : loops) {
    if (loop.size() < 3) throw NumericalFailure("merged hull face has fewer than 3 corners");
    Face face;
    face.vertices = loop;
    // Newell's normal: n ∝ Σ_i v_i × v_{i+1} (twice the vector area), exact direction for
    // planar polygons, an area-weighted mean for nearly planar ones; taken relative to
    // the first vertex against cancellation far from the origin.
    Vector3d n = Vector3d::Zero();
    const std::size_t m = face.vertices.size();
    const Vector3d& origin = shape.vertices_[face.vertices[0]];
    for (std::size_t i = 1; i + 1 < m; ++i)
      n += (shape.vertices_[face.vertices[i]] - origin)
               .cross(shape.vertices_[face.vertices[i + 1]] - origin);
    face.normal = n.normalized();
    face.offset = -std::numeric_limits<double>::infinity();
    for (int v : face.vertices) face.offset = std::max(face.offset, face.normal.dot(shape.vertices_[v]));
    for (std::size_t i = 0; i < m; ++i) {
      const int a = face.vertices[i], b = face.vertices[(i + 1) % m];
      ++edge_uses[{std::min(a, b), std::max(a, b)}];
    }
    shape.faces_.push_back(std::move(face));
  }
  for (const auto& [edge, count] : edge_uses) {
    if (count != 2) throw NumericalFailure("hull edge not shared by exactly two faces");
    shape.edges_.push_back({edge.first, edge.second});
  }
  shape.index_adjacency();
  return shape;
}

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
// Mass properties

MassProperties ConvexShape::sharp_mass_properties(double density) const {
  require_positive("density", density);
  if (is_sphere())
    throw InvalidArgument("model",
                          "a sphere has no sharp mass properties: its core is one point, of zero "
                          "volume (use the dilated mass model)");
  Vector3d reference = Vector3d::Zero();
  for (const auto& v : vertices_) reference += v;
  reference /= static_cast<double>(vertices_.size());
  return mass_properties_from_moments(polyhedron_moments(vertices_, faces_, reference),
                                      reference, density);
}

// The parallel set P ⊕ B_r minus P splits (up to measure zero) into
//   face prisms     F × [0, r] n_F,
//   edge wedges     {p + s e + ρ u(φ)}: s ∈ [0, L], ρ ∈ [0, r], u turning from n_f to n_g
//                   in the plane ⊥ e through the angle α = ∠(n_f, n_g),
//   vertex sectors  {v + ρ u}: ρ ∈ [0, r], u ∈ Ω_v, the normal cone of P at v (a convex
//                   spherical polygon whose corners are the normals of the faces at v),
// because every point of the parallel set outside P has a unique nearest point on P, in
// the relative interior of exactly one face, edge or vertex.
//
// With u(φ) = cos φ n_f + sin φ w (w ⊥ e, n_f, towards n_g):
//   U1 = ∫₀^α u dφ = sin α n_f + (1 − cos α) w,
//   U2 = ∫₀^α u uᵀ dφ = (α/2 + sin 2α/4) n_f n_fᵀ + (α/2 − sin 2α/4) w wᵀ
//                       + (sin²α/2)(n_f wᵀ + w n_fᵀ).
// For the sectors, |Ω_v| = 2π − Σ (face angles at v) (angle defect), and the divergence
// theorem on the unit cone K_v = {ρ u: u ∈ Ω_v, ρ ≤ 1}, whose flat sides lie in the planes
// ⊥ each edge (v, w) with inward normal m = (v − w)/|v − w|, gives
//   M1 = ∫_Ω u dΩ = Σ_edges (α_e / 2) m_e                  (from ∫_K ∇1 = 0),
//   M2 = ∫_Ω u uᵀ dΩ = |Ω|/3 · 1 + Σ_edges S_e m_eᵀ        (from ∫_K ∂_j x_k = δ_jk |K|),
// with S_e = U1_e / 3 the first moment of the flat unit sector of edge e.
MassProperties ConvexShape::dilated_mass_properties(double density) const {
  require_positive("density", density);
  const double r = sweep_radius_;
  Vector3d reference = Vector3d::Zero();
  for (const auto& v : vertices_) reference += v;
  reference /= static_cast<double>(vertices_.size());
  Moments m = polyhedron_moments(vertices_, faces_, reference);
  if (r == 0.0) return mass_properties_from_moments(m, reference, density);

  const double r2 = r * r, r3 = r2 * r, r4 = r3 * r, r5 = r4 * r;

  // face prisms: ∫ over y ∈ F, t ∈ [0, r] of 1, y + t n, (y + t n)(y + t n)ᵀ
  std::map<std::pair<int, int>, int> face_of_directed_edge;
  std::vector<double> face_angle_sum(vertices_.size(), 0.0);
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
    const Face& face = faces_[f];
    const Vector3d& n = face.normal;
    const std::size_t k = face.vertices.size();
    double area = 0.0;
    Vector3d first = Vector3d::Zero();
    Matrix3d second = Matrix3d::Zero();
    const Vector3d a = vertices_[face.vertices[0]] - reference;
    for (std::size_t i = 1; i + 1 < k; ++i) {
      const Vector3d b = vertices_[face.vertices[i]] - reference;
      const Vector3d c = vertices_[face.vertices[i + 1]] - reference;
      const double tri_area = 0.5 * n.dot((b - a).cross(c - a));
      area += tri_area;
      first += tri_area / 3.0 * (a + b + c);
      second += triangle_second_moment(tri_area, a, b, c);
    }
    m.volume += r * area;
    m.first += r * first + 0.5 * r2 * area * n;
    m.second += r * second + 0.5 * r2 * (first * n.transpose() + n * first.transpose()) +
                r3 / 3.0 * area * n * n.transpose();

    for (std::size_t i = 0; i < k; ++i) {
      const int prev = face.vertices[(i + k - 1) % k], here = face.vertices[i],
                next = face.vertices[(i + 1) % k];
      face_of_directed_edge[{here, next}] = f;
      const Vector3d to_prev = vertices_[prev] - vertices_[here];
      const Vector3d to_next = vertices_[next] - vertices_[here];
      face_angle_sum[here] += std::atan2(to_prev.cross(to_next).norm(), to_prev.dot(to_next));
    }
  }

  // edge wedges, and the edges' contributions to the vertex sectors' M1 and M2
  std::vector<Vector3d> sector_first(vertices_.size(), Vector3d::Zero());
  std::vector<Matrix3d> sector_second(vertices_.size(), Matrix3d::Zero());
  for (const auto& edge : edges_) {
    const int i = edge[0], j = edge[1];
    const Vector3d& n_f = faces_[face_of_directed_edge.at({i, j})].normal;
    const Vector3d& n_g = faces_[face_of_directed_edge.at({j, i})].normal;
    const Vector3d p = vertices_[i] - reference;
    const Vector3d along = vertices_[j] - vertices_[i];
    const double length = along.norm();
    const Vector3d e = along / length;
    const double alpha = std::atan2(n_f.cross(n_g).norm(), n_f.dot(n_g));
    Vector3d w = e.cross(n_f).normalized();
    if (w.dot(n_g) < 0.0) w = -w;
    const double sin_a = std::sin(alpha), cos_a = std::cos(alpha), sin_2a = std::sin(2.0 * alpha);
    const Vector3d u1 = sin_a * n_f + (1.0 - cos_a) * w;
    const Matrix3d u2 = (0.5 * alpha + 0.25 * sin_2a) * n_f * n_f.transpose() +
                        (0.5 * alpha - 0.25 * sin_2a) * w * w.transpose() +
                        0.5 * sin_a * sin_a * (n_f * w.transpose() + w * n_f.transpose());
    // ∫₀^L a(s) ds and ∫₀^L a aᵀ ds along the edge line a(s) = p + s e
    const Vector3d line_first = length * p + 0.5 * length * length * e;
    const Matrix3d line_second = length * p * p.transpose() +
                                 0.5 * length * length * (p * e.transpose() + e * p.transpose()) +
                                 length * length * length / 3.0 * e * e.transpose();
    // volume element ρ dρ dφ ds
    m.volume += 0.5 * r2 * alpha * length;
    m.first += 0.5 * r2 * alpha * line_first + r3 / 3.0 * length * u1;
    m.second += 0.5 * r2 * alpha * line_second +
                r3 / 3.0 * (line_first * u1.transpose() + u1 * line_first.transpose()) +
                0.25 * r4 * length * u2;

    const Vector3d flat_sector_first = u1 / 3.0;
    sector_first[i] += 0.5 * alpha * (-e);  // inward side normal at i: (v_i − v_j)/L
    sector_first[j] += 0.5 * alpha * e;
    sector_second[i] += flat_sector_first * (-e).transpose();
    sector_second[j] += flat_sector_first * e.transpose();
  }

  // vertex sectors: volume element ρ² dρ dΩ. The lone vertex of a sphere has no faces and
  // its normal cone is the whole unit sphere: |Ω| = 4π, M1 = 0, M2 = 4π/3 · 1, so the
  // sector is the ball, V = 4π r³/3, ∫ x xᵀ = 4π r⁵/15 · 1, I = 8π ρ r⁵/15 = 2/5 m r².
  for (std::size_t v = 0; v < vertices_.size(); ++v) {
    const double solid_angle = is_sphere() ? 4.0 * kPi : 2.0 * kPi - face_angle_sum[v];
    Matrix3d m2 = solid_angle / 3.0 * Matrix3d::Identity() + sector_second[v];
    m2 = 0.5 * (m2 + m2.transpose());
    const Vector3d& m1 = sector_first[v];
    const Vector3d p = vertices_[v] - reference;
    m.volume += r3 / 3.0 * solid_angle;
    m.first += r3 / 3.0 * solid_angle * p + 0.25 * r4 * m1;
    m.second += r3 / 3.0 * solid_angle * p * p.transpose() +
                0.25 * r4 * (p * m1.transpose() + m1 * p.transpose()) + 0.2 * r5 * m2;
  }
  return mass_properties_from_moments(m, reference, density);
}

MassProperties ConvexShape::mass_properties(double density, MassModel model) const {
  return model == MassModel::dilated ? dilated_mass_properties(density)
                                     : sharp_mass_properties(density);
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

PrincipalAxes principal_axes(const Matrix3d& inertia) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> solver(0.5 * (inertia + inertia.transpose()));
  if (solver.info() != Eigen::Success)
    throw NumericalFailure("eigen-decomposition of the inertia tensor failed");
  PrincipalAxes axes;
  axes.moments = solver.eigenvalues();  // ascending
  axes.axes = solver.eigenvectors();
  // Equal moments leave the axes free within their eigenspace, and the solver then
  // returns whatever rounding dictates. Choose them as close to the input axes as
  // possible, so a cube, tetrahedron or octahedron (all moments equal) keeps its input
  // orientation and a symmetric top keeps its input axes around the symmetry axis.
  const Vector3d& m = axes.moments;
  const double tol = 1e-10 * std::max(std::abs(m[2]), 1e-300);
  const bool low_pair = m[1] - m[0] <= tol, high_pair = m[2] - m[1] <= tol;
  if (low_pair && high_pair) {
    axes.axes.setIdentity();
  } else if (low_pair || high_pair) {
    const Vector3d unique = low_pair ? axes.axes.col(2) : axes.axes.col(0);
    // the input axis least aligned with the unique one, projected into its plane
    int k = 0;
    for (int d = 1; d < 3; ++d)
      if (std::abs(unique[d]) < std::abs(unique[k])) k = d;
    Vector3d first = Vector3d::Unit(k) - unique[k] * unique;
    first.normalize();
    if (low_pair) {
      axes.axes.col(0) = first;
      axes.axes.col(1) = unique.cross(first);
    } else {
      axes.axes.col(1) = first;
      axes.axes.col(2) = unique.cross(first);
    }
  }
  if (axes.axes.determinant() < 0.0) axes.axes.col(2) = -axes.axes.col(2);
  return axes;
}

BodyFrameShape to_body_frame(const ConvexShape& shape, double density, MassModel model) {
  const MassProperties mass = shape.mass_properties(density, model);
  const PrincipalAxes axes = principal_axes(mass.inertia);
  const Matrix3d& rotation = axes.axes;  // columns: body axes in the input frame
  // x_input = R x_body + c  ⇔  x_body = Rᵀ (x_input − c)
  BodyFrameShape body{shape.transformed(rotation.transpose(), -(rotation.transpose() * mass.centroid)),
                      Eigen::Quaterniond(rotation).normalized(),
                      mass.centroid,
                      mass,
                      axes.moments};
  body.mass.centroid = Vector3d::Zero();
  body.mass.inertia = axes.moments.asDiagonal();
  return body;
}

}  // namespace wiregrain
