#include "core/wire/wire_elasticity.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

namespace wiregrain {

namespace {


}  // namespace

void WireMaterial::validate() const {
  require_positive("E", youngs_modulus);
  require_positive("radius", radius);
  require_positive("segment_length", segment_length);
  require_positive("density", density);
  require_nonnegative("m_elo", elongation_multiplier);
  require_nonnegative("m_rot", rotation_multiplier);
}

double WireMaterial::cross_section_area() const { return kPi * radius * radius; }

double WireMaterial::second_moment_of_area() const {
  return kPi * radius * radius * radius * radius / 4.0;
}

double WireMaterial::node_mass() const {
  return density * cross_section_area() * segment_length;
}

double WireMaterial::axial_stiffness() const {
  return elongation_multiplier * youngs_modulus * cross_section_area() / segment_length;
}

double WireMaterial::bending_stiffness() const {
  return rotation_multiplier * youngs_modulus * second_moment_of_area() / segment_length;
}

StretchResult wire_stretch(const Eigen::Vector3d& x_i, const Eigen::Vector3d& x_j,
                           double axial_stiffness, double rest_length) {
  StretchResult r;
  const Eigen::Vector3d d = x_j - x_i;
  const double length = d.norm();
  const double extension = length - rest_length;
  r.energy = 0.5 * axial_stiffness * extension * extension;
  r.tension = axial_stiffness * extension;
  if (length > 0.0) {
    // F_j = −∂U/∂x_j = −k_s (|d| − l0) d/|d|
    r.force_j = -(r.tension / length) * d;
    r.force_i = -r.force_j;
  }
  return r;
}

BendResult wire_bend(const Eigen::Vector3d& x_i, const Eigen::Vector3d& x_j,
                     const Eigen::Vector3d& x_k, double bending_stiffness) {
  BendResult r;
  const Eigen::Vector3d e1 = x_j - x_i, e2 = x_k - x_j;
  const double len1 = e1.norm(), len2 = e2.norm();
  if (!(len1 > 0.0) || !(len2 > 0.0)) return r;  // zero-length segment: no bending plane
  const Eigen::Vector3d a = e1 / len1, b = e2 / len2;
  // n = â × b̂, |n| = sin θ; θ from atan2 is accurate at both ends of [0, π].
  const Eigen::Vector3d n = a.cross(b);
  const double sin_theta = n.norm();
  const double theta = std::atan2(sin_theta, a.dot(b));
  r.angle = theta;
  r.energy = 0.5 * bending_stiffness * theta * theta;
  if (!(sin_theta >= std::numeric_limits<double>::min())) return r;  // θ = 0 or π exactly
  // ∂θ/∂e1 = −(n × â) / (sin θ |e1|),  ∂θ/∂e2 = −(b̂ × n) / (sin θ |e2|):
  // n × â = b̂ − cos θ â and b̂ × n = â − cos θ b̂ are the in-plane unit normals times
  // sin θ, formed from the cross product so there is no cancellation at small θ.
  // ∂U/∂e = κ θ ∂θ/∂e; the factor θ / sin θ → 1 as θ → 0.
  const double factor = bending_stiffness * theta / sin_theta;
  const Eigen::Vector3d grad_e1 = -(factor / len1) * n.cross(a);
  const Eigen::Vector3d grad_e2 = -(factor / len2) * b.cross(n);
  // e1 = x_j − x_i, e2 = x_k − x_j  ⇒  F_i = ∂U/∂e1, F_j = ∂U/∂e2 − ∂U/∂e1, F_k = −∂U/∂e2.
  r.force_i = grad_e1;
  r.force_j = grad_e2 - grad_e1;
  r.force_k = -grad_e2;
  return r;
}

WireChainElasticity wire_chain_elasticity(const std::vector<Eigen::Vector3d>& nodes,
                                          const WireMaterial& material) {
  WireChainElasticity out;
  const std::size_t n = nodes.size();
  out.forces.assign(n, Eigen::Vector3d::Zero());
  out.node_energy.assign(n, 0.0);
  const double k_s = material.axial_stiffness();
  const double kappa = material.bending_stiffness();
  const double l0 = material.segment_length;
  for (std::size_t s = 0; s + 1 < n; ++s) {
    const StretchResult st = wire_stretch(nodes[s], nodes[s + 1], k_s, l0);
    out.forces[s] += st.force_i;
    out.forces[s + 1] += st.force_j;
    out.node_energy[s] += 0.5 * st.energy;
    out.node_energy[s + 1] += 0.5 * st.energy;
    out.stretching_energy += st.energy;
  }
  for (std::size_t j = 1; j + 1 < n; ++j) {
    const BendResult bd = wire_bend(nodes[j - 1], nodes[j], nodes[j + 1], kappa);
    out.forces[j - 1] += bd.force_i;
    out.forces[j] += bd.force_j;
    out.forces[j + 1] += bd.force_k;
    out.node_energy[j] += bd.energy;
    out.bending_energy += bd.energy;
  }
  return out;
}

void WireEnergyTotals::add(const BeadElasticEnergy& bead) {
  stretching_energy += bead.stretching;
  bending_energy += bead.bending;
  length += bead.segment_length;
}

void WireEnergyTotals::merge(const WireEnergyTotals& other) {
  stretching_energy += other.stretching_energy;
  bending_energy += other.bending_energy;
  length += other.length;
}

WireEnergyTotals wire_energy_totals(const std::vector<BeadElasticEnergy>& beads) {
  WireEnergyTotals totals;
  for (const BeadElasticEnergy& bead : beads) totals.add(bead);
  return totals;
}

double wire_axial_frequency_max(const WireMaterial& material) {
  return 2.0 * std::sqrt(material.axial_stiffness() / material.node_mass());
}

double wire_bending_frequency_max(const WireMaterial& material) {
  const double l = material.segment_length;
  return 4.0 * std::sqrt(material.bending_stiffness() / (material.node_mass() * l * l));
}

double wire_critical_time_step(const WireMaterial& material) {
  const double w_ax = wire_axial_frequency_max(material);
  const double w_b = wire_bending_frequency_max(material);
  const double w_max = std::sqrt(w_ax * w_ax + w_b * w_b);
  if (!(w_max > 0.0)) return std::numeric_limits<double>::infinity();
  return 2.0 / w_max;
}

}  // namespace wiregrain
