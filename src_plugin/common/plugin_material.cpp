#include "plugin_material.h"

#include <cmath>
#include <string>

#include "atom.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"

#include "core/common/validation.h"
#include "core/contact/soft_contact.h"
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


// E and ν of atom type `type`: keyword, else property/global, else `m` as given.
wiregrain::ElasticMaterial material_of_type(LAMMPS_NS::LAMMPS *lmp, int type, const MaterialKeywords &given,
                                            wiregrain::ElasticMaterial m, const std::string &kind,
                                            const std::string &style, const std::string &id) {
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

}  // namespace

wiregrain::ElasticMaterial wire_material_of_type(LAMMPS_NS::LAMMPS *lmp, int type, const MaterialKeywords &given,
                                                 const std::string &kind, const std::string &style,
                                                 const std::string &id) {
  return material_of_type(lmp, type, given, wiregrain::ElasticMaterial(), kind, style, id);  // E_w = 100, ν_w = 0
}

wiregrain::ElasticMaterial grain_material_of_type(LAMMPS_NS::LAMMPS *lmp, int type, const MaterialKeywords &given,
                                                  const std::string &kind, const std::string &style,
                                                  const std::string &id) {
  wiregrain::ElasticMaterial table1;
  table1.youngs_modulus = 1000.0;
  table1.poisson_ratio = 0.3;
  return material_of_type(lmp, type, given, table1, kind, style, id);
}

bool parse_material_keyword(StyleArgs &args, const std::string &key, const char *youngs_key, const char *poisson_key,
                            MaterialKeywords &given) {
  if (key == youngs_key) {
    given.youngs_modulus = args.value_positive(key);
    given.has_youngs_modulus = true;
  } else if (key == poisson_key) {
    given.poisson_ratio = args.value_nonnegative(key);
    if (given.poisson_ratio >= 0.5) args.fail("value of '" + key + "' must be < 0.5");
    given.has_poisson_ratio = true;
  } else {
    return false;
  }
  return true;
}

bool parse_friction_keyword(StyleArgs &args, const std::string &key, wiregrain::ContactFriction &friction) {
  if (key == "mu_s") friction.static_friction = args.value_nonnegative(key);
  else if (key == "mu_d") friction.dynamic_friction = args.value_nonnegative(key);
  else if (key == "restitution") {
    const double e = args.value_nonnegative(key);
    if (e > 1.0) args.fail("value of 'restitution' must be in [0, 1]");
    friction.damping_ratio = wiregrain::damping_ratio_from_restitution(e);
  } else if (key == "damping_ratio") friction.damping_ratio = args.value_nonnegative(key);
  else if (key == "limit_force") {
    const std::string v = args.value_word(key);
    if (v != "yes" && v != "no") args.fail("value of 'limit_force' must be yes or no");
    friction.limit_force = v == "yes";
  } else {
    return false;
  }
  return true;
}

KeywordList friction_keywords() { return {"mu_s", "mu_d", "restitution", "damping_ratio", "limit_force"}; }

void check_friction(const StyleArgs &args, const wiregrain::ContactFriction &friction) {
  if (friction.dynamic_friction > friction.static_friction)
    args.fail("mu_d (" + std::to_string(friction.dynamic_friction) + ") must not exceed mu_s (" +
              std::to_string(friction.static_friction) + ")");
}

wiregrain::ContactFriction table1_friction() {
  wiregrain::ContactFriction friction;
  friction.static_friction = 0.5;
  friction.dynamic_friction = 0.5;
  friction.damping_ratio = wiregrain::damping_ratio_from_restitution(0.5);
  friction.limit_force = false;
  return friction;
}

}  // namespace wiregrain_lmp
