// Convex polyhedral grain shapes (spheropolyhedra) and their exact mass properties.
//
// A ConvexShape is a convex polyhedron P given in its own frame (vertices, edges and
// faces) together with a sweep radius r >= 0: the grain is the spheropolyhedron
// P ⊕ B_r (Minkowski sum of P and a ball of radius r), i.e. every point within distance r
// of P. Conventions:
//   - faces are vertex-index loops, counter-clockwise seen from outside, so that the
//     outward unit normal n satisfies n ∝ Σ_i v_i × v_{i+1} (Newell); coplanar triangles
//     of the hull are merged into one convex polygon (a cube has 6 quadrilaterals), and
//     vertices that are not corners of the hull (on an edge or inside a face) are dropped;
//   - each face stores its plane n·x = offset; every vertex satisfies n·x <= offset;
//   - edges are vertex-index pairs (i < j), each shared by exactly two faces.
//
// Mass properties come in two flavours, both exact (closed form, rounding only):
//   - "sharp": the polyhedron P alone, without the dilation by r;
//   - "dilated": the spheropolyhedron P ⊕ B_r, decomposed into P, one prism r thick on
//     every face, one cylindrical wedge on every edge and one spherical sector on every
//     vertex (the Steiner decomposition of a convex body's parallel set).
// Which one a simulation uses is the caller's choice; the difference is O(r·area/volume).
//
// A sphere is the spheropolyhedron whose core is one point: one vertex, no edges, no
// faces, sweep radius = the sphere's radius > 0 (ConvexShape::sphere, or from_points
// with one point). Its dilated mass properties are the ball's; it has no sharp volume,
// so its sharp mass properties are refused (InvalidArgument "model").
//
// Input errors throw wiregrain::InvalidArgument whose argument() is the C++ parameter name
// below (n_vertices, a, b_over_a, c_over_a, sweep_radius, points, path, edge, ...).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace wiregrain {

// Volume, mass, centre of mass and inertia tensor about the centre of mass, in the axes
// of the frame the shape is given in.
struct MassProperties {
  double volume = 0.0;
  double mass = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

// Principal moments (ascending) and principal axes (columns, a right-handed rotation
// matrix: det = +1) of a symmetric inertia tensor: inertia = axes · diag(moments) · axesᵀ.
struct PrincipalAxes {
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
};

// Which body the mass properties describe: the polyhedron alone or the dilated grain.
enum class MassModel { sharp_polyhedron, dilated };

class ConvexShape {
 public:
  struct Face {
    std::vector<int> vertices;  // counter-clockwise seen from outside
    Eigen::Vector3d normal;     // outward unit normal
    double offset = 0.0;        // plane: normal · x = offset
  };

  // Convex hull (CGAL, exact predicates) of at least 4 points that span a volume, or
  // of exactly one point: the sphere of radius sweep_radius centred there (the hull of
  // one point is that point; its vertex keeps its coordinates).
  // Rejects: 2 or 3 points, two points closer than 1e-10 times the size of the
  // point cloud (duplicates), all points within 1e-10 times that size of one plane
  // (flat or collinear: zero volume), non-finite coordinates, sweep_radius < 0, and
  // sweep_radius = 0 for one point (argument "sweep_radius").
  static ConvexShape from_points(const std::vector<Eigen::Vector3d>& points,
                                 double sweep_radius);

  // The sphere of the given radius centred at the origin: one vertex at the origin, no
  // edges, no faces, sweep radius = radius. Rejects radius <= 0 or not finite
  // (argument "radius").
  static ConvexShape sphere(double radius);

  // Convex hull of n_vertices random points on the surface of the ellipsoid with
  // semi-axes a ≥ b ≥ c along x, y, z (b = b_over_a·a, c = c_over_a·a). Each point is a
  // direction drawn uniformly on the unit sphere (z uniform in [-1, 1], azimuth uniform:
  // Archimedes) scaled by (a, b, c); the points are therefore denser near the ends of
  // the long axis than an area-uniform sample would be. Every point is a hull vertex
  // (the ellipsoid is strictly convex). The random numbers are taken from the raw
  // 64-bit output of the engine, so a seed gives the same shape on every platform.
  // Rejects n_vertices < 4, a <= 0, b_over_a outside (0, 1], c_over_a outside
  // (0, b_over_a], sweep_radius < 0.
  static ConvexShape random_ellipsoid(std::mt19937_64& rng, int n_vertices, double a,
                                      double b_over_a, double c_over_a,
                                      double sweep_radius);
  static ConvexShape random_ellipsoid(std::uint64_t seed, int n_vertices, double a,
                                      double b_over_a, double c_over_a,
                                      double sweep_radius);

  // Regular solids centred at the origin (for tests and simple setups).
  static ConvexShape cube(double edge, double sweep_radius = 0.0);
  static ConvexShape box(double lx, double ly, double lz, double sweep_radius = 0.0);
  static ConvexShape regular_tetrahedron(double edge, double sweep_radius = 0.0);
  static ConvexShape regular_octahedron(double edge, double sweep_radius = 0.0);

