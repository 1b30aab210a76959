#include "plugin_material.h"

#include <cmath>
#include <string>

#include "atom.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

#include "core/common/validation.h"
#include "plugin_args.h"

namespace wiregrain_lmp {

namespace {

// The value of `property` (a fix property/global ... peratomtype) for atom type `type`;
// false when no such fix is defined.
bool property_of_type(LAMMPS_NS::LAMMPS *lmp, const char *property, int type, double &value,
                      const std::string &kind, const std::string &style, const std::string &id) {
  std::string caller = kind + " " + style;
  LAMMPS_NS::Fix *fix = lmp->modify->find_fix_property(property, "property/global", "peratomtype", 0, 0,
                                                       caller.c_str(), false);
  if (!fix) return false;
  const int ntypes = lmp->atom->ntypes;
  // LIGGGHTS checks the length only in the fix's init(), after the pair style's
  if (fix->size_vector < ntypes)
    style_error(lmp->error, kind, style, id,
                "fix property/global " + std::string(property) + " has " + std::to_string(fix->size_vector) +
                    " value(s), needs one per atom type (" + std::to_string(ntypes) + ")");
  value = fix->compute_vector(type - 1);
  return true;
}

}  // namespace

wiregrain::ElasticMaterial wire_material_of_type(LAMMPS_NS::LAMMPS *lmp, int type, const MaterialKeywords &given,
                                                 const std::string &kind, const std::string &style,
                                                 const std::string &id) {
  wiregrain::ElasticMaterial m;  // Table 1: E_w = 100, ν_w = 0
  const std::string of_type = " of atom type " + std::to_string(type);
  double value = 0.0;
  if (given.has_youngs_modulus) {
    m.youngs_modulus = given.youngs_modulus;
  } else if (property_of_type(lmp, "youngsModulus", type, value, kind, style, id)) {
    if (!(std::isfinite(value) && value > 0.0))
      style_error(lmp->error, kind, style, id,
                  "youngsModulus" + of_type + " must be a finite number > 0, got " + wiregrain::format_number(value));
    m.youngs_modulus = value;
  }
  if (given.has_poisson_ratio) {
    m.poisson_ratio = given.poisson_ratio;
  } else if (property_of_type(lmp, "poissonsRatio", type, value, kind, style, id)) {
    if (!(std::isfinite(value) && value >= 0.0 && value < 0.5))
      style_error(lmp->error, kind, style, id,
                  "poissonsRatio" + of_type + " must be in [0, 0.5), got " + wiregrain::format_number(value));
    m.poisson_ratio = value;
  }
  return m;
}

}  // namespace wiregrain_lmp
