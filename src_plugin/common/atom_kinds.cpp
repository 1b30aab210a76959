#include "atom_kinds.h"

#include <mpi.h>

#include "atom.h"
#include "atom_style_part.h"
#include "bead_chain_links.h"
#include "grain_shape_source.h"
#include "group.h"
#include "lammps.h"
#include "plugin_args.h"

namespace wiregrain_lmp {

AtomKinds::AtomKinds(LAMMPS_NS::LAMMPS *lmp)
    : lmp_(lmp),
      polyhedra_(atom_style_part<const GrainShapeSource>(lmp->atom)),
      chains_(atom_style_part<const BeadChainLinks>(lmp->atom)),
      stock_grains_(lmp->atom->sphere_flag || lmp->atom->superquadric_flag) {}

AtomKind AtomKinds::of(int i) const {
  if (polyhedra_ && lmp_->atom->shapetype[i] >= 0) return AtomKind::polyhedron;
  if (chains_ && (chains_->previous_bead_tag(i) || chains_->next_bead_tag(i))) return AtomKind::bead;
  if (polyhedra_) return AtomKind::shapeless;
  if (stock_grains_) return AtomKind::stock_grain;
  return chains_ ? AtomKind::bead : AtomKind::other;
}

bool AtomKinds::is_grain(int i) const {
  const AtomKind kind = of(i);
  return kind == AtomKind::polyhedron || kind == AtomKind::stock_grain;
}

AtomKindCounts AtomKinds::count(int groupbit) const {
  long local[5] = {0, 0, 0, 0, 0}, global[5];
  const int *mask = lmp_->atom->mask;
  for (int i = 0; i < lmp_->atom->nlocal; i++)
    if (mask[i] & groupbit) local[static_cast<int>(of(i))]++;
  MPI_Allreduce(local, global, 5, MPI_LONG, MPI_SUM, lmp_->world);
  AtomKindCounts counts;
  counts.beads = global[static_cast<int>(AtomKind::bead)];
  counts.polyhedra = global[static_cast<int>(AtomKind::polyhedron)];
  counts.stock_grains = global[static_cast<int>(AtomKind::stock_grain)];
  counts.shapeless = global[static_cast<int>(AtomKind::shapeless)];
  counts.others = global[static_cast<int>(AtomKind::other)];
  return counts;
}

void require_no_grains(LAMMPS_NS::LAMMPS *lmp, int igroup, const std::string &kind, const std::string &style,
                       const std::string &id) {
  const long grains = AtomKinds(lmp).count(lmp->group->bitmask[igroup]).grains();
  if (grains > 0)
    style_error(lmp->error, kind, style, id,
                "group '" + std::string(lmp->group->names[igroup]) + "' holds " + std::to_string(grains) +
                    " grains (give the wire beads only)");
}

void require_no_beads(LAMMPS_NS::LAMMPS *lmp, int igroup, const std::string &kind, const std::string &style,
                      const std::string &id) {
  const long beads = AtomKinds(lmp).count(lmp->group->bitmask[igroup]).beads;
  if (beads > 0)
    style_error(lmp->error, kind, style, id,
                "group '" + std::string(lmp->group->names[igroup]) + "' holds " + std::to_string(beads) +
                    " wire beads (give the grains only)");
}

}  // namespace wiregrain_lmp
