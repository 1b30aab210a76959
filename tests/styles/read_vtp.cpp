// read_vtp FILE.vtp: reads a VTK XML PolyData file with VTK's own vtkXMLPolyDataReader
// and prints what it found, one item per line, for the deck tests:
//   points <n>
//   cells <n>            (all cells: verts + lines + polys + strips)
//   polys <n>
//   lines <n>
//   verts <n>
//   point_array <name> <components> <tuples>
//   cell_array <name> <components> <tuples>
// Exit status 1 (and a message on stderr) if the file cannot be read or the reader
// reports an error or a warning (e.g. a truncated or malformed data array).
#include <cstdio>

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

namespace {
int reported = 0;

void count_report(vtkObject *, unsigned long, void *, void *call_data) {
  reported++;
  std::fprintf(stderr, "read_vtp: VTK reports: %s\n", call_data ? static_cast<const char *>(call_data) : "");
}

void print_arrays(const char *kind, vtkFieldData *data) {
  for (int k = 0; k < data->GetNumberOfArrays(); k++) {
    vtkAbstractArray *a = data->GetAbstractArray(k);
    std::printf("%s %s %d %lld\n", kind, a->GetName() ? a->GetName() : "(unnamed)",
                a->GetNumberOfComponents(), static_cast<long long>(a->GetNumberOfTuples()));
  }
}
}  // namespace

int main(int argc, char **argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: read_vtp FILE.vtp\n");
    return 2;
  }
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  if (!reader->CanReadFile(argv[1])) {
    std::fprintf(stderr, "read_vtp: '%s' is not a readable VTK XML PolyData file\n", argv[1]);
    return 1;
  }
  auto observer = vtkSmartPointer<vtkCallbackCommand>::New();
  observer->SetCallback(count_report);
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::WarningEvent, observer);
  reader->SetFileName(argv[1]);
  reader->Update();
  if (reader->GetErrorCode() != 0 || reported > 0) {
    std::fprintf(stderr, "read_vtp: error reading '%s'\n", argv[1]);
    return 1;
  }
  vtkPolyData *poly = reader->GetOutput();
  if (!poly) {
    std::fprintf(stderr, "read_vtp: no output reading '%s'\n", argv[1]);
    return 1;
  }
  std::printf("points %lld\n", static_cast<long long>(poly->GetNumberOfPoints()));
  std::printf("cells %lld\n", static_cast<long long>(poly->GetNumberOfCells()));
  std::printf("polys %lld\n", static_cast<long long>(poly->GetNumberOfPolys()));
  std::printf("lines %lld\n", static_cast<long long>(poly->GetNumberOfLines()));
  std::printf("verts %lld\n", static_cast<long long>(poly->GetNumberOfVerts()));
  print_arrays("point_array", poly->GetPointData());
  print_arrays("cell_array", poly->GetCellData());
  return 0;
}
