// The wire–wire contact; the equations are in wire_wire_contact.h.
#include "core/contact/wire_wire_contact.h"

namespace wiregrain {

WireWireContact wire_wire_contact(const SoftContactLaw& law, const WireSegmentState& a, const WireSegmentState& b,
                                  double dt, TangentialHistory& history) {
  const WireWireGeometry g = wire_wire_geometry(a, b);
  if (g.touching) return load_wire_wire_pair(law, a, b, dt, history, g);
  WireWireContact apart;
  static_cast<WireWireGeometry&>(apart) = g;
  return apart;
}

}  // namespace wiregrain
