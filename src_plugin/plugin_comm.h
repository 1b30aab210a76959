// Ghost-shell size for the plugin's styles.
#ifndef WIREGRAIN_PLUGIN_COMM_H
#define WIREGRAIN_PLUGIN_COMM_H

namespace LAMMPS_NS {
class LAMMPS;
}

namespace wiregrain_lmp {

// Make ghost atoms reach at least `reach` beyond each subdomain. LIGGGHTS' granular
// communication (Comm::use_gran_opt, any atom style with a radius in an orthogonal box)
// sends atoms only within cutghost/2 + skin/2 + their radius, so the user cutoff must be
// twice the reach there. Call from init(): Comm::init runs after the styles' init.
void ensure_ghost_reach(LAMMPS_NS::LAMMPS *lmp, double reach);

}  // namespace wiregrain_lmp

#endif
