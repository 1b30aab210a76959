#include "companion_fix.h"

#include "fix.h"
#include "lammps.h"
#include "modify.h"

namespace wiregrain_lmp {

LAMMPS_NS::Fix *ensure_companion_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &id, const std::string &style) {
  if (!find_companion_fix(lmp, id)) {
    std::string fix_id = id, group = "all", fix_style = style;
    char *args[3] = {&fix_id[0], &group[0], &fix_style[0]};
    lmp->modify->add_fix(3, args);
  }
  return find_companion_fix(lmp, id);
}

LAMMPS_NS::Fix *find_companion_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &id) {
  const int ifix = lmp->modify->find_fix(id.c_str());
  return ifix < 0 ? nullptr : lmp->modify->fix[ifix];
}

void delete_companion_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &id) {
  if (lmp->modify->find_fix(id.c_str()) >= 0) lmp->modify->delete_fix(id.c_str());
}

}  // namespace wiregrain_lmp
