// Communication helpers for the plugin's styles: ghost-shell size, periodic image shifts,
// restart records, all-gathers of per-atom records.
#ifndef WIREGRAIN_PLUGIN_COMM_H
#define WIREGRAIN_PLUGIN_COMM_H

#include <mpi.h>

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class Domain;
class Atom;
}

namespace wiregrain_lmp {

// Make ghost atoms reach at least `reach` beyond each subdomain, measured to their centre
// minus `radius` (an atom of radius ≤ `radius` whose surface is within `reach`). LIGGGHTS'
// granular communication (Comm::use_gran_opt, any atom style with a radius in an
// orthogonal box) sends atoms only within cutghost/2 + skin/2 + their radius, so the user
// cutoff must be twice the reach there; elsewhere it is the reach + `radius`. Call from
// init(): Comm::init runs after the styles' init.
void ensure_ghost_reach(LAMMPS_NS::LAMMPS *lmp, double reach, double radius = 0.0);

// Shift of a periodic image for an atom style's pack_comm (border = false) and
// pack_border (border = true): box lengths, or for a triclinic box tilt-corrected lengths
// (forward) and lamda units (border), as LIGGGHTS' own styles compute it.
void periodic_image_shift(const LAMMPS_NS::Domain *domain, int pbc_flag, const int *pbc, bool border,
                          double shift[3]);
// Velocity added to a periodic image in a deforming box (fix deform remap v).
void deforming_image_velocity(int pbc_flag, const int *pbc, int deform_vremap, const double *h_rate,
                              double dv[3]);

// A fix's per-atom restart record of atom nlocal (Fix::unpack_restart(nlocal, nth)): the
// values after its length word, skipping the records of the nth fixes stored before it;
// nullptr when the atom has no record (created after read_restart: see
// clear_restart_record) or the record is not `length` values long. The caller then starts
// the atom as new (its set_arrays). length < 0: a record of any length.
const double *fix_restart_record(const LAMMPS_NS::Atom *atom, int nlocal, int nth, int length);

// An atom created while read_restart's per-atom fix records are pending (atom->extra,
// until the first run) has none: read_restart sized atom->extra for the atoms it read, so
// the row of atom i is grown into existence and zeroed (a zero length word = no record).
// Called by the plugin's atom styles' create_atom; a fix defined after read_restart and
// create_atoms then starts such atoms as new instead of reading past atom->extra.
void clear_restart_record(LAMMPS_NS::LAMMPS *lmp, int i);

// Every rank's `mine` (fixed-size records of doubles, any number per rank) concatenated in
// rank order, returned on every rank: MPI_Allgather of the lengths, then MPI_Allgatherv.
// Collective over `comm`.
std::vector<double> all_gather_records(MPI_Comm comm, const std::vector<double> &mine);

}  // namespace wiregrain_lmp

#endif
