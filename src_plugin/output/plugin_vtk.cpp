#include "plugin_vtk.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#ifdef LAMMPS_VTK
#include <vtkErrorCode.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>
#endif

namespace wiregrain_lmp {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// directory part (with its trailing '/') and file name of a path
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::string::size_type slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  return {dir, path.substr(dir.size())};
}

}  // namespace

std::string vtp_pattern_problem(const std::string& pattern) {
  const std::string name = split_path(pattern).second;
  if (name.find('*') == std::string::npos)
    return "file '" + pattern + "' must contain a '*' in its name (replaced by the time step)";
  if (std::count(pattern.begin(), pattern.end(), '*') != 1)
    return "file '" + pattern + "' must contain exactly one '*', in its name";
  if (!ends_with(name, ".vtp") || name.size() <= 4) return "file '" + pattern + "' must end in '.vtp'";
  if (pattern.find('%') != std::string::npos)
    return "file '" + pattern + "' must not contain '%' (rank 0 writes every snapshot)";
  return std::string();
}

std::string vtp_series_path(const std::string& pattern, const std::string& dump_id) {
  const std::pair<std::string, std::string> parts = split_path(pattern);
  const std::string& name = parts.second;
  const std::string::size_type star = name.find('*');
  std::string before = name.substr(0, star);
  const std::string after = name.substr(star + 1);  // ends in ".vtp"
  if (!before.empty() && std::strchr("_-.", before.back())) before.pop_back();
  std::string stem = before + after.substr(0, after.size() - 4);
  if (stem.empty()) stem = dump_id;
  return parts.first + stem + ".vtp.series";
}

std::string vtp_snapshot_path(const std::string& pattern, long long step, int pad) {
  const std::string::size_type star = pattern.find('*');
  char text[64];
  if (pad <= 0) snprintf(text, sizeof(text), "%lld", step);
  else snprintf(text, sizeof(text), "%0*lld", pad, step);
  return pattern.substr(0, star) + text + pattern.substr(star + 1);
}

void VtpSeries::load(double now) {
  loaded_ = true;
  std::ifstream in(path_);
  if (!in) return;
  std::string line;
  while (std::getline(in, line)) {
    const std::string::size_type n = line.find("\"name\"");
    const std::string::size_type t = line.find("\"time\"");
    if (n == std::string::npos || t == std::string::npos) continue;
    const std::string::size_type q0 = line.find('"', line.find(':', n) + 1);
    if (q0 == std::string::npos) continue;
    std::string name;
    std::string::size_type k = q0 + 1;
    for (; k < line.size() && line[k] != '"'; k++) {
      if (line[k] == '\\' && k + 1 < line.size()) k++;
      name += line[k];
    }
    const double time = std::strtod(line.c_str() + line.find(':', t) + 1, NULL);
    if (time < now) entries_.emplace_back(name, time);
  }
}

bool VtpSeries::add(const std::string& snapshot_path, double time, bool append) {
  if (!loaded_) {
    loaded_ = true;
    if (append) load(time);
  }
  const std::string name = split_path(snapshot_path).second;
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const std::pair<std::string, double>& e) { return e.first == name; }),
                 entries_.end());
  entries_.emplace_back(name, time);

  std::ostringstream out;
  out << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
  for (size_t k = 0; k < entries_.size(); k++) {
    char text[64];
    snprintf(text, sizeof(text), "%.17g", entries_[k].second);
    out << "    { \"name\" : " << json_string(entries_[k].first) << ", \"time\" : " << text << " }"
        << (k + 1 < entries_.size() ? "," : "") << "\n";
  }
  out << "  ]\n}\n";

  const std::string tmp = path_ + ".tmp";
  const std::string text = out.str();
  bool ok = false;
  if (FILE* f = fopen(tmp.c_str(), "w")) {
    ok = fwrite(text.data(), 1, text.size(), f) == text.size();
    ok = fclose(f) == 0 && ok;
  }
  return ok && std::rename(tmp.c_str(), path_.c_str()) == 0;
}

bool write_vtp(vtkPolyData* poly, const std::string& path, bool ascii) {
#ifdef LAMMPS_VTK
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetFileName(path.c_str());
  writer->SetInputData(poly);
  if (ascii) {
    writer->SetDataModeToAscii();
  } else {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw binary
  }
  // Write() returns 1 even when the file cannot be opened; the error code tells
  return writer->Write() == 1 && writer->GetErrorCode() == vtkErrorCode::NoError;
#else
  (void)poly;
  (void)path;
  (void)ascii;
  return false;
#endif
}

}  // namespace wiregrain_lmp
