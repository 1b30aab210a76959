// Elasticity of the wire: a chain of point masses joined by axial springs, with a
// rotational (bending) spring at every inner node; no torsion (paper Sec. 2.2, Fig. 3).
// Stateless force kernels in the manner of LAMMPS bond/angle styles, so the LIGGGHTS
// adapter only loops over its bonds and angles. Formulas and sources: docs/design.md, "Wire forces and integration".
#pragma once

#include <Eigen/Core>
#include <vector>

namespace wiregrain {

// Wire material and discretisation; defaults from the paper's Table 1 (dimensionless).
// validate() names the offending parameter with these keywords:
//   E, radius, segment_length, density (> 0), m_elo, m_rot (>= 0); all finite.
struct WireMaterial {
  double youngs_modulus = 100.0;        // E_w                 keyword "E"
  double radius = 0.1;                  // r_w                 keyword "radius"
  double segment_length = 0.2;          // l_w, rest length    keyword "segment_length"
  double elongation_multiplier = 1.0;   // m_elo               keyword "m_elo"
  double rotation_multiplier = 0.1;     // m_rot               keyword "m_rot"
  double density = 0.5;                 // ρ_w                 keyword "density"

  // Throws InvalidArgument naming the first parameter out of its domain.
  void validate() const;

  // A = π r_w²
  double cross_section_area() const;
  // I = π r_w⁴ / 4 (second moment of area of the circular section)
  double second_moment_of_area() const;
  // m = ρ_w A l_w: one segment's mass lumped into one node (an end node gets the same).
  double node_mass() const;
  // k_s = m_elo E A / l_w: force per unit change of one segment's length. Per unit
  // length this is the paper's k_elo = m_elo E π r_w² / l_w² = k_s / l_w.
  double axial_stiffness() const;
  // κ = m_rot E I / l_w: moment per radian of the angle between consecutive segments.
  // Per unit length this is the paper's k_rot = m_rot E π r_w⁴ / (4 l_w²) = κ / l_w.
  double bending_stiffness() const;
};

// One segment i–j stretched from its rest length l0: U = ½ k_s (|d| − l0)², d = x_j − x_i.
struct StretchResult {
  double energy = 0.0;
  double tension = 0.0;            // k_s (|d| − l0), > 0 when stretched
  Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_j = Eigen::Vector3d::Zero();
};
// Coincident nodes (|d| = 0): the direction is undefined; the forces are zero (0 is a
// subgradient of U at that cone point) and the energy is ½ k_s l0².
StretchResult wire_stretch(const Eigen::Vector3d& x_i, const Eigen::Vector3d& x_j,
                           double axial_stiffness, double rest_length);

// Bending at inner node j between neighbours i and k: θ is the angle between
// e1 = x_j − x_i and e2 = x_k − x_j, θ = atan2(|e1 × e2|, e1·e2) ∈ [0, π], and
// U = ½ κ θ² (straight rest state). Forces are −∇U:
//   θ → 0: exact, smooth and → 0 (the factor θ / sin θ is formed as atan2(s, c) / s,
//          which stays ≈ 1 with no cancellation);
//   θ → π: finite, magnitude κ θ / |e| in the plane of the three nodes, accurate while
//          sin θ is above round-off (tested at π − 1e-6);
//   θ = π exactly (sin θ rounds to 0, the chain folded back on itself) or a zero-length
//          segment: the bending plane is undefined and the forces are zero. U has a
//          cone-shaped maximum there, 0 belongs to its generalised gradient, and any
//          perturbation leaves the point.
struct BendResult {
  double energy = 0.0;
  double angle = 0.0;              // θ
  Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_j = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_k = Eigen::Vector3d::Zero();
};
BendResult wire_bend(const Eigen::Vector3d& x_i, const Eigen::Vector3d& x_j,
                     const Eigen::Vector3d& x_k, double bending_stiffness);

// Elastic forces and energies of one open chain (free ends), nodes in order, rest
// length l_w for every segment. For output, each node's energy is half of the stretching
// energy of each of its (one or two) segments plus the bending energy at that node, so
// the node energies add up to the total.
struct WireChainElasticity {
  std::vector<Eigen::Vector3d> forces;
  std::vector<double> node_energy;
  double stretching_energy = 0.0;
  double bending_energy = 0.0;
  double total_energy() const { return stretching_energy + bending_energy; }
};
WireChainElasticity wire_chain_elasticity(const std::vector<Eigen::Vector3d>& nodes,
                                          const WireMaterial& material);

// What one bead carries for output: half of the stretching energy of each of its (one or
// two) segments, the bending energy at the bead, and the length of its segment to the next
// bead (0 at a wire's last bead), so that sums over beads count each segment once.
struct BeadElasticEnergy {
  double stretching = 0.0;
  double bending = 0.0;
  double segment_length = 0.0;
};

// Sums over the beads of a wire or a group: stretching energy U_str, bending energy U_bend,
// elastic energy U_s = U_str + U_bend, wire length L, and the energy per length U_s/L
// (0 when L = 0). Sums from several ranks combine with merge().
struct WireEnergyTotals {
  double stretching_energy = 0.0;
  double bending_energy = 0.0;
  double length = 0.0;
  void add(const BeadElasticEnergy& bead);
  void merge(const WireEnergyTotals& other);
  double total_energy() const { return stretching_energy + bending_energy; }
  double energy_per_length() const { return length > 0.0 ? total_energy() / length : 0.0; }
};
WireEnergyTotals wire_energy_totals(const std::vector<BeadElasticEnergy>& beads);

// Highest angular frequencies of the linearised free chain of node masses m:
//   axial:   ω_ax² = 4 k_s / m             (the zone-boundary mode of a mass–spring chain);
//   bending: ω_b²  = 16 κ / (m l_w²)       (U = κ/(2 l_w²) Σ (w_{j+1} − 2 w_j + w_{j−1})²,
//                                           whose stiffness (κ/l_w²) D2ᵀD2 has eigenvalues
//                                           up to 16 κ/l_w² for the zigzag mode).
// For a straight chain the two families decouple; the sum ω_max² = ω_ax² + ω_b² is an
// upper bound for any configuration (eigenvalues of a sum of stiffness matrices), and
// differs from max(ω_ax, ω_b) by at most a factor √2 (by 1.2 % for Table 1).
double wire_axial_frequency_max(const WireMaterial& material);
double wire_bending_frequency_max(const WireMaterial& material);
// dt_crit = 2 / ω_max: the stability limit of velocity Verlet (central differences) for
// the elastic forces alone (contacts add their own stiffness). Run at a fraction of it:
// the fifth-order Gear predictor–corrector (c0 = 3/16) is stable on a harmonic mode only
// for ω dt < 0.313, i.e. dt < 0.156 dt_crit, so use dt ≤ 0.1 dt_crit with Gear
// (docs/design.md, "Wire forces and integration"). +infinity when m_elo = m_rot = 0.
double wire_critical_time_step(const WireMaterial& material);

}  // namespace wiregrain
