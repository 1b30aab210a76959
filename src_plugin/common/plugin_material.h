/* Materials per atom type: the one place the plugin's styles read E and ν of an atom type.

   A user defines them as for LIGGGHTS' own granular styles, one value per atom type:
     fix m1 all property/global youngsModulus peratomtype 100 1000
     fix m2 all property/global poissonsRatio peratomtype 0   0.3
   Precedence, per value: a keyword given to the style (E, nu) wins; else the property/global
   value of the atom type; else the paper's Table 1 (wire E_w = 100, ν_w = 0; grains
   E_p = 1000, ν_p = 0.3).
   The keywords of a soft contact (mu_s, mu_d, restitution, damping_ratio, limit_force)
   are parsed here too, once for every style that has them. */

#ifndef WIREGRAIN_PLUGIN_MATERIAL_H
#define WIREGRAIN_PLUGIN_MATERIAL_H

#include <string>

#include "core/contact/contact_materials.h"
#include "plugin_args.h"

namespace LAMMPS_NS {
class LAMMPS;
}
namespace wiregrain_lmp {
class StyleArgs;
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
// The same for the grains of atom type `type` (Table 1: E_p = 1000, ν_p = 0.3).
wiregrain::ElasticMaterial grain_material_of_type(LAMMPS_NS::LAMMPS *lmp, int type, const MaterialKeywords &given,
                                                  const std::string &kind, const std::string &style,
                                                  const std::string &id);

// Parses the value of `key` when it is one of the material keywords named youngs_key
// (E > 0) and poisson_key (ν in [0, 0.5)); returns false for any other key.
bool parse_material_keyword(StyleArgs &args, const std::string &key, const char *youngs_key,
                            const char *poisson_key, MaterialKeywords &given);
// Parses the value of `key` when it is mu_s, mu_d (≥ 0), restitution (in [0, 1], turned
// into ζ), damping_ratio (≥ 0) or limit_force (yes|no); returns false for any other key.
bool parse_friction_keyword(StyleArgs &args, const std::string &key, wiregrain::ContactFriction &friction);
// The keywords parse_friction_keyword takes, for a style's KeywordList.
KeywordList friction_keywords();
// Stops with "mu_d (x) must not exceed mu_s (y)" when μ_d > μ_s.
void check_friction(const StyleArgs &args, const wiregrain::ContactFriction &friction);
// Table 1's contact: μ_s = μ_d = 0.5, restitution 0.5, no force limit.
wiregrain::ContactFriction table1_friction();

}  // namespace wiregrain_lmp

#endif
