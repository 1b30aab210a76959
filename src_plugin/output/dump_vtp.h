// Base of the plugin's VTK XML dumps (dump wire/vtk, dump polyhedron/vtk): the snapshot
// file pattern and its ParaView series file, the `format ascii|binary` keyword, and the
// gathering of every rank's packed rows on rank 0. A derived dump packs its rows (pack)
// and builds the snapshot from `gathered_` (write_snapshot). Not a style of its own.
#ifndef WIREGRAIN_DUMP_VTP_H
#define WIREGRAIN_DUMP_VTP_H

#include <functional>
#include <string>
#include <vector>

#include "dump.h"
#include "output/plugin_vtk.h"

namespace wiregrain_lmp {
class StyleArgs;
}

namespace wiregrain_lmp {

// The rows every rank packed, gathered on rank 0: value(r, c) is column c of row r.
class GatheredRows {
 public:
  GatheredRows(const std::vector<double> &values, int columns) : values_(values), columns_(columns) {}
  int size() const { return static_cast<int>(values_.size() / columns_); }
  double operator()(int row, int column) const { return values_[static_cast<size_t>(row) * columns_ + column]; }

 private:
  const std::vector<double> &values_;
  int columns_;
};

}  // namespace wiregrain_lmp

namespace LAMMPS_NS {

class DumpVtp : public Dump {
 public:
  DumpVtp(class LAMMPS *, int, char **, const char *style);
  void write();

 protected:
  void write_header(bigint);
  void write_data(int, double *);
  int modify_param(int, char **) { return 0; }  // only the base-class dump_modify keywords

  // from the derived constructor: the file name as pattern (checked) and its series file
  void take_pattern(wiregrain_lmp::StyleArgs &args);
  // the value of keyword 'format'
  void take_format(wiregrain_lmp::StyleArgs &args);
  virtual void write_snapshot(const std::string &path) = 0;
  // whether the dump writes atom i of its group: a dump of one kind of atom (beads, grains)
  // leaves the other kind out (common/atom_kinds.h)
  virtual bool writes(int i) const = 0;
  // Dump::count: the local atoms of the group that the dump writes
  int count();
  // Dump::pack over those atoms: row(i, values) writes the size_one values of atom i; ids,
  // when given, receive the tags
  void pack_group(int *ids, const std::function<void(int, double *)> &row);
  // gathered_ by rows of size_one values
  wiregrain_lmp::GatheredRows gathered_rows() const { return wiregrain_lmp::GatheredRows(gathered_, size_one); }
  // writes `poly` to `path` (ascii_), an error if it cannot
  void write_polydata(vtkPolyData *poly, const std::string &path);

  std::string style_;                  // "wire/vtk", ...
  std::string pattern_;                // the file name as given, with its '*'
  bool ascii_;                         // VTK XML data mode: ascii or binary (appended, raw)
  std::vector<double> gathered_;       // rank 0: all packed rows
  wiregrain_lmp::VtpSeries series_;    // rank 0: <pattern without '*'>.vtp.series
};

}  // namespace LAMMPS_NS

#endif
