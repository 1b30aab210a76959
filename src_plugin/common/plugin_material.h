/* Materials per atom type: the one place the plugin's styles read E and ν of an atom type.

   A user defines them as for LIGGGHTS' own granular styles, one value per atom type:
     fix m1 all property/global youngsModulus peratomtype 100 1000
     fix m2 all property/global poissonsRatio peratomtype 0   0.3
   Precedence, per value: a keyword given to the style (E, nu) wins; else the property/global
   value of the atom type; else the paper's Table 1 for the wire (E_w = 100, ν_w = 0). */

#ifndef WIREGRAIN_PLUGIN_MATERIAL_H
#define WIREGRAIN_PLUGIN_MATERIAL_H

#include <string>

#include "core/contact/contact_materials.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wiregrain_lmp {

// Values a style was given as keywords; those not given come from the atom type.
struct MaterialKeywords {
  bool has_youngs_modulus = false;
  double youngs_modulus = 0.0;  // keyword E
  bool has_poisson_ratio = false;
  double poisson_ratio = 0.0;   // keyword nu
};

// E and ν of the wire beads of atom type `type` (1..ntypes) by the precedence above.
// Stops with "<kind> <style> (id <ID>): ..." when a property/global has fewer values than
// atom types, or a value is out of its domain (E finite and > 0, ν finite in [0, 0.5)).
// Looks the properties up on every call: call it from init(), not per atom.
wiregrain::ElasticMaterial wire_material_of_type(LAMMPS_NS::LAMMPS *lmp, int type, const MaterialKeywords &given,
                                                 const std::string &kind, const std::string &style,
                                                 const std::string &id);

}  // namespace wiregrain_lmp

#endif
