#include "plugin_comm.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "lammps.h"

namespace wiregrain_lmp {

void ensure_ghost_reach(LAMMPS_NS::LAMMPS *lmp, double reach) {
  const bool halved = lmp->domain->triclinic == 0 && lmp->atom->radius != nullptr;
  const double cutoff = halved ? 2.0 * reach : reach;
  if (lmp->comm->cutghostuser < cutoff) lmp->comm->cutghostuser = cutoff;
}

}  // namespace wiregrain_lmp
