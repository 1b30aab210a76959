// The inputs of the contact laws of contact_laws.h: the elastic constants of one side and
// the damping and friction of a contact. Plain data without Eigen, so that LIGGGHTS style
// headers (compiled with LIGGGHTS' own sources) can hold them.
#pragma once

namespace wiregrain {

// Elastic constants of one side of a contact.
struct ElasticMaterial {
  double youngs_modulus = 100.0;  // E (Table 1: E_w = 100)
  double poisson_ratio = 0.0;     // ν (Table 1: ν_w = 0)

  // Throws InvalidArgument: E finite and > 0 (name "E"), ν finite in [0, 0.5) (name "nu").
  void validate() const;
};

// Damping and friction of a contact (not derived from the elastic constants).
struct ContactFriction {
  double damping_ratio = 0.0;     // ζ
  double static_friction = 0.0;   // μ_s
  double dynamic_friction = 0.0;  // μ_d ≤ μ_s
  bool limit_force = false;       // no attractive normal force when true
};

}  // namespace wiregrain
