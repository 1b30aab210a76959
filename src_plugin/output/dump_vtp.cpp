#include "dump_vtp.h"

#include "atom.h"
#include "error.h"
#include "update.h"

#include "plugin_args.h"

using namespace LAMMPS_NS;

DumpVtp::DumpVtp(LAMMPS *lmp, int narg, char **arg, const char *style)
    : Dump(lmp, narg, arg), style_(style), ascii_(false) {
  clearstep = 0;  // no compute is invoked
  // Files are opened by the derived dump, not by the base class: with multifile = 0
  // Dump::write() only counts, packs and gathers (openfile() and fclose() are skipped).
  multifile = 0;
  flush_flag = 0;
}

void DumpVtp::take_pattern(wiregrain_lmp::StyleArgs &args) {
  pattern_ = filename;
  const std::string problem = wiregrain_lmp::vtp_pattern_problem(pattern_);
  if (!problem.empty()) args.fail(problem);
  // e.g. post/wire_*.vtp -> post/wire.vtp.series
  series_ = wiregrain_lmp::VtpSeries(wiregrain_lmp::vtp_series_path(pattern_, id));
}

void DumpVtp::take_format(wiregrain_lmp::StyleArgs &args) {
  const std::string value = args.value_word("format");
  if (value == "ascii") ascii_ = true;
  else if (value == "binary") ascii_ = false;
  else args.fail("value of 'format' must be 'ascii' or 'binary', got '" + value + "'");
}

void DumpVtp::write() {
  gathered_.clear();
  Dump::write();  // count(), pack(), then write_header()/write_data() on rank 0
  if (filewriter) {
    const std::string path =
        wiregrain_lmp::vtp_snapshot_path(pattern_, static_cast<long long>(update->ntimestep), padflag);
    write_snapshot(path);
    if (!series_.add(path, update->get_cur_time(), append_flag != 0))
      error->one(FLERR, ("dump " + style_ + " (id " + std::string(id) + "): cannot write file '" + series_.path() +
                         "'").c_str());
  }
}

int DumpVtp::count() {
  const int *mask = atom->mask;
  int n = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && writes(i)) n++;
  return n;
}

void DumpVtp::pack_group(int *ids, const std::function<void(int, double *)> &row) {
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask, *tag = atom->tag;
  int m = 0, n = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!((mask[i] & groupbit) && writes(i))) continue;
    row(i, buf + m);
    if (ids) ids[n] = tag[i];
    m += size_one;
    n++;
  }
}

void DumpVtp::write_header(bigint ndump) {
  gathered_.clear();
  gathered_.reserve(static_cast<size_t>(ndump) * size_one);
}

void DumpVtp::write_data(int n, double *mybuf) {
  gathered_.insert(gathered_.end(), mybuf, mybuf + static_cast<size_t>(n) * size_one);
}

void DumpVtp::write_polydata(vtkPolyData *poly, const std::string &path) {
  if (!wiregrain_lmp::write_vtp(poly, path, ascii_))
    error->one(FLERR, ("dump " + style_ + " (id " + std::string(id) + "): cannot write file '" + path + "'").c_str());
}
