/* How outputs read the per-bead elastic energies of the wire: a style that computes them
   (fix wire/elastic) derives from WireEnergySource; compute wire/energy and dump wire/vtk
   find it by its style name and read named values, never array columns. */

#ifndef WIREGRAIN_WIRE_ENERGY_SOURCE_H
#define WIREGRAIN_WIRE_ENERGY_SOURCE_H

// declared in core/wire/wire_elasticity.h (not included: style headers need no Eigen)
namespace wiregrain {
struct BeadElasticEnergy;
}

namespace wiregrain_lmp {

class WireEnergySource {
 public:
  virtual ~WireEnergySource() = default;
  // step of the last force evaluation; the bead energies are those of that step
  virtual long long energies_step() const = 0;
  // stretching and bending energy and segment length of owned bead i (local index)
  virtual wiregrain::BeadElasticEnergy bead_energy(int i) const = 0;
};

}  // namespace wiregrain_lmp

#endif
