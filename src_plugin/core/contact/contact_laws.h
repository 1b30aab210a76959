// Contact laws from materials: the one place that turns the materials of the two sides of
// a soft contact of the wire into its SoftContactLaw (k_n, k_t, ζ, μ_s, μ_d, limit_force;
// the force kernel is soft_contact.h). Pairings and equations (the paper's section 2.2 and
// docs/design.md, "The wire: bead chain with soft contacts"):
//   effective modulus E*:
//     wire–wire   E_ww = E_w / (2(1−ν_w²))                  (two sides of one material)
//                 1/E* = (1−ν_a²)/E_a + (1−ν_b²)/E_b        (two wire materials)
//     wire–grain  1/E_wp = (1−ν_w²)/E_w + (1−ν_p²)/E_p
//     wire–wall   E* = E_w/(1−ν_w²)                         (a rigid wall, E_b → ∞)
//   stiffnesses of a wire segment of length l_w and radius r_w:
//     k_n = E* l_w π/4,   k_t = E* r_w,
//   with l_w, r_w: wire–wire the means of the two segments' rest lengths and radii,
//   wire–grain the segment's, wire–wall those of the bead (bead_segment_length).
//
// A law is built in two steps, as the equations read: E* of the pairing from the two
// materials (one function per pairing), then the law of one contact from E* and its
// segment (segment_contact_law, the same for the three pairings). The contact styles
// (pair wire/contact, fix wire/wall, fix wire/grain) tabulate E* once per pair of atom
// types when a run starts, since the materials are per atom type, and form each contact's
// law from the table and the contact's segment; a function per pairing from the materials
// to the law would compute E* again at every contact and hide the only thing in which the
// three pairings differ. There is one law (no choice of normal, tangential or damping
// sub-models as in LAMMPS' GRANULAR package); a second law would be a kernel beside
// soft_contact.h and its parameters built here.
#pragma once

#include "core/contact/contact_materials.h"
#include "core/contact/soft_contact.h"

namespace wiregrain {

// The mixing rule 1/E* = (1−ν_a²)/E_a + (1−ν_b²)/E_b.
double effective_modulus(double e_a, double nu_a, double e_b, double nu_b);

// Effective moduli E* of the pairings above.
double wire_wire_modulus(const ElasticMaterial& a, const ElasticMaterial& b);
double wire_grain_modulus(const ElasticMaterial& wire, const ElasticMaterial& grain);
double wire_wall_modulus(const ElasticMaterial& wire);

// k_n = E* l_w π/4, k_t = E* r_w, with the damping and friction as given.
SoftContactLaw segment_contact_law(double effective_modulus, double segment_length, double wire_radius,
                                   const ContactFriction& friction);

// The segment length a single bead stands for in a contact with a wall: the rest length
// of its own segment (to its next bead); at the last bead of a wire, that of the
// previous bead's segment (previous_rest_length, ≤ 0 when there is none); a lone bead is
// a sphere, l = 2 r.
double bead_segment_length(double own_rest_length, double previous_rest_length, double radius);

}  // namespace wiregrain
