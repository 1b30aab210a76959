// Contact laws from materials: the one place that turns the materials of the two sides of
// a soft contact into its SoftContactLaw (k_n, k_t, ζ, μ_s, μ_d, limit_force), in the
// manner of the sub-models of LAMMPS' GRANULAR package. Pairings and equations (the
// paper's section 2.2 and docs/design.md, "The wire: bead chain with soft contacts"):
//   effective modulus E*:
//     wire–wire   E_ww = E_w / (2(1−ν_w²))                  (two sides of one material)
//                 1/E* = (1−ν_a²)/E_a + (1−ν_b²)/E_b        (two wire materials)
//     wire–grain  1/E_wp = (1−ν_w²)/E_w + (1−ν_p²)/E_p
//     wire–wall   E* = E_w/(1−ν_w²)                         (a rigid wall, E_b → ∞)
//   stiffnesses of a wire segment of length l_w and radius r_w:
//     k_n = E* l_w π/4,   k_t = E* r_w.
#pragma once

#include "core/contact/contact_materials.h"
#include "core/contact/soft_contact.h"

namespace wiregrain {

// Effective moduli E* of the pairings above.
double wire_wire_modulus(const ElasticMaterial& a, const ElasticMaterial& b);
double wire_grain_modulus(const ElasticMaterial& wire, const ElasticMaterial& grain);
double wire_wall_modulus(const ElasticMaterial& wire);

// k_n = E* l_w π/4, k_t = E* r_w, with the damping and friction as given.
SoftContactLaw segment_contact_law(double effective_modulus, double segment_length, double wire_radius,
                                   const ContactFriction& friction);

// The laws of the three pairings. Wire–wire: l_w and r_w are the means of the two
// segments' rest lengths and radii (the caller forms them).
SoftContactLaw wire_wire_contact_law(const ElasticMaterial& a, const ElasticMaterial& b, double segment_length,
                                     double wire_radius, const ContactFriction& friction);
SoftContactLaw wire_grain_contact_law(const ElasticMaterial& wire, const ElasticMaterial& grain,
                                      double segment_length, double wire_radius, const ContactFriction& friction);
SoftContactLaw wire_wall_contact_law(const ElasticMaterial& wire, double segment_length, double wire_radius,
                                     const ContactFriction& friction);

// The segment length a single bead stands for in a contact with a wall: the rest length
// of its own segment (to its next bead); at the last bead of a wire, that of the
// previous bead's segment (previous_rest_length, ≤ 0 when there is none); a lone bead is
// a sphere, l = 2 r.
double bead_segment_length(double own_rest_length, double previous_rest_length, double radius);

}  // namespace wiregrain
