// A companion fix: a fix that a style creates for its own use and deletes with itself
// (the tangential-spring history fix wire/contact/history of pair wire/contact, fix
// wire/wall and fix wire/grain). Its id names the owner (WIRE_CONTACT_HISTORY,
// WIRE_WALL_HISTORY_<fix ID>, WIRE_GRAIN_HISTORY_<fix ID>), its group is all.
#ifndef WIREGRAIN_COMPANION_FIX_H
#define WIREGRAIN_COMPANION_FIX_H

#include <string>

namespace LAMMPS_NS {
class Fix;
class LAMMPS;
}  // namespace LAMMPS_NS

namespace wiregrain_lmp {

// The fix `id`, created as `fix id all style` when there is none (a restart or an earlier
// run may have made it). A fix creates its companion in post_create, not in its
// constructor: Modify::add_fix has then finished with it, which a nested add_fix would upset.
LAMMPS_NS::Fix *ensure_companion_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &id, const std::string &style);

// The fix `id`, or null when there is none.
LAMMPS_NS::Fix *find_companion_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &id);

// Deletes the fix `id` if there is one (from the owner's destructor).
void delete_companion_fix(LAMMPS_NS::LAMMPS *lmp, const std::string &id);

}  // namespace wiregrain_lmp

#endif
