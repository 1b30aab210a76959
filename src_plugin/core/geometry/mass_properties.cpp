// Exact mass properties of polyhedra and spheropolyhedra, principal axes and the body
// frame. Declared in convex_shape.h.
#include "core/geometry/convex_shape.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

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