  // Hull of the points in a text file, one "x y z" per line; '#' starts a comment,
  // blank lines are skipped. An unreadable file or a malformed line throws
  // InvalidArgument("path", ...) naming the file (and the line).
  static ConvexShape from_vertex_file(const std::string& path, double sweep_radius);

  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }
  const std::vector<Face>& faces() const { return faces_; }
  // per vertex: the faces and the edges that contain it, ascending indices
  const std::vector<int>& faces_at_vertex(int v) const { return faces_at_vertex_[v]; }
  const std::vector<int>& edges_at_vertex(int v) const { return edges_at_vertex_[v]; }
  // per face, with at most 64 vertices (else empty): bit i set when vertex i is a corner
  // (one contiguous array: the contact geometry tests many faces of many shapes per step)
  const std::vector<std::uint64_t>& face_vertex_masks() const { return face_vertex_masks_; }
  // per vertex, its faces (ascending index) with what the feature selection of the
  // contact geometry reads of them, side by side: the normal, the corner mask (0 above 64
  // vertices) and the index. Reading them through faces_at_vertex, the masks and faces()
  // was a chase of cache misses over the 915 shapes of a column (half of that loop's time).
  struct IncidentFace {
    Eigen::Vector3d normal;
    std::uint64_t mask = 0;
    int face = -1;
  };
  struct IncidentFaces {
    const IncidentFace *first, *last;
    const IncidentFace* begin() const { return first; }
    const IncidentFace* end() const { return last; }
  };
  IncidentFaces incident_faces(int v) const {
    return {incident_faces_.data() + incident_offsets_[v], incident_faces_.data() + incident_offsets_[v + 1]};
  }
  double sweep_radius() const { return sweep_radius_; }
  // True for a sphere: the core is one point (one vertex, no edges, no faces).
  bool is_sphere() const { return faces_.empty(); }
  // max |v| over the vertices plus the sweep radius: the radius of a sphere about the
  // frame origin that contains the grain (about the centroid once in the body frame).
  double bounding_radius() const;

  // The same shape moved rigidly: every point x becomes rotation·x + translation.
  // `rotation` must be a rotation matrix (orthonormal, det +1).
  ConvexShape transformed(const Eigen::Matrix3d& rotation,
                          const Eigen::Vector3d& translation) const;

  // Exact mass properties of the polyhedron P (no dilation) for a uniform density:
  // divergence theorem on signed tetrahedra (reference point, face-fan triangle), with
  // ∫_T x xᵀ dV = V_T/20 (Σ_k v_k v_kᵀ + s sᵀ), s = Σ_k v_k, over the 4 vertices of T.
  // A sphere's core is a point of zero volume: InvalidArgument("model", ...) (use the
  // dilated model).
  MassProperties sharp_mass_properties(double density) const;

  // Exact mass properties of the spheropolyhedron P ⊕ B_r. Its volume is Steiner's
  // V_r = V + S r + (r²/2) Σ_edges L_e α_e + (4π/3) r³ (α_e: angle between the normals
  // of the edge's two faces). See convex_shape.cpp for the pieces' moments. For a
  // sphere: the ball, V = 4π r³/3, inertia 2/5 m r² about its centre.
  MassProperties dilated_mass_properties(double density) const;

  // InvalidArgument("model", ...) for the sharp model of a sphere (see above).
  MassProperties mass_properties(double density, MassModel model) const;

 private:
  ConvexShape() = default;
  // Builds faces/edges from a triangulated hull; merges coplanar triangles.
  static ConvexShape from_hull_triangles(const std::vector<Eigen::Vector3d>& points,
                                         const std::vector<std::array<int, 3>>& triangles,
                                         double sweep_radius, double length_scale);

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<Face> faces_;
  std::vector<std::vector<int>> faces_at_vertex_, edges_at_vertex_;
  std::vector<std::uint64_t> face_vertex_masks_;
  std::vector<IncidentFace> incident_faces_;
  std::vector<int> incident_offsets_;  // vertex v's incident faces: [offsets[v], offsets[v + 1])
  double sweep_radius_ = 0.0;
  void index_adjacency();
  void index_incident_faces();  // from faces_at_vertex_, the faces and the masks
};

// Polygons that draw a grain (body frame; each convex, counter-clockwise seen from
// outside), for output such as dump polyhedron/vtk:
//   - a polyhedral core: its faces, each moved out along its normal by the sweep radius
//     when `swept` (the spheropolyhedron's flat faces; edges and corners not rounded);
//   - a sphere, whatever `swept` (its point core alone draws nothing): the ball of radius
//     r tessellated along latitudes and longitudes, kSphereDisplayBands bands of polar
//     angle π/kSphereDisplayBands times 2·kSphereDisplayBands sectors, triangles at the
//     poles and planar quadrilaterals between, every vertex on the sphere.
constexpr int kSphereDisplayBands = 8;
std::vector<std::vector<Eigen::Vector3d>> surface_polygons(const ConvexShape& shape, bool swept);

// Principal moments (ascending) and right-handed principal axes of an inertia tensor
// (Eigen::SelfAdjointEigenSolver).
PrincipalAxes principal_axes(const Eigen::Matrix3d& inertia);

// A shape re-expressed in its body frame: centre of mass at the origin, principal axes
// of inertia along x, y, z with ascending moments, right-handed. A point x_body of the
// body-frame shape is the point  rotation · x_body + centroid  of the input shape.
struct BodyFrameShape {
  ConvexShape shape;
  Eigen::Quaterniond rotation;      // body frame -> input frame (unit quaternion)
  Eigen::Vector3d centroid;         // centre of mass in the input frame
  MassProperties mass;              // in the body frame: centroid 0, inertia diagonal
  Eigen::Vector3d principal_moments;  // ascending, = mass.inertia diagonal
};

// Body frame from the mass properties of the chosen model (sharp or dilated).
BodyFrameShape to_body_frame(const ConvexShape& shape, double density,
                             MassModel model = MassModel::sharp_polyhedron);

}  // namespace wiregrain
