// The soft contact law the wire–grain core tests use (test_wire_grain_contact.cpp,
// test_superquadric.cpp): round numbers with distinct normal and tangential stiffness
// and distinct static and dynamic friction, so a mixed-up term shows.
#pragma once

#include "core/contact/soft_contact.h"

namespace wiregrain_test {

inline wiregrain::SoftContactLaw wire_contact_law(double damping = 0.0) {
  wiregrain::SoftContactLaw l;
  l.normal_stiffness = 15.7;
  l.tangential_stiffness = 9.2;
  l.damping_ratio = damping;
  l.static_friction = 0.5;
  l.dynamic_friction = 0.4;
  return l;
}

}  // namespace wiregrain_test
