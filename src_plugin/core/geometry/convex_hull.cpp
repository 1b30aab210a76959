// Convex hulls of grain vertices: ConvexShape::from_points (checks, CGAL's hull) and
// from_hull_triangles (coplanar triangles merged into convex faces, vertices that are no
// corner dropped). Declared in convex_shape.h, whose top comment gives the conventions.
#include "core/geometry/convex_shape.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

using Eigen::Vector3d;
using Triangles = std::vector<std::array<int, 3>>;
// the triangle across each directed edge (a -> b belongs to the triangle listing a, b in order)
using EdgeTriangles = std::map<std::pair<int, int>, int>;

// Two input points closer than this times the size of the cloud are duplicates; a cloud
// whose points all lie this close (relative) to one plane is flat.
constexpr double kDegenerateTolerance = 1e-10;
// Adjacent hull triangles whose vertices lie this close (relative to the size of the
// cloud) to a face's plane belong to that face; vertices this close to the line through
// their neighbours on every face are not corners. Well above the rounding of a rigidly
// moved point set (~1e-15), well below any facet of a random hull.
constexpr double kCoplanarTolerance = 1e-11;

// ---------------------------------------------------------------------------------------
// The checks of from_points

// The size of a point cloud: the diagonal of its bounding box.
double cloud_size(const std::vector<Vector3d>& points) {
  Vector3d lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// InvalidArgument("points") for two points closer than tol: a sweep in x order,
// comparing only points within tol in x.
void check_no_duplicates(const std::vector<Vector3d>& points, double tol) {
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
}

// InvalidArgument("points") when every point lies within tol of one line or of one plane
// (zero volume): the farthest point from p0, from the line p0-p1, from the plane
// p0-p1-p2. scale: the cloud's size, for the message.
void check_spans_volume(const std::vector<Vector3d>& points, double tol, double scale) {
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
}

// The hull's triangles (CGAL quickhull with exact predicates: the combinatorics are exact
// for the given doubles, and the hull vertices are copies of input points, no
// constructions), with the hull's vertices numbered in the order of the input points
// (each is a copy of one), so that a point set always gives the same numbering, whatever
// CGAL's internal order.
void hull_triangles(const std::vector<Vector3d>& points, std::vector<Vector3d>& vertices, Triangles& triangles) {
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

  std::map<std::array<double, 3>, std::size_t> input_index;
  for (std::size_t i = 0; i < points.size(); ++i)
    input_index[{points[i].x(), points[i].y(), points[i].z()}] = i;
  std::vector<std::pair<std::size_t, Mesh::Vertex_index>> by_input;
  for (const Mesh::Vertex_index v : hull.vertices()) {
    const Kernel::Point_3& p = hull.point(v);
    by_input.emplace_back(input_index.at({p.x(), p.y(), p.z()}), v);
  }
  std::sort(by_input.begin(), by_input.end());
  std::map<std::size_t, int> vertex_index;
  for (const auto& [input, v] : by_input) {
    vertex_index[static_cast<std::size_t>(v)] = static_cast<int>(vertices.size());
    vertices.push_back(points[input]);
  }
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
}

// ---------------------------------------------------------------------------------------
// The steps of from_hull_triangles

// Orient every triangle counter-clockwise from outside: the hull is closed, so the
// signed volume Σ a·(b×c)/6 about any point is positive for outward orientation.
void orient_outward(const std::vector<Vector3d>& points, Triangles& triangles) {
  Vector3d inner = Vector3d::Zero();
  for (const auto& p : points) inner += p;
  inner /= static_cast<double>(points.size());
  double signed_volume = 0.0;
  for (const auto& t : triangles)
    signed_volume += (points[t[0]] - inner).dot((points[t[1]] - inner).cross(points[t[2]] - inner));
  if (signed_volume < 0.0)
    for (auto& t : triangles) std::swap(t[1], t[2]);
}

EdgeTriangles triangles_of_edges(const Triangles& triangles) {
  EdgeTriangles triangle_of_edge;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      triangle_of_edge[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;
  return triangle_of_edge;
}

// The triangle across edge k → k+1 of triangle t; NumericalFailure on an open surface.
int neighbour_triangle(const Triangles& triangles, const EdgeTriangles& triangle_of_edge, int t, int k) {
  const auto it = triangle_of_edge.find({triangles[t][(k + 1) % 3], triangles[t][k]});
  if (it == triangle_of_edge.end()) throw NumericalFailure("convex hull is not a closed surface");
  return it->second;
}

// The faces being grown from the triangles: each triangle's group (−1: none yet) and
// each group's plane normal · x = offset (its seed's).
struct TriangleGroups {
  std::vector<int> of_triangle;
  std::vector<Vector3d> normal;
  std::vector<double> offset;
  // whether the vertices of triangle t lie within tol of group g's plane
  bool in_plane(const std::vector<Vector3d>& points, const Triangles& triangles, int t, int g, double tol) const {
    for (int v : triangles[t])
      if (std::abs(normal[g].dot(points[v]) - offset[g]) > tol) return false;
    return true;
  }
};

// Group coplanar triangles: grow each group from a seed over shared edges while the new
// triangle's vertices lie within tol of the seed's plane (no drift along curved
// surfaces) and its normal points the same way. A sliver (height below tol: three
// points that rounding put just off one edge line) has an ill-defined, even zero,
// normal: it joins any face whose plane holds its vertices, and seeds are taken
// largest first so that slivers are absorbed rather than start faces. Slivers not
// reached are left in no group (join_slivers).
TriangleGroups grow_coplanar_groups(const std::vector<Vector3d>& points, const Triangles& triangles,
                                    const EdgeTriangles& triangle_of_edge, double tol) {
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
  TriangleGroups groups;
  std::vector<int>& group = groups.of_triangle;
  group.assign(triangles.size(), -1);
  for (int seed : seeds) {
    if (group[seed] >= 0 || sliver[seed]) continue;
    const int g = static_cast<int>(groups.normal.size());
    groups.normal.push_back(triangle_normal[seed]);
    groups.offset.push_back(triangle_normal[seed].dot(points[triangles[seed][0]]));
    std::vector<int> stack{seed};
    group[seed] = g;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int u = neighbour_triangle(triangles, triangle_of_edge, t, k);
        if (group[u] >= 0 || (!sliver[u] && triangle_normal[u].dot(groups.normal[g]) <= 0.0) ||
            !groups.in_plane(points, triangles, u, g, tol))
          continue;
        group[u] = g;
        stack.push_back(u);
      }
    }
  }
  return groups;
}

