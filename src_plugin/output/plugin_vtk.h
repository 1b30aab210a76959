// Shared by the plugin's VTK XML dumps (dump wire/vtk, dump polyhedron/vtk): the snapshot
// file pattern ("post/name_*.vtp"), the ParaView ".vtp.series" file that lists the
// snapshots with their simulation times, and writing one vtkPolyData. Both dumps take the
// time from Update::get_cur_time(), so their series files carry the same time values and
// open together in ParaView.
#ifndef WIREGRAIN_PLUGIN_VTK_H
#define WIREGRAIN_PLUGIN_VTK_H

#include <string>
#include <utility>
#include <vector>

#ifdef LAMMPS_VTK
#include <vtkSmartPointer.h>
#include <vtkType.h>
#endif

class vtkPolyData;

namespace wiregrain_lmp {

// Empty if `pattern` is a valid snapshot pattern: exactly one '*', in the file name (not
// in a directory), a name ending in ".vtp", no '%'. Otherwise the complaint, e.g.
// "file 'post/wire.vtp' must contain a '*' in its name (replaced by the time step)".
std::string vtp_pattern_problem(const std::string& pattern);

// The series file of a valid pattern: the name without the '*' and a '_', '-' or '.'
// just before it, plus ".series": post/wire_*.vtp -> post/wire.vtp.series; a name that is
// only "*.vtp" gives <dump_id>.vtp.series in the same directory.
std::string vtp_series_path(const std::string& pattern, const std::string& dump_id);

// The snapshot file of a time step: '*' replaced by `step`, zero-padded to `pad` digits
// when pad > 0 (dump_modify pad).
std::string vtp_snapshot_path(const std::string& pattern, long long step, int pad);

// The entries of one series file, kept on the rank that writes.
class VtpSeries {
 public:
  explicit VtpSeries(std::string path = std::string()) : path_(std::move(path)) {}
  const std::string& path() const { return path_; }

  // Lists the snapshot `snapshot_path` (stored by its file name) at `time` and rewrites
  // the series file (through a temporary file and a rename, so a reader never sees half
  // a file). A snapshot of the same name replaces the earlier entry. On the first call,
  // with `append` (dump_modify append yes) the entries of an existing series file that
  // lie before `time` are kept, so a run continued from a restart continues the series;
  // without it the list starts afresh. Returns false if the file cannot be written.
  bool add(const std::string& snapshot_path, double time, bool append);

 private:
  std::string path_;
  std::vector<std::pair<std::string, double> > entries_;
  bool loaded_ = false;
  void load(double now);
};

#ifdef LAMMPS_VTK
// A VTK data array (vtkDoubleArray, vtkIntArray) named `name` of `tuples` tuples of
// `components` values, to fill with SetValue/SetTuple and add to point or cell data.
template <class Array>
vtkSmartPointer<Array> named_array(const char* name, vtkIdType tuples, int components = 1) {
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}
#endif

// Writes `poly` to `path` with vtkXMLPolyDataWriter: ascii (readable text, full double
// precision) or raw appended binary. Returns false on failure. Without VTK (no
// LAMMPS_VTK) it does nothing and returns false.
bool write_vtp(vtkPolyData* poly, const std::string& path, bool ascii);

}  // namespace wiregrain_lmp

#endif