// Slivers not reached from a face: join a neighbouring face whose plane holds them.
// NumericalFailure if one fits none.
void join_slivers(const std::vector<Vector3d>& points, const Triangles& triangles,
                  const EdgeTriangles& triangle_of_edge, double tol, TriangleGroups& groups) {
  std::vector<int>& group = groups.of_triangle;
  for (bool changed = true; changed;) {
    changed = false;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      if (group[t] >= 0) continue;
      for (int k = 0; k < 3 && group[t] < 0; ++k) {
        const int u = neighbour_triangle(triangles, triangle_of_edge, t, k);
        if (group[u] >= 0 && groups.in_plane(points, triangles, t, group[u], tol)) {
          group[t] = group[u];
          changed = true;
        }
      }
    }
  }
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    if (group[t] < 0) throw NumericalFailure("a degenerate hull triangle fits no face plane");
}

// Boundary loop of each group: its directed edges whose twin lies in another group,
// chained head to tail (a convex planar region has one simple boundary loop).
std::vector<std::vector<int>> group_boundary_loops(const Triangles& triangles, const EdgeTriangles& triangle_of_edge,
                                                   const std::vector<int>& group, int n_groups) {
  std::vector<std::vector<int>> loops(n_groups);
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
  return loops;
}

// Drop vertices that are no corner: on every face loop containing them they lie on the
// line through their two neighbours (they sit on an edge of the hull).
void drop_non_corners(const std::vector<Vector3d>& points, std::vector<std::vector<int>>& loops, double tol) {
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
}

// The face of a vertex loop (counter-clockwise from outside). Newell's normal:
// n ∝ Σ_i v_i × v_{i+1} (twice the vector area), exact direction for planar polygons, an
// area-weighted mean for nearly planar ones; taken relative to the first vertex against
// cancellation far from the origin. The offset: the largest n·v over the loop.
ConvexShape::Face face_of_loop(const std::vector<Vector3d>& vertices, const std::vector<int>& loop) {
  ConvexShape::Face face;
  face.vertices = loop;
  Vector3d n = Vector3d::Zero();
  const std::size_t m = face.vertices.size();
  const Vector3d& origin = vertices[face.vertices[0]];
  for (std::size_t i = 1; i + 1 < m; ++i)
    n += (vertices[face.vertices[i]] - origin).cross(vertices[face.vertices[i + 1]] - origin);
  face.normal = n.normalized();
  face.offset = -std::numeric_limits<double>::infinity();
  for (int v : face.vertices) face.offset = std::max(face.offset, face.normal.dot(vertices[v]));
  return face;
}

}  // namespace

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

  const double scale = cloud_size(points);
  const double tol = kDegenerateTolerance * scale;
  if (scale == 0.0)
    throw InvalidArgument("points", "all " + std::to_string(points.size()) +
                                        " points coincide: the hull has zero volume");
  check_no_duplicates(points, tol);
  check_spans_volume(points, tol, scale);

  std::vector<Vector3d> vertices;
  Triangles triangles;
  hull_triangles(points, vertices, triangles);
  return from_hull_triangles(vertices, triangles, sweep_radius, scale);
}

ConvexShape ConvexShape::from_hull_triangles(const std::vector<Vector3d>& points,
                                             const std::vector<std::array<int, 3>>& triangles_in,
                                             double sweep_radius, double length_scale) {
  const double tol = kCoplanarTolerance * length_scale;
  Triangles triangles = triangles_in;
  orient_outward(points, triangles);
  const EdgeTriangles triangle_of_edge = triangles_of_edges(triangles);
  TriangleGroups groups = grow_coplanar_groups(points, triangles, triangle_of_edge, tol);
  join_slivers(points, triangles, triangle_of_edge, tol, groups);
  const int n_groups = static_cast<int>(groups.normal.size());
  std::vector<std::vector<int>> loops = group_boundary_loops(triangles, triangle_of_edge, groups.of_triangle, n_groups);
  drop_non_corners(points, loops, tol);

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
    Face face = face_of_loop(shape.vertices_, loop);
    const std::size_t m = face.vertices.size();
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

}  // namespace wiregrain
